// `lightrig mix AOVS.exr --mix MIX.json [--mix MIX2.json ...] -o OUT.png|OUT.exr|FOLDER [--format png|exr]
//  [--exposure EV] [--tonemap OP]` (issue 37; docs/light-mixing.md): re-balances a finished render per light
// group with no render. AOVS.exr is what `render --aovs` wrote (or any multi-layer EXR whose RGB layers are
// light groups); it is decoded once, in the import worker (an untrusted file), and each mix file makes one
// image: Σ tint × 2^ev × group. One --mix writes OUT (a file); several write FOLDER/NAME.png (or .exr), NAME
// being each mix file's base name: one traced render, many looks. A .png is exposed and tone mapped as the
// render was (the EXR header's lightrig/exposureEV and lightrig/toneMap) unless --exposure or --tonemap say
// otherwise; an .exr is scene-linear float RGBA. Every mix file is read and checked against the image's
// groups before anything is written, and the outputs are written all or none.
// Exit status: 0 written; 1 a bad image or mix file (naming the file and the field) or an unwritable output;
// 2 usage error.
#include "cli.h"
#include "outputfiles.h"

#include "core/lightmixfile.h"
#include "core/types.h"
#include "model/exrdecode.h"
#include "render/imagefile.h"
#include "scene/displayimage.h"
#include "scene/renderlayersexr.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QTextStream>
#include <cmath>

namespace lr::cli {

namespace {

const char* kUsage = "lightrig mix AOVS.exr --mix MIX.json [--mix MIX2.json ...] -o OUT.png|OUT.exr|FOLDER "
                     "[--format png|exr] [--exposure EV] [--tonemap OP]";

QString attributeOf(const ExrFile& file, const char* name) {
    for (const auto& [key, value] : file.attributes)
        if (key == QLatin1String(name)) return value;
    return {};
}

} // namespace

int runMix(const QStringList& args) {
    QTextStream err(stderr), out(stdout);
    const QString name = QStringLiteral("lightrig mix");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Re-balances a render's light groups with no render: each mix file (format \"lightrig-mix\") gives "
        "per group an on/off, an EV and a tint, and makes one image from AOVS.exr (written by lightrig "
        "render "
        "--aovs).\nExit status: 0 written, 1 bad image, mix file or output (nothing written), 2 usage "
        "error."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("Show this help."));
    const QCommandLineOption mixOption(QStringLiteral("mix"),
                                       QStringLiteral("A mix file (repeat for several looks)."),
                                       QStringLiteral("MIX.json"));
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")},
                                    QStringLiteral("The image (.png, .jpg, .jpeg or .exr), or with several "
                                                   "--mix a folder."),
                                    QStringLiteral("OUT"));
    const QCommandLineOption format(QStringLiteral("format"),
                                    QStringLiteral("With several --mix: png (default), jpeg or exr."),
                                    QStringLiteral("F"));
    const QCommandLineOption exposure(QStringLiteral("exposure"),
                                      QStringLiteral("Exposure in EV for .png/.jpg (default: the render's)."),
                                      QStringLiteral("EV"));
    const QCommandLineOption toneMap(
        QStringLiteral("tonemap"),
        QStringLiteral("Tone map for .png/.jpg: %1 (default: the render's).").arg(allowedNames<ToneMap>()),
        QStringLiteral("OP"));
    parser.addOptions({help, mixOption, output, format, exposure, toneMap});
    parser.addPositionalArgument(QStringLiteral("AOVS.exr"), QStringLiteral("What render --aovs wrote."));
    const CommandUsage usage{name, kUsage, out, err};
    if (const std::optional<int> done = usage.parse(parser, args, help)) return *done;
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1 || positional[0].isEmpty())
        return usage(QStringLiteral("needs one AOVS.exr, got %1 argument(s)").arg(positional.size()));
    const QStringList mixes = parser.values(mixOption);
    if (mixes.isEmpty()) return usage(QStringLiteral("needs at least one --mix MIX.json"));
    if (!parser.isSet(output)) return usage(QStringLiteral("needs -o OUT"));
    double exposureEV = 0.0;
    if (parser.isSet(exposure)) {
        bool ok = false;
        exposureEV = parser.value(exposure).toDouble(&ok);
        if (!ok || !std::isfinite(exposureEV) || std::abs(exposureEV) > 60.0)
            return usage(QStringLiteral("--exposure must be a number of EV in -60..60, got '%1'")
                             .arg(parser.value(exposure)));
    }
    std::optional<ToneMap> tone;
    if (parser.isSet(toneMap)) {
        tone = fromString<ToneMap>(parser.value(toneMap));
        if (!tone)
            return usage(QStringLiteral("--tonemap must be %1, got '%2'")
                             .arg(allowedNames<ToneMap>(), parser.value(toneMap)));
    }
    // Where each look goes, and as what.
    const QString outPath = parser.value(output);
    std::vector<std::pair<QString, QByteArray>> targets; // path, "png" | "jpeg" | "exr"
    const auto formatOf = [](const QString& path) -> QByteArray {
        if (path.endsWith(QLatin1String(".exr"), Qt::CaseInsensitive)) return "exr";
        return writableImageFormatOf(path);
    };
    if (mixes.size() == 1 && !QFileInfo(outPath).isDir()) {
        if (parser.isSet(format)) return usage(QStringLiteral("--format applies to a folder output only"));
        const QByteArray f = formatOf(outPath);
        if (f.isEmpty())
            return usage(QStringLiteral("-o must end in .png, .jpg, .jpeg or .exr: '%1'").arg(outPath));
        targets.push_back({outPath, f});
    } else {
        if (!QFileInfo(outPath).isDir())
            return usage(
                QStringLiteral("with several --mix, -o must be an existing folder: '%1'").arg(outPath));
        QByteArray f = parser.isSet(format) ? parser.value(format).toLower().toLatin1() : QByteArray("png");
        if (f == "jpg") f = "jpeg";
        if (f != "png" && f != "jpeg" && f != "exr")
            return usage(
                QStringLiteral("--format must be png, jpeg or exr, got '%1'").arg(parser.value(format)));
        QStringList seen;
        for (const QString& m : mixes) {
            const QString base = QFileInfo(m).completeBaseName();
            if (seen.contains(base))
                return usage(
                    QStringLiteral("two mix files are named %1: their images would overwrite each other")
                        .arg(base));
            seen << base;
            targets.push_back({QDir(outPath).filePath(base + QLatin1Char('.') +
                                                      QString::fromLatin1(f == "jpeg" ? "jpg" : f)),
                               f});
        }
    }

    const auto failed = [&](const QString& reason) {
        err << name << ": " << QString(reason).replace(QLatin1Char('\n'), QLatin1String(" | ")) << '\n';
        return int(Failed);
    };
    QString message;
    std::vector<NamedFile> inputs{{positional[0], QStringLiteral("the image")}}, written;
    for (const QString& m : mixes)
        inputs.push_back({m, QStringLiteral("a mix file")});
    for (const auto& [path, f] : targets)
        written.push_back({path, QStringLiteral("an output")});
    if (!checkDistinctFiles(inputs, written, &message)) return failed(message);
    for (const auto& [path, f] : targets)
        if (!checkOutputPath(path, &message)) return failed(message);

    const std::optional<ExrFile> file = importExrLayersIsolated(positional[0], &message);
    if (!file) return failed(message);
    const std::optional<RenderLayers> layers = renderLayersFromExr(*file, &message);
    if (!layers) return failed(QStringLiteral("%1: %2").arg(positional[0], message));
    if (layers->groups.empty())
        return failed(
            QStringLiteral("%1: it has no light groups to mix (write it with lightrig render --aovs)")
                .arg(positional[0]));
    const QStringList groups = groupNames(layers->groups);
    std::vector<LightMix> looks;
    for (const QString& m : mixes) {
        const LightMixReadResult r = readLightMixFile(m, groups);
        for (const QString& w : r.warnings)
            err << name << ": warning: " << w << '\n';
        if (!r.mix) return failed(r.errors.join(QLatin1Char('\n')));
        looks.push_back(*r.mix);
    }
    if (!tone) tone = fromString<ToneMap>(attributeOf(*file, "lightrig/toneMap"));
    if (!parser.isSet(exposure)) {
        bool ok = false;
        const double ev = attributeOf(*file, "lightrig/exposureEV").toDouble(&ok);
        if (ok && std::isfinite(ev)) exposureEV = ev;
    }
    const bool transparent = std::any_of(layers->beauty.pixels.begin(), layers->beauty.pixels.end(),
                                         [](const glm::vec4& p) { return p.w < 1.0f; });
    std::vector<OutputBytes> files;
    for (size_t i = 0; i < looks.size(); ++i) {
        const FloatImage mixed = mixGroupImages(*layers, looks[i]);
        QByteArray bytes;
        if (targets[i].second == "exr") {
            bytes =
                encodeExrRgba(mixed.width, mixed.height, &mixed.pixels.front().x,
                              {{QStringLiteral("lightrig/mix"), QFileInfo(mixes[qsizetype(i)]).fileName()},
                               {QStringLiteral("lightrig/exposureEV"), QString::number(exposureEV)},
                               {QStringLiteral("lightrig/toneMap"), toString(tone.value_or(ToneMap::Clamp))}},
                              &message);
        } else {
            bytes = encodeImage(displayImage(mixed, exposureEV, tone.value_or(ToneMap::Clamp), transparent),
                                targets[i].second, &message);
        }
        if (bytes.isEmpty()) return failed(QStringLiteral("%1: %2").arg(targets[i].first, message));
        files.push_back({targets[i].first, bytes});
    }
    if (!writeOutputFiles(files, &message)) return failed(message);
    for (size_t i = 0; i < files.size(); ++i)
        out << QStringLiteral("wrote %1 (%2x%3): %4 of %5 groups changed by %6\n")
                   .arg(files[i].path)
                   .arg(layers->beauty.width)
                   .arg(layers->beauty.height)
                   .arg(std::count_if(looks[i].groups.begin(), looks[i].groups.end(),
                                      [](const auto& g) { return !g.second.isIdentity(); }))
                   .arg(groups.size())
                   .arg(mixes[qsizetype(i)]);
    return Ok;
}

} // namespace lr::cli
