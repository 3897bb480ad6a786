#include "exrencode.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

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

} // namespace

QByteArray encodeExrRgba(int width, int height, const float* rgba,
                         const std::vector<std::pair<QString, QString>>& attributes, QString* error) {
    if (width <= 0 || height <= 0 || !rgba) {
        *error = QStringLiteral("there is no image to write");
        return {};
    }
    QByteArray bytes;
    try {
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* c : {"R", "G", "B", "A"})
            header.channels().insert(c, Imf::Channel(Imf::FLOAT));
        for (const auto& [name, value] : attributes)
            header.insert(name.toStdString(), Imf::StringAttribute(value.toStdString()));
        Imf::FrameBuffer frame;
        const size_t xStride = 4 * sizeof(float), yStride = xStride * size_t(width);
        const char* base = reinterpret_cast<const char*>(rgba);
        int offset = 0;
        for (const char* c : {"R", "G", "B", "A"})
            frame.insert(c, Imf::Slice(Imf::FLOAT, const_cast<char*>(base) + sizeof(float) * size_t(offset++),
                                       xStride, yStride));
        MemoryOStream stream(&bytes);
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(frame);
        file.writePixels(height);
    } catch (const std::exception& e) {
        *error = QStringLiteral("OpenEXR: %1").arg(QString::fromLocal8Bit(e.what()));
        return {};
    }
    return bytes;
}

} // namespace lr
