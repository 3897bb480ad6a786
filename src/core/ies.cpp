// The LM-63 reader (core/ies.h): header lines up to TILT=, then whitespace- or comma-separated numbers
// that may wrap across lines. Every number is checked where it is read, with the line it is on.
#include "ies.h"

#include <QFile>
#include <QFileInfo>
#include <charconv>
#include <optional>

namespace lr {

namespace {

constexpr int kMaxHeaderLines = 10000;
constexpr int kMaxTiltAngles = 10000;

struct Failure {
    int line;
    QString reason;
};

class Reader {
  public:
    Reader(const QByteArray& data) : m_data(data) {}

    // The next line (without its end), or nullopt at the end of the data.
    std::optional<QByteArray> line() {
        if (m_pos >= m_data.size()) return std::nullopt;
        qsizetype end = m_data.indexOf('\n', m_pos);
        if (end < 0) end = m_data.size();
        QByteArray l = m_data.mid(m_pos, end - m_pos);
        if (l.endsWith('\r')) l.chop(1);
        m_lastLine = m_line;
        if (end < m_data.size()) ++m_line;
        m_pos = end + 1;
        return l;
    }
    int lineNumber() const { return m_line; }
    int lastLine() const { return m_lastLine; } // the line line() returned, or the last number's

    // The next number; `what` names it in the message.
    double number(const QString& what) {
        skipSpace();
        if (m_pos >= m_data.size())
            throw Failure{m_lastLine, QStringLiteral("the file ends before %1 (truncated?)").arg(what)};
        m_lastLine = m_line;
        const qsizetype start = m_pos;
        while (m_pos < m_data.size() && !isSeparator(m_data[m_pos]))
            ++m_pos;
        QByteArray token = m_data.mid(start, m_pos - start);
        const QByteArray shown = token.left(40);
        if (token.startsWith('+')) token.remove(0, 1);
        double v = 0.0;
        const char* b = token.constData();
        const char* e = b + token.size();
        const auto [ptr, ec] = std::from_chars(b, e, v);
        const bool alpha = !token.isEmpty() && (std::isalpha(uchar(token[0])) ||
                                                (token.size() > 1 && std::isalpha(uchar(token[1]))));
        if (token.isEmpty() || alpha || ec != std::errc() || ptr != e)
            throw Failure{m_line,
                          QStringLiteral("%1: \"%2\" is not a number").arg(what, QString::fromLatin1(shown))};
        if (!std::isfinite(v))
            throw Failure{m_line,
                          QStringLiteral("%1: %2 is not finite").arg(what, QString::fromLatin1(shown))};
        return v;
    }
    int integer(const QString& what, int lo, int hi) {
        const int at = (skipSpace(), m_line);
        const double v = number(what);
        if (v != std::floor(v) || v < lo || v > hi)
            throw Failure{at, QStringLiteral("%1 is %2; expected an integer from %3 to %4")
                                  .arg(what)
                                  .arg(v)
                                  .arg(lo)
                                  .arg(hi)};
        return int(v);
    }
    bool atEnd() {
        skipSpace();
        return m_pos >= m_data.size();
    }

  private:
    static bool isSeparator(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ','; }
    void skipSpace() {
        while (m_pos < m_data.size() && isSeparator(m_data[m_pos])) {
            if (m_data[m_pos] == '\n') ++m_line;
            ++m_pos;
        }
    }
    const QByteArray& m_data;
    qsizetype m_pos = 0;
    int m_line = 1; // the line m_pos is on
    int m_lastLine = 1;
};

// Angles: finite (the reader checks), strictly ascending, within [lo, hi].
std::vector<double> readAngles(Reader& r, int n, const char* which, double lo, double hi) {
    std::vector<double> a;
    a.reserve(std::size_t(n));
    for (int i = 0; i < n; ++i) {
        const QString what = QStringLiteral("%1 angle %2").arg(QLatin1String(which)).arg(i + 1);
        const double v = r.number(what);
        if (v < lo || v > hi)
            throw Failure{
                r.lineNumber(),
                QStringLiteral("%1 is %2; it must lie in %3 ... %4").arg(what).arg(v).arg(lo).arg(hi)};
        if (!a.empty() && !(v > a.back()))
            throw Failure{r.lineNumber(), QStringLiteral("%1 is %2, not above the one before (%3): angles "
                                                         "must ascend")
                                              .arg(what)
                                              .arg(v)
                                              .arg(a.back())};
        a.push_back(v);
    }
    return a;
}

// The file's horizontal columns unfolded to 0 ... 360 (see ies.h).
void unfold(IesProfile& p, const std::vector<double>& h, const std::vector<double>& cd, int line) {
    const std::size_t nv = p.vertical.size();
    const auto column = [&](std::size_t i) {
        return std::vector<double>(cd.begin() + long(i * nv), cd.begin() + long((i + 1) * nv));
    };
    std::vector<std::pair<double, std::vector<double>>> cols;
    const double first = h.front(), last = h.back();
    if (h.size() == 1) {
        if (first != 0.0)
            throw Failure{line,
                          QStringLiteral("a single horizontal angle must be 0 (rotational symmetry), not %1")
                              .arg(first)};
        p.symmetry = QStringLiteral("rotational");
        cols = {{0.0, column(0)}, {360.0, column(0)}};
    } else if (first == 0.0 && last == 90.0) {
        p.symmetry = QStringLiteral("quadrant");
        for (std::size_t i = 0; i < h.size(); ++i) {
            cols.push_back({h[i], column(i)});
            cols.push_back({180.0 - h[i], column(i)});
            cols.push_back({180.0 + h[i], column(i)});
            cols.push_back({360.0 - h[i], column(i)});
        }
    } else if (first == 0.0 && last == 180.0) {
        p.symmetry = QStringLiteral("bilateral");
        for (std::size_t i = 0; i < h.size(); ++i) {
            cols.push_back({h[i], column(i)});
            cols.push_back({360.0 - h[i], column(i)});
        }
    } else if (first == 90.0 && last == 270.0) {
        p.symmetry = QStringLiteral("bilateral-90");
        for (std::size_t i = 0; i < h.size(); ++i) {
            cols.push_back({h[i], column(i)});
            cols.push_back({h[i] <= 180.0 ? 180.0 - h[i] : 540.0 - h[i], column(i)});
        }
    } else if (first == 0.0 && last > 180.0) {
        p.symmetry = QStringLiteral("full");
        for (std::size_t i = 0; i < h.size(); ++i)
            cols.push_back({h[i], column(i)});
    } else {
        throw Failure{line,
                      QStringLiteral("horizontal angles from %1 to %2 are no LM-63 symmetry: type C "
                                     "horizontal angles are 0 alone, 0 ... 90, 0 ... 180, 90 ... 270 or "
                                     "0 ... more than 180")
                          .arg(first)
                          .arg(last)};
    }
    std::stable_sort(cols.begin(), cols.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [angle, values] : cols) {
        if (!p.horizontal.empty() && p.horizontal.back() == angle) continue; // mirror planes appear twice
        p.horizontal.push_back(angle);
        p.candela.insert(p.candela.end(), values.begin(), values.end());
    }
    if (p.horizontal.back() < 360.0) { // closed over the gap to 360 = 0 (full without 360; bilateral-90)
        p.horizontal.push_back(360.0);
        const std::vector<double> zero(p.candela.begin(), p.candela.begin() + long(nv));
        p.candela.insert(p.candela.end(), zero.begin(), zero.end());
    }
}

std::shared_ptr<IesProfile> parse(const QByteArray& data) {
    auto p = std::make_shared<IesProfile>();
    Reader r(data);
    p->format = QStringLiteral("LM-63-1986");
    bool tilt = false;
    QByteArray tiltValue;
    for (int n = 0; n < kMaxHeaderLines && !tilt; ++n) {
        const auto l = r.line();
        if (!l)
            throw Failure{
                r.lastLine(),
                QStringLiteral("the file ends before its TILT= line (truncated, or not an IES file)")};
        const QByteArray t = l->trimmed();
        if (n == 0 && (t.startsWith("IESNA:LM-63-") || t.startsWith("IES:LM-63-")))
            p->format = QString::fromLatin1(t.mid(t.indexOf(':') + 1, 10));
        else if (n == 0 && t.startsWith("IESNA91"))
            p->format = QStringLiteral("LM-63-1991");
        if (t.startsWith("TILT")) {
            const qsizetype eq = t.indexOf('=');
            if (eq < 0) throw Failure{r.lastLine(), QStringLiteral("\"TILT\" without \"=\"")};
            tiltValue = t.mid(eq + 1).trimmed();
            tilt = true;
        }
    }
    if (!tilt)
        throw Failure{r.lineNumber(),
                      QStringLiteral("no TILT= line in the first %1 lines").arg(kMaxHeaderLines)};
    if (tiltValue == "INCLUDE") { // read and checked, not applied (ies.h)
        r.integer(QStringLiteral("the lamp-to-luminaire geometry"), 1, 3);
        const int n = r.integer(QStringLiteral("the number of tilt angles"), 0, kMaxTiltAngles);
        readAngles(r, n, "tilt", 0.0, 180.0);
        for (int i = 0; i < n; ++i)
            if (r.number(QStringLiteral("tilt multiplier %1").arg(i + 1)) < 0.0)
                throw Failure{r.lineNumber(), QStringLiteral("tilt multiplier %1 is negative").arg(i + 1)};
    } else if (tiltValue.isEmpty()) {
        throw Failure{r.lastLine(), QStringLiteral("TILT= names nothing (NONE, INCLUDE or a file)")};
    }
    r.integer(QStringLiteral("the number of lamps"), 0, 1 << 20);
    const double lumens = r.number(QStringLiteral("the lumens per lamp"));
    if (lumens <= 0.0 && lumens != -1.0)
        throw Failure{
            r.lineNumber(),
            QStringLiteral("the lumens per lamp are %1; positive, or -1 (absolute photometry)").arg(lumens)};
    const double multiplier = r.number(QStringLiteral("the candela multiplier"));
    if (multiplier <= 0.0)
        throw Failure{r.lineNumber(),
                      QStringLiteral("the candela multiplier is %1; it must be positive").arg(multiplier)};
    const int nv = r.integer(QStringLiteral("the number of vertical angles"), 1, kMaxIesAngles);
    const int nh = r.integer(QStringLiteral("the number of horizontal angles"), 1, kMaxIesAngles);
    const int typeLine = (r.atEnd(), r.lineNumber());
    const int type = r.integer(QStringLiteral("the photometric type"), 1, 3);
    if (type != 1)
        throw Failure{typeLine, QStringLiteral("photometric type %1 (%2) is not read: only type C (1)")
                                    .arg(type)
                                    .arg(type == 2 ? QStringLiteral("B") : QStringLiteral("A"))};
    if ((long long)nv * nh > kMaxIesValues)
        throw Failure{
            typeLine,
            QStringLiteral("%1 × %2 candela values; at most %3").arg(nv).arg(nh).arg(kMaxIesValues)};
    r.integer(QStringLiteral("the units type"), 1, 2);
    for (const char* what : {"the luminous width", "the luminous length", "the luminous height"})
        r.number(QLatin1String(what));
    if (r.number(QStringLiteral("the ballast factor")) < 0.0)
        throw Failure{r.lineNumber(), QStringLiteral("the ballast factor is negative")};
    r.number(QStringLiteral("the file generation type / ballast-lamp factor"));
    r.number(QStringLiteral("the input watts"));
    p->vertical = readAngles(r, nv, "vertical", 0.0, 180.0);
    const int hLine = (r.atEnd(), r.lineNumber());
    const std::vector<double> h = readAngles(r, nh, "horizontal", 0.0, 360.0);
    std::vector<double> cd(std::size_t(nv) * std::size_t(nh));
    for (int i = 0; i < nh; ++i)
        for (int j = 0; j < nv; ++j) {
            const QString what =
                QStringLiteral("candela value %1 of horizontal angle %2").arg(j + 1).arg(h[std::size_t(i)]);
            const double v = r.number(what);
            if (v < 0.0)
                throw Failure{r.lineNumber(), QStringLiteral("%1 is negative (%2)").arg(what).arg(v)};
            cd[std::size_t(i) * std::size_t(nv) + std::size_t(j)] = v * multiplier;
            if (!std::isfinite(cd[std::size_t(i) * std::size_t(nv) + std::size_t(j)]))
                throw Failure{r.lineNumber(),
                              QStringLiteral("%1 × the candela multiplier is not finite").arg(what)};
        }
    if (!r.atEnd())
        throw Failure{r.lineNumber(), QStringLiteral("more numbers after the last candela value")};
    p->fileVertical = nv;
    p->fileHorizontal = nh;
    unfold(*p, h, cd, hLine);
    for (const double v : p->candela)
        p->peak = std::max(p->peak, v);
    return p;
}

} // namespace

std::shared_ptr<const IesProfile> readIesData(const QByteArray& data, const QString& name, QString* error) {
    try {
        return parse(data);
    } catch (const Failure& f) {
        if (error) *error = QStringLiteral("%1:%2: %3").arg(name).arg(std::max(f.line, 1)).arg(f.reason);
    } catch (const std::bad_alloc&) {
        if (error) *error = QStringLiteral("%1: out of memory").arg(name);
    }
    return nullptr;
}

std::shared_ptr<const IesProfile> readIesFile(const QString& path, QString* error) {
    QFile file(path);
    if (!QFileInfo(path).isFile() || !file.open(QIODevice::ReadOnly)) {
        if (error)
            *error =
                QStringLiteral("%1: cannot open: %2")
                    .arg(path, QFileInfo::exists(path) ? file.errorString() : QStringLiteral("no such file"));
        return nullptr;
    }
    if (file.size() > kMaxIesFileBytes) {
        if (error)
            *error = QStringLiteral("%1: %2 bytes; an IES file may have at most %3")
                         .arg(path)
                         .arg(file.size())
                         .arg(kMaxIesFileBytes);
        return nullptr;
    }
    const QByteArray data = file.read(kMaxIesFileBytes + 1);
    if (file.error() != QFileDevice::NoError) {
        if (error) *error = QStringLiteral("%1: cannot read: %2").arg(path, file.errorString());
        return nullptr;
    }
    return readIesData(data, path, error);
}

double iesBeamAngle(const IesProfile& p) {
    if (!(p.peak > 0.0) || p.vertical.empty()) return 0.0;
    if (p.vertical.size() == 1) return 360.0; // the same everywhere
    const double half = 0.5 * p.peak;
    // The outermost vertical angle of the half plane at `phi` where the intensity is >= half (linear).
    const auto extent = [&](double phi) {
        double out = 0.0;
        const std::size_t n = p.vertical.size();
        for (std::size_t i = 0; i < n; ++i) {
            const double v = iesCandela(p, p.vertical[i], phi);
            if (v < half) continue;
            out = p.vertical[i];
            if (i + 1 < n) {
                const double w = iesCandela(p, p.vertical[i + 1], phi);
                if (w < half) out += (p.vertical[i + 1] - p.vertical[i]) * (v - half) / (v - w);
            }
        }
        return out;
    };
    return 0.5 * ((extent(0.0) + extent(180.0)) + (extent(90.0) + extent(270.0)));
}

} // namespace lr
