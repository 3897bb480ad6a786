#include "exrencode.h"

#include "exrdecode.h"
#include "exrio.h"

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include <QSet>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>

namespace lr {

namespace {

// OpenEXR's output stream into a QByteArray (it seeks back to write the line offsets).
class MemoryOStream : public Imf::OStream {
  public:
    explicit MemoryOStream(QByteArray* bytes) : Imf::OStream("memory"), m_bytes(bytes) {}
    void write(const char c[], int n) override {
        const qint64 end = m_position + n;
        if (end > m_bytes->size()) m_bytes->resize(end);
        std::memcpy(m_bytes->data() + m_position, c, size_t(n));
        m_position = end;
    }
    uint64_t tellp() override { return uint64_t(m_position); }
    void seekp(uint64_t pos) override { m_position = qint64(pos); }

  private:
    QByteArray* m_bytes;
    qint64 m_position = 0;
};

// A layer as the one writer takes it: the pixels are the caller's, not copied.
struct LayerView {
    QString name;
    QStringList channels;
    const float* pixels = nullptr;
    size_t count = 0; // floats at `pixels`
};

// Names OpenEXR writes itself or gives a meaning and a type other than string: a string attribute of that
// name would be refused by OpenEXR or misread by every other reader.
const QSet<QString>& reservedAttributes() {
    static const QSet<QString> names = {"channels",
                                        "compression",
                                        "dataWindow",
                                        "displayWindow",
                                        "lineOrder",
                                        "pixelAspectRatio",
                                        "screenWindowCenter",
                                        "screenWindowWidth",
                                        "tiles",
                                        "type",
                                        "name",
                                        "version",
                                        "chunkCount",
                                        "maxSamplesPerPixel",
                                        "view",
                                        "multiView",
                                        "chromaticities",
                                        "whiteLuminance",
                                        "adoptedNeutral",
                                        "xDensity",
                                        "utcOffset",
                                        "longitude",
                                        "latitude",
                                        "altitude",
                                        "focus",
                                        "expTime",
                                        "aperture",
                                        "isoSpeed",
                                        "envmap",
                                        "keyCode",
                                        "timeCode",
                                        "framesPerSecond",
                                        "worldToCamera",
                                        "worldToNDC",
                                        "deepImageState",
                                        "originalDataWindow",
                                        "dwaCompressionLevel",
                                        "idManifest"};
    return names;
}

bool asciiNameCharacter(QChar c, bool dash) {
    const char16_t u = c.unicode();
    return (u >= 'A' && u <= 'Z') || (u >= 'a' && u <= 'z') || (u >= '0' && u <= '9') || u == '_' ||
           (dash && u == '-');
}

QString layerLabel(const QString& name) {
    return name.isEmpty() ? QStringLiteral("the unnamed layer") : QStringLiteral("layer \"%1\"").arg(name);
}

QString channelNameProblem(const QString& name) {
    if (name.isEmpty()) return QStringLiteral("a channel name is empty");
    if (name.size() > kMaxExrChannelName)
        return QStringLiteral("channel \"%1\" is longer than %2 characters")
            .arg(name)
            .arg(kMaxExrChannelName);
    for (QChar c : name)
        if (!asciiNameCharacter(c, false))
            return QStringLiteral("channel \"%1\" has \"%2\" (a channel name is letters, digits and \"_\")")
                .arg(name, c);
    return {};
}

// The size, the names and the pixel counts; empty when the writer may go ahead.
QString layersProblem(int width, int height, const std::vector<LayerView>& layers) {
    if (width <= 0 || height <= 0 || layers.empty()) return QStringLiteral("there is no image to write");
    if (QString why = exrSizeProblem(width, height, 0); !why.isEmpty()) return why;
    QSet<QString> names;
    qint64 channels = 0;
    for (const LayerView& layer : layers) {
        const QString label = layerLabel(layer.name);
        if (QString why = exrLayerNameProblem(layer.name); !why.isEmpty())
            return QStringLiteral("layer \"%1\": %2").arg(layer.name, why);
        if (names.contains(layer.name))
            return layer.name.isEmpty() ? QStringLiteral("two layers are unnamed")
                                        : QStringLiteral("two layers are called \"%1\"").arg(layer.name);
        names.insert(layer.name);
        if (layer.channels.isEmpty()) return QStringLiteral("%1 has no channel").arg(label);
        QSet<QString> seen;
        for (const QString& c : layer.channels) {
            if (QString why = channelNameProblem(c); !why.isEmpty())
                return label + QStringLiteral(": ") + why;
            if (seen.contains(c)) return QStringLiteral("%1 has channel \"%2\" twice").arg(label, c);
            seen.insert(c);
        }
        const qint64 expected = qint64(width) * height * layer.channels.size();
        if (!layer.pixels || qint64(layer.count) != expected)
            return QStringLiteral("%1 has %2 values for %3×%4 pixels of %5 channels (%6 expected)")
                .arg(label)
                .arg(layer.pixels ? qint64(layer.count) : 0)
                .arg(width)
                .arg(height)
                .arg(layer.channels.size())
                .arg(expected);
        channels += layer.channels.size();
    }
    if (channels > kMaxExrChannels)
        return QStringLiteral("%1 channels in all is more than the limit of %2")
            .arg(channels)
            .arg(kMaxExrChannels);
    return exrSizeProblem(width, height, int(channels));
}

QString attributesProblem(const std::vector<std::pair<QString, QString>>& attributes) {
    QSet<QString> seen;
    for (const auto& [name, value] : attributes) {
        Q_UNUSED(value);
        if (name.isEmpty()) return QStringLiteral("an attribute name is empty");
        if (name.toUtf8().size() > 255)
            return QStringLiteral("attribute \"%1…\" has a name longer than 255 bytes").arg(name.left(32));
        for (QChar c : name)
            if (c.category() == QChar::Other_Control)
                return QStringLiteral("attribute \"%1\" has a control character in its name").arg(name);
        if (reservedAttributes().contains(name))
            return QStringLiteral("attribute \"%1\" is one OpenEXR defines itself").arg(name);
        if (seen.contains(name)) return QStringLiteral("attribute \"%1\" appears twice").arg(name);
        seen.insert(name);
    }
    return {};
}

// Depth: a "Z" that is not a vector's third component.
bool isDepth(const QStringList& channels, const QString& channel) {
    return channel == QLatin1String("Z") && !channels.contains(QLatin1String("X")) &&
           !channels.contains(QLatin1String("Y"));
}

Imath::half toHalf(float v) {
    constexpr float kHalfMax = 65504.0f;
    return Imath::half(std::isfinite(v) ? std::clamp(v, -kHalfMax, kHalfMax) : v);
}

// The one writer. Rows go out in strips, so that half channels need a strip's worth of converted values,
// not a copy of the image; float channels are read from the caller's pixels where they are.
QByteArray writeExr(int width, int height, const std::vector<LayerView>& layers,
                    const std::vector<std::pair<QString, QString>>& attributes, ExrPixel pixel,
                    QString* error) {
    QString why = layersProblem(width, height, layers);
    if (why.isEmpty()) why = attributesProblem(attributes);
    if (!why.isEmpty()) {
        *error = why;
        return {};
    }
    QByteArray bytes;
    try {
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        std::vector<std::vector<Imf::PixelType>> types(layers.size());
        for (size_t l = 0; l < layers.size(); ++l)
            for (const QString& c : layers[l].channels) {
                const Imf::PixelType type =
                    pixel == ExrPixel::Float || isDepth(layers[l].channels, c) ? Imf::FLOAT : Imf::HALF;
                types[l].push_back(type);
                const QString full = layers[l].name.isEmpty() ? c : layers[l].name + QLatin1Char('.') + c;
                header.channels().insert(full.toStdString(), Imf::Channel(type));
            }
        for (const auto& [name, value] : attributes)
            header.insert(name.toStdString(), Imf::StringAttribute(value.toStdString()));
        MemoryOStream stream(&bytes);
        Imf::OutputFile file(stream, header, exrio::threads());
        const int stripRows = 32 * std::max(1, exrio::threads()); // 2 ZIP blocks of 16 rows a thread
        std::vector<std::vector<Imath::half>> halves(layers.size());
        for (int y0 = 0; y0 < height; y0 += stripRows) {
            const int rows = std::min(stripRows, height - y0);
            Imf::FrameBuffer frame;
            for (size_t l = 0; l < layers.size(); ++l) {
                const LayerView& layer = layers[l];
                const size_t n = size_t(layer.channels.size());
                const bool anyHalf = std::count(types[l].begin(), types[l].end(), Imf::HALF) > 0;
                const float* strip = layer.pixels + size_t(y0) * size_t(width) * n;
                if (anyHalf) {
                    std::vector<Imath::half>& h = halves[l];
                    h.resize(size_t(rows) * size_t(width) * n);
                    std::transform(strip, strip + h.size(), h.begin(), toHalf);
                }
                for (size_t c = 0; c < n; ++c) {
                    const QString& name = layer.channels[qsizetype(c)];
                    const QString full = layer.name.isEmpty() ? name : layer.name + QLatin1Char('.') + name;
                    const bool isFloat = types[l][c] == Imf::FLOAT;
                    const size_t size = isFloat ? sizeof(float) : sizeof(Imath::half);
                    const char* base = isFloat ? reinterpret_cast<const char*>(strip + c)
                                               : reinterpret_cast<const char*>(halves[l].data() + c);
                    frame.insert(full.toStdString(),
                                 Imf::Slice::Make(types[l][c], base, Imath::V2i(0, y0), width, rows, size * n,
                                                  size * n * size_t(width)));
                }
            }
            file.setFrameBuffer(frame);
            file.writePixels(rows);
        }
    } catch (const std::exception& e) {
        *error = QStringLiteral("OpenEXR: %1").arg(QString::fromLocal8Bit(e.what()));
        return {};
    }
    return bytes;
}

} // namespace

QByteArray encodeExrLayers(int width, int height, const std::vector<ExrLayer>& layers,
                           const std::vector<std::pair<QString, QString>>& attributes, ExrPixel pixel,
                           QString* error) {
    std::vector<LayerView> views;
    views.reserve(layers.size());
    for (const ExrLayer& l : layers)
        views.push_back({l.name, l.channels, l.pixels.empty() ? nullptr : l.pixels.data(), l.pixels.size()});
    return writeExr(width, height, views, attributes, pixel, error);
}

QByteArray encodeExrRgba(int width, int height, const float* rgba,
                         const std::vector<std::pair<QString, QString>>& attributes, QString* error) {
    if (width <= 0 || height <= 0 || !rgba) {
        *error = QStringLiteral("there is no image to write");
        return {};
    }
    const LayerView view{QString(), {"R", "G", "B", "A"}, rgba, size_t(width) * size_t(height) * 4};
    return writeExr(width, height, {view}, attributes, ExrPixel::Float, error);
}

QString exrLayerNameProblem(const QString& name) {
    if (name.size() > kMaxExrLayerName)
        return QStringLiteral("longer than %1 characters").arg(kMaxExrLayerName);
    for (QChar c : name)
        if (!asciiNameCharacter(c, true))
            return QStringLiteral("\"%1\" is not allowed (a layer name is letters A-Z a-z, digits, \"_\" and "
                                  "\"-\")")
                .arg(c);
    return {};
}

QString exrLayerName(const QString& anyName) {
    const QString decomposed = anyName.normalized(QString::NormalizationForm_KD);
    QString out;
    bool gap = false;
    for (QChar c : decomposed) {
        if (c.category() == QChar::Mark_NonSpacing) continue; // the accent of a decomposed letter
        if (!asciiNameCharacter(c, true)) {
            gap = true;
            continue;
        }
        if (gap && !out.isEmpty()) out += QLatin1Char('_');
        gap = false;
        out += c;
    }
    out.truncate(kMaxExrLayerName);
    return out.isEmpty() ? QStringLiteral("layer") : out;
}

QStringList uniqueExrLayerNames(const QStringList& anyNames, const QStringList& taken) {
    QSet<QString> used(taken.begin(), taken.end());
    QStringList out;
    for (const QString& name : anyNames) {
        const QString base = exrLayerName(name);
        QString candidate = base;
        for (int k = 2; used.contains(candidate); ++k) {
            const QString suffix = QStringLiteral("_%1").arg(k);
            candidate = base.left(kMaxExrLayerName - suffix.size()) + suffix;
        }
        used.insert(candidate);
        out << candidate;
    }
    return out;
}

} // namespace lr
