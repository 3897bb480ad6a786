#include "exrdecode.h"

#include "exrio.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>
#include <ImfVersion.h>

#include <QHash>
#include <QSet>
#include <cstring>
#include <exception>
#include <map>
#include <new>

namespace lr {

namespace {

constexpr char kExrMagic[] = {0x76, 0x2f, 0x31, 0x01};

// R, G, B, A, X, Y, Z first, then the rest by name.
int channelRank(const QString& c) {
    static const QStringList first = {"R", "G", "B", "A", "X", "Y", "Z"};
    const qsizetype at = first.indexOf(c);
    return at < 0 ? int(first.size()) : int(at);
}

QString boxText(const Imath::Box2i& b) {
    return QStringLiteral("(%1, %2)-(%3, %4)").arg(b.min.x).arg(b.min.y).arg(b.max.x).arg(b.max.y);
}

// Where each channel of the file goes: its layer and its name there.
struct Grouped {
    QString layer, channel;
    std::string full;
};

// The header's checks before InputFile sizes anything by it: empty when it may be read.
QString headerProblem(int version, const Imf::Header& header, qint64 fileBytes, qint64 afterHeader) {
    if (Imf::isMultiPart(version))
        return QStringLiteral("it has several parts; only single-part files are read");
    if (Imf::isNonImage(version)) return QStringLiteral("it holds deep data, not flat pixels");
    const Imath::Box2i display = header.displayWindow(), data = header.dataWindow();
    const qint64 w = exrio::windowWidth(display), h = exrio::windowHeight(display);
    int channels = 0;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it, ++channels)
        if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
            return QStringLiteral(
                       "channel \"%1\" is subsampled (%2×%3); only full-resolution channels are read")
                .arg(QString::fromUtf8(it.name()))
                .arg(it.channel().xSampling)
                .arg(it.channel().ySampling);
    if (channels == 0) return QStringLiteral("it has no channels");
    if (QString why = exrSizeProblem(w, h, channels); !why.isEmpty()) return why;
    if (exrio::windowWidth(data) < 1 || exrio::windowHeight(data) < 1 || data.min.x < display.min.x ||
        data.min.y < display.min.y || data.max.x > display.max.x || data.max.y > display.max.y)
        return QStringLiteral("its data window %1 is not inside its display window %2")
            .arg(boxText(data), boxText(display));
    if (exrio::chunkCount(header) * 8 > fileBytes - afterHeader)
        return QStringLiteral("the header claims %1×%2 pixels but the file holds only %3 bytes")
            .arg(w)
            .arg(h)
            .arg(fileBytes);
    const qint64 decoded = w * h * channels * qint64(sizeof(float));
    if (decoded > maxExrDecodedBytes(fileBytes))
        return QStringLiteral(
                   "the header claims %1×%2 pixels of %3 channels (%4 MiB decoded) but the file holds "
                   "only %5 bytes (at most %6 bytes decoded per byte of file are accepted)")
            .arg(w)
            .arg(h)
            .arg(channels)
            .arg(decoded >> 20)
            .arg(fileBytes)
            .arg(kMaxExrExpansion);
    return {};
}

QString decode(QByteArrayView bytes, ExrFile* out) {
    if (bytes.size() < 4 || std::memcmp(bytes.data(), kExrMagic, 4) != 0)
        return QStringLiteral("not an OpenEXR file (unknown first bytes)");
    exrio::MemoryIStream stream(bytes);
    {
        Imf::Header first;
        const int version = exrio::readFirstHeader(stream, bytes, &first);
        if (QString why = headerProblem(version, first, bytes.size(), qint64(stream.tellg())); !why.isEmpty())
            return why;
        stream.seekg(0);
    }
    Imf::InputFile file(stream, exrio::threads());
    const Imf::Header& header = file.header();
    const Imath::Box2i display = header.displayWindow();
    const qint64 w = exrio::windowWidth(display), h = exrio::windowHeight(display);

    // Layers by name ("" first: std::map's order is QString's), channels grouped by their last dot.
    std::map<QString, std::vector<Grouped>> layers;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        const QString full = QString::fromUtf8(it.name());
        const qsizetype dot = full.lastIndexOf(QLatin1Char('.'));
        Grouped g;
        g.full = it.name();
        if (dot > 0 && dot < full.size() - 1) {
            g.layer = full.left(dot);
            g.channel = full.mid(dot + 1);
        } else {
            g.channel = full;
        }
        layers[g.layer].push_back(std::move(g));
    }
    ExrFile result;
    result.width = int(w);
    result.height = int(h);
    Imf::FrameBuffer frame;
    result.layers.reserve(layers.size());
    for (auto& [name, channels] : layers) {
        std::stable_sort(channels.begin(), channels.end(), [](const Grouped& a, const Grouped& b) {
            const int ra = channelRank(a.channel), rb = channelRank(b.channel);
            return ra != rb ? ra < rb : a.channel < b.channel;
        });
        ExrLayer& layer = result.layers.emplace_back();
        layer.name = name;
        for (const Grouped& g : channels) {
            if (layer.channels.contains(g.channel)) // names that are not UTF-8 can read alike
                return QStringLiteral("two channels of layer \"%1\" read as \"%2\"").arg(name, g.channel);
            layer.channels << g.channel;
        }
        const size_t n = size_t(layer.channels.size());
        layer.pixels.assign(size_t(w) * size_t(h) * n, 0.0f);
        for (size_t c = 0; c < n; ++c)
            frame.insert(channels[c].full,
                         Imf::Slice::Make(Imf::FLOAT, layer.pixels.data() + c, display.min, w, h,
                                          sizeof(float) * n, sizeof(float) * n * size_t(w)));
    }
    file.setFrameBuffer(frame);
    file.readPixels(header.dataWindow().min.y, header.dataWindow().max.y);
    for (auto it = header.begin(); it != header.end(); ++it)
        if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
            result.attributes.emplace_back(QString::fromUtf8(it.name()), QString::fromStdString(s->value()));
    *out = std::move(result);
    return {};
}

} // namespace

QString exrSizeProblem(qint64 width, qint64 height, int channels) {
    if (width <= 0 || height <= 0) return QStringLiteral("its size %1×%2 is empty").arg(width).arg(height);
    if (width > kMaxExrSide || height > kMaxExrSide)
        return QStringLiteral("%1×%2 pixels is larger than the limit of %3 on a side")
            .arg(width)
            .arg(height)
            .arg(kMaxExrSide);
    if (width * height > kMaxExrPixels)
        return QStringLiteral("%1×%2 pixels is more than the limit of %3 Mpx")
            .arg(width)
            .arg(height)
            .arg(kMaxExrPixels >> 20);
    if (channels > kMaxExrChannels)
        return QStringLiteral("%1 channels is more than the limit of %2").arg(channels).arg(kMaxExrChannels);
    if (width * height * channels * qint64(sizeof(float)) > kMaxExrDecodedBytes)
        return QStringLiteral("%1×%2 pixels of %3 channels is more than the limit of %4 GiB as float")
            .arg(width)
            .arg(height)
            .arg(channels)
            .arg(kMaxExrDecodedBytes >> 30);
    return {};
}

const ExrLayer* ExrFile::layer(const QString& name) const {
    const auto it =
        std::find_if(layers.begin(), layers.end(), [&](const ExrLayer& l) { return l.name == name; });
    return it == layers.end() ? nullptr : &*it;
}

std::optional<ExrFile> decodeExrLayers(const QByteArray& bytes, QString* error) {
    ExrFile file;
    QString why;
    try {
        why = decode(bytes, &file);
    } catch (const std::bad_alloc&) {
        why = QStringLiteral("out of memory decoding it");
    } catch (const std::exception& e) {
        why = QStringLiteral("truncated or corrupt OpenEXR (%1)").arg(QString::fromLocal8Bit(e.what()));
    } catch (...) {
        why = QStringLiteral("truncated or corrupt OpenEXR");
    }
    if (!why.isEmpty()) {
        *error = why;
        return std::nullopt;
    }
    return file;
}

std::optional<ExrFile> decodeExrLayersFile(const QString& path, QString* error) {
    exrio::UntrustedFile file;
    QString why = file.open(path, kMaxExrFileBytes);
    std::optional<ExrFile> decoded;
    if (why.isEmpty()) {
        const QByteArray bytes = QByteArray::fromRawData(file.bytes().data(), file.bytes().size());
        decoded = decodeExrLayers(bytes, &why);
    }
    if (!decoded) *error = QStringLiteral("could not read %1: %2").arg(path, why);
    return decoded;
}

} // namespace lr
