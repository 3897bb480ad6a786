#include "environmentdecode.h"

#include "environmentstb.h"
#include "exrio.h"

#include <ImfArray.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <QByteArray>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <exception>
#include <sys/stat.h>

namespace lr {

namespace {

constexpr char kExrMagic[] = {0x76, 0x2f, 0x31, 0x01};

QString sizeProblem(qint64 w, qint64 h) {
    if (w <= 0 || h <= 0) return QStringLiteral("its size %1×%2 is empty").arg(w).arg(h);
    if (w > kMaxEnvironmentSide || h > kMaxEnvironmentSide)
        return QStringLiteral("%1×%2 texels is larger than the limit of %3 on a side")
            .arg(w)
            .arg(h)
            .arg(kMaxEnvironmentSide);
    if (w * h > kMaxEnvironmentTexels)
        return QStringLiteral("%1×%2 texels is more than the limit of %3 Mpx")
            .arg(w)
            .arg(h)
            .arg(kMaxEnvironmentTexels >> 20);
    return {};
}

// A header's size against the file's: more texels than such a file could hold is refused before any
// pixel memory is allocated (maxEnvironmentDecodedBytes).
QString expansionProblem(qint64 w, qint64 h, qint64 fileBytes) {
    const qint64 decoded = w * h * qint64(sizeof(glm::vec3));
    if (decoded <= maxEnvironmentDecodedBytes(fileBytes)) return {};
    return QStringLiteral("the header claims %1×%2 texels (%3 MiB decoded) but the file holds only %4 bytes "
                          "(at most %5 bytes decoded per byte of file are accepted)")
        .arg(w)
        .arg(h)
        .arg(decoded >> 20)
        .arg(fileBytes)
        .arg(kMaxEnvironmentExpansion);
}

// OpenEXR: the header is checked against the limits and the file size before any pixel is read.
QString decodeExr(QByteArrayView bytes, EnvironmentImage* image) {
    exrio::MemoryIStream stream(bytes);
    { // The (first part's) header alone, before InputFile sizes its tables by it.
        Imf::Header first;
        exrio::readFirstHeader(stream, bytes, &first);
        const qint64 w = exrio::windowWidth(first.dataWindow()), h = exrio::windowHeight(first.dataWindow());
        if (QString why = sizeProblem(w, h); !why.isEmpty()) return why;
        if (exrio::chunkCount(first) * 8 > bytes.size() - qint64(stream.tellg()))
            return QStringLiteral("the header claims %1×%2 texels but the file holds only %3 bytes")
                .arg(w)
                .arg(h)
                .arg(bytes.size());
        if (QString why = expansionProblem(w, h, bytes.size()); !why.isEmpty()) return why;
        stream.seekg(0);
    }
    Imf::InputFile file(stream, 1);
    const Imf::Header& header = file.header();
    const Imath::Box2i window = header.dataWindow();
    const qint64 w = qint64(window.max.x) - window.min.x + 1, h = qint64(window.max.y) - window.min.y + 1;
    if (QString why = sizeProblem(w, h); !why.isEmpty()) return why;
    const Imf::ChannelList& channels = header.channels();
    const bool rgb = channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B");
    const bool grey = !rgb && channels.findChannel("Y");
    if (!rgb && !grey) return QStringLiteral("it has no R, G, B or Y channel");
    image->width = int(w);
    image->height = int(h);
    image->texels.assign(size_t(w * h), glm::vec3(0.0f));
    char* base = reinterpret_cast<char*>(image->texels.data());
    Imf::FrameBuffer fb;
    const size_t xs = sizeof(glm::vec3), ys = xs * size_t(w);
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
        fb.insert(grey ? "Y" : names[c],
                  Imf::Slice::Make(Imf::FLOAT, base + c * sizeof(float), window, xs, ys));
    file.setFrameBuffer(fb);
    file.readPixels(window.min.y, window.max.y);
    return {};
}

// Walks the pixel data the way stb_image's decoder will, without decoding: stb_image reads zeros past the
// end and loops forever on a run of length 0, so both are refused here first.
QString checkRgbeData(QByteArrayView data, qint64 w, qint64 h) {
    const QString truncated = QStringLiteral("the file ends before its pixel data does");
    if (w < 8 || w >= 32768) return 4 * w * h <= data.size() ? QString() : truncated;
    qsizetype pos = 0;
    const auto byte = [&](quint8* out) {
        if (pos >= data.size()) return false;
        *out = quint8(data[pos++]);
        return true;
    };
    for (qint64 y = 0; y < h; ++y) {
        const qsizetype lineStart = pos;
        quint8 c[4];
        for (quint8& b : c)
            if (!byte(&b)) return truncated;
        if (c[0] != 2 || c[1] != 2 || (c[2] & 0x80)) // not run-length encoded: flat from here to the end
            return lineStart + 4 * w * h <= data.size() ? QString() : truncated;
        if ((qint64(c[2]) << 8 | c[3]) != w)
            return QStringLiteral("corrupt run-length data (scanline %1 is not %2 texels wide)")
                .arg(y)
                .arg(w);
        for (int channel = 0; channel < 4; ++channel)
            for (qint64 x = 0; x < w;) {
                quint8 count = 0;
                if (!byte(&count)) return truncated;
                const bool run = count > 128;
                const qint64 n = run ? count - 128 : count;
                if (n == 0 || n > w - x)
                    return QStringLiteral("corrupt run-length data (a run of %1 in scanline %2)")
                        .arg(n)
                        .arg(y);
                if (pos + (run ? 1 : n) > data.size()) return truncated;
                pos += run ? 1 : n;
                x += n;
            }
    }
    return {};
}

// Radiance RGBE: the header parsed here (limits, a lower bound on the data size), the pixels by stb.
QString decodeHdr(QByteArrayView bytes, EnvironmentImage* image) {
    qsizetype end = bytes.indexOf("\n\n");
    // A header written with CRLF line ends (Windows tools): its lines read with LF, as stb reads them;
    // the pixels after the resolution line are not touched.
    QByteArray lf;
    if (const qsizetype crlf = bytes.indexOf("\r\n\r\n"); crlf >= 0 && (end < 0 || crlf < end)) {
        if (const qsizetype resolutionEnd = bytes.indexOf('\n', crlf + 4); resolutionEnd >= 0) {
            lf = bytes.first(resolutionEnd + 1).toByteArray().replace("\r\n", "\n");
            lf += bytes.sliced(resolutionEnd + 1);
            bytes = lf;
            end = bytes.indexOf("\n\n");
        }
    }
    if (end < 0) return QStringLiteral("its Radiance header does not end");
    const qsizetype lineEnd = bytes.indexOf('\n', end + 2);
    const QByteArrayView resolution =
        lineEnd < 0 ? QByteArrayView() : bytes.sliced(end + 2, lineEnd - end - 2);
    static const QRegularExpression re(QStringLiteral("^-Y (\\d{1,9}) \\+X (\\d{1,9})$"));
    const auto m = re.match(QString::fromLatin1(resolution).trimmed());
    if (!m.hasMatch()) return QStringLiteral("its resolution line is not \"-Y height +X width\"");
    const qint64 h = m.captured(1).toLongLong(), w = m.captured(2).toLongLong();
    if (QString why = sizeProblem(w, h); !why.isEmpty()) return why;
    // Each scanline takes at least 4 bytes a texel flat, or run-length encoded 4 + 4 × 2 per 127 texels.
    const qint64 minLine = (w < 8 || w >= 32768) ? 4 * w : std::min(4 * w, 4 + 8 * ((w + 126) / 127));
    if (minLine * h > bytes.size() - lineEnd - 1)
        return QStringLiteral("the header claims %1×%2 texels but the file holds only %3 bytes")
            .arg(w)
            .arg(h)
            .arg(bytes.size());
    if (QString why = expansionProblem(w, h, bytes.size()); !why.isEmpty()) return why;
    if (QString why = checkRgbeData(bytes.sliced(lineEnd + 1), w, h); !why.isEmpty()) return why;
    stb::HdrResult r = stb::decodeHdr(bytes.data(), size_t(bytes.size()));
    if (!r.error.empty())
        return QStringLiteral("truncated or corrupt Radiance file (%1)").arg(QString::fromStdString(r.error));
    if (r.width != w || r.height != h) return QStringLiteral("its size does not match its header");
    image->width = r.width;
    image->height = r.height;
    image->texels.resize(size_t(w * h));
    std::memcpy(image->texels.data(), r.rgb.data(), r.rgb.size() * sizeof(float));
    return {};
}

// Values that are NaN or infinite become 0, negative ones 0, those above kMaxEnvironmentRadiance that
// limit; counted by texel.
struct Sanitised {
    qint64 nonFinite = 0, negative = 0, bright = 0;
    double mostNegative = 0.0, mean = 0.0; // the mean of every finite value in [0, limit]
};
Sanitised sanitise(EnvironmentImage* image) {
    Sanitised s;
    double sum = 0.0;
    qint64 counted = 0;
    for (glm::vec3& t : image->texels) {
        bool nonFinite = false, negative = false, bright = false;
        for (int c = 0; c < 3; ++c) {
            float& v = t[c];
            if (!std::isfinite(v)) {
                v = 0.0f;
                nonFinite = true;
            } else if (v < 0.0f) {
                s.mostNegative = std::min(s.mostNegative, double(v));
                v = 0.0f;
                negative = true;
            } else if (v > kMaxEnvironmentRadiance) {
                v = kMaxEnvironmentRadiance;
                bright = true;
            } else {
                sum += v;
                ++counted;
            }
        }
        s.nonFinite += nonFinite;
        s.negative += negative;
        s.bright += bright;
    }
    s.mean = counted > 0 ? sum / double(counted) : 0.0;
    return s;
}

} // namespace

EnvironmentDecodeResult decodeEnvironment(QByteArrayView bytes, const QString& path) {
    EnvironmentDecodeResult r;
    const QString name = QFileInfo(path).fileName().isEmpty() ? path : QFileInfo(path).fileName();
    try {
        if (bytes.size() >= 4 && std::memcmp(bytes.data(), kExrMagic, 4) == 0)
            r.reason = decodeExr(bytes, &r.image);
        else if (bytes.startsWith("#?RADIANCE") || bytes.startsWith("#?RGBE"))
            r.reason = decodeHdr(bytes, &r.image);
        else
            r.reason = QStringLiteral("not an OpenEXR or Radiance .hdr image (unknown first bytes)");
    } catch (const std::bad_alloc&) {
        r.reason = QStringLiteral("out of memory decoding it");
    } catch (const std::exception& e) {
        r.reason = QStringLiteral("truncated or corrupt OpenEXR (%1)").arg(QString::fromLocal8Bit(e.what()));
    } catch (...) {
        r.reason = QStringLiteral("truncated or corrupt image");
    }
    if (!r.reason.isEmpty()) {
        r.image = {};
        r.error = QStringLiteral("could not read %1: %2").arg(path, r.reason);
        return r;
    }
    const Sanitised s = sanitise(&r.image);
    if (s.nonFinite > 0)
        r.warnings << QStringLiteral("%1: %2 texels were NaN or infinite and were set to 0")
                          .arg(name)
                          .arg(s.nonFinite);
    // Lossy compression rings slightly below 0 around bright edges (studio.exr: 3 texels, the lowest
    // -3e-6 in an image of mean 0.26; each of the eight shared DWAB HDRIs has a few, down to -3e-4): set
    // to 0 without a word. A negative that matters is a broken file.
    if (s.negative > 0 && -s.mostNegative > kNegativeTolerance * s.mean)
        r.warnings << QStringLiteral("%1: %2 texels were negative (down to %3) and were set to 0")
                          .arg(name)
                          .arg(s.negative)
                          .arg(s.mostNegative, 0, 'g', 3);
    if (s.bright > 0)
        r.warnings << QStringLiteral("%1: %2 texels were brighter than %3 and were clamped to it (brighter "
                                     "values overflow when the environment is filtered)")
                          .arg(name)
                          .arg(s.bright)
                          .arg(double(kMaxEnvironmentRadiance), 0, 'g', 3);
    if (r.image.width != 2 * r.image.height)
        r.warnings << QStringLiteral("%1: %2×%3 is not 2:1; it is stretched over the sphere as an "
                                     "equirectangular image")
                          .arg(name)
                          .arg(r.image.width)
                          .arg(r.image.height);
    return r;
}

QString environmentFileProblem(const QString& path) {
    struct stat st {};
    if (::stat(QFile::encodeName(path).constData(), &st) != 0)
        return errno == ENOENT ? QStringLiteral("no such file")
                               : QString::fromLocal8Bit(std::strerror(errno));
    if (!S_ISREG(st.st_mode)) return QStringLiteral("not a regular file (a folder, FIFO, socket or device)");
    return {};
}

EnvironmentDecodeResult decodeEnvironmentFile(const QString& path) {
    exrio::UntrustedFile file;
    if (QString problem = file.open(path, kMaxEnvironmentFileBytes); !problem.isEmpty()) {
        EnvironmentDecodeResult r;
        r.reason = problem;
        r.error = QStringLiteral("could not read %1: %2").arg(path, problem);
        return r;
    }
    return decodeEnvironment(file.bytes(), path);
}

QString checkEnvironmentImage(const EnvironmentImage& image) {
    if (QString why = sizeProblem(image.width, image.height); !why.isEmpty()) return why;
    if (image.texels.size() != size_t(image.width) * size_t(image.height))
        return QStringLiteral("%1 texels for %2×%3")
            .arg(image.texels.size())
            .arg(image.width)
            .arg(image.height);
    for (const glm::vec3& t : image.texels)
        for (int c = 0; c < 3; ++c) {
            if (!(std::isfinite(t[c]) && t[c] >= 0.0f))
                return QStringLiteral("a texel value %1 (not finite and >= 0)").arg(double(t[c]));
            if (t[c] > kMaxEnvironmentRadiance)
                return QStringLiteral("a texel value %1 (above the limit of %2)")
                    .arg(double(t[c]))
                    .arg(double(kMaxEnvironmentRadiance));
        }
    return {};
}

} // namespace lr
