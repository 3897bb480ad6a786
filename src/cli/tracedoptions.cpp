#include "tracedoptions.h"

#include <cmath>

namespace lr::cli {

TracedOptionSet::TracedOptionSet()
    : samples(
          QStringLiteral("samples"),
          QStringLiteral("--quality path: samples per pixel, 1..1000000 (default 64; with --time-limit or "
                         "--noise-threshold and no --samples, 1000000)."),
          QStringLiteral("N")),
      timeLimit(QStringLiteral("time-limit"),
                QStringLiteral("--quality path: stop after S seconds of tracing (> 0), or at the samples or "
                               "noise target if sooner."),
                QStringLiteral("S")),
      noiseThreshold(
          QStringLiteral("noise-threshold"),
          QStringLiteral("--quality path: stop once the estimated relative noise (the RMS standard "
                         "error of the pixel means over the mean luminance) is at most T (> 0; "
                         "0.01: 1 %)."),
          QStringLiteral("T")),
      bounces(QStringLiteral("bounces"),
              QStringLiteral("--quality path: surface interactions per path, 0..1024 (default 8; 1 is direct "
                             "light only)."),
              QStringLiteral("B")),
      threads(QStringLiteral("threads"),
              QStringLiteral("--quality path: worker threads, 1..1024 (default: every core)."),
              QStringLiteral("T")),
      fireflyClamp(QStringLiteral("firefly-clamp"),
                   QStringLiteral("--quality path: clamp each sample's largest channel to X (linear radiance "
                                  "> 0); biased, off by default."),
                   QStringLiteral("X")),
      seed(
          QStringLiteral("seed"),
          QStringLiteral("--quality path: the random sequence, 0..2147483647 (default 0); another seed gives "
                         "an independent image of the same scene (for error estimates against a "
                         "reference)."),
          QStringLiteral("S")) {}

void TracedOptionSet::addTo(QCommandLineParser& parser) const {
    parser.addOptions({samples, timeLimit, noiseThreshold, bounces, threads, fireflyClamp, seed});
}

std::optional<TracedRenderOptions> TracedOptionSet::read(const QCommandLineParser& parser, bool path,
                                                         QString* error) const {
    TracedRenderOptions o;
    for (const QCommandLineOption* option :
         {&samples, &timeLimit, &noiseThreshold, &bounces, &threads, &fireflyClamp, &seed})
        if (parser.isSet(*option) && !path) {
            *error = QStringLiteral("--%1 needs --quality path").arg(option->names().constLast());
            return std::nullopt;
        }
    if (!path) return o;
    const auto number = [&](const QCommandLineOption& option, int lo, int hi, int* v) {
        if (!parser.isSet(option)) return true;
        const std::optional<int> n = wholeNumber(parser, option, lo, hi, error);
        if (n) *v = *n;
        return n.has_value();
    };
    // A positive finite number, or the usage error "--NAME must be WHAT > 0, got 'VALUE'".
    const auto positive = [&](const QCommandLineOption& option, const char* what, double* v) {
        if (!parser.isSet(option)) return true;
        bool ok = false;
        *v = parser.value(option).toDouble(&ok);
        if (ok && std::isfinite(*v) && *v > 0.0) return true;
        *error = QStringLiteral("--%1 must be %2 > 0, got '%3'")
                     .arg(option.names().constLast(), QLatin1String(what), parser.value(option));
        return false;
    };
    if (!number(samples, 1, 1000000, &o.samples) || !number(bounces, 0, 1024, &o.bounces) ||
        !number(threads, 1, 1024, &o.threads) || !number(seed, 0, 2147483647, &o.seed) ||
        !positive(fireflyClamp, "a linear radiance", &o.fireflyClamp) ||
        !positive(timeLimit, "a number of seconds", &o.timeLimit) ||
        !positive(noiseThreshold, "a relative noise", &o.noiseThreshold))
        return std::nullopt;
    if (!parser.isSet(samples) && (o.timeLimit > 0.0 || o.noiseThreshold > 0.0)) o.samples = 1000000;
    return o;
}

std::optional<int> wholeNumber(const QCommandLineParser& parser, const QCommandLineOption& option, int lo,
                               int hi, QString* message) {
    bool ok = false;
    const QString text = parser.value(option);
    const int v = text.toInt(&ok);
    if (ok && v >= lo && v <= hi) return v;
    *message = QStringLiteral("--%1 must be a whole number in %2..%3, got '%4'")
                   .arg(option.names().constLast())
                   .arg(lo)
                   .arg(hi)
                   .arg(text);
    return std::nullopt;
}

} // namespace lr::cli
