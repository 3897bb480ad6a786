#include "exrio.h"

#include <ImfThreading.h>
#include <ImfTileDescription.h>

#include <QThread>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <mutex>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace lr::exrio {

namespace {

int linesPerChunk(Imf::Compression c) {
    switch (c) {
    case Imf::NO_COMPRESSION:
    case Imf::RLE_COMPRESSION:
    case Imf::ZIPS_COMPRESSION:
        return 1;
    case Imf::ZIP_COMPRESSION:
    case Imf::PXR24_COMPRESSION:
        return 16;
    case Imf::PIZ_COMPRESSION:
    case Imf::B44_COMPRESSION:
    case Imf::B44A_COMPRESSION:
    case Imf::DWAA_COMPRESSION:
        return 32;
    default: // DWAB and any later one
        return 256;
    }
}

} // namespace

char* MemoryIStream::readMemoryMapped(int n) {
    char* p = const_cast<char*>(m_bytes.data()) + m_pos;
    advance(n);
    return p;
}

bool MemoryIStream::read(char c[], int n) {
    const qsizetype at = m_pos;
    advance(n);
    std::memcpy(c, m_bytes.data() + at, size_t(n));
    return m_pos < m_bytes.size();
}

void MemoryIStream::seekg(uint64_t pos) {
    if (pos > uint64_t(m_bytes.size())) throw std::runtime_error("seek past the end of the file");
    m_pos = qsizetype(pos);
}

void MemoryIStream::advance(int n) {
    if (n < 0 || n > m_bytes.size() - m_pos) throw std::runtime_error("unexpected end of file");
    m_pos += n;
}

int readFirstHeader(MemoryIStream& stream, QByteArrayView bytes, Imf::Header* header) {
    int version = 0;
    if (bytes.size() < 8) throw std::runtime_error("unexpected end of file");
    std::memcpy(&version, bytes.data() + 4, sizeof version);
    stream.seekg(8);
    header->readFrom(stream, version);
    return version;
}

qint64 windowWidth(const Imath::Box2i& box) {
    return qint64(box.max.x) - box.min.x + 1;
}

qint64 windowHeight(const Imath::Box2i& box) {
    return qint64(box.max.y) - box.min.y + 1;
}

qint64 chunkCount(const Imf::Header& header) {
    const qint64 w = windowWidth(header.dataWindow()), h = windowHeight(header.dataWindow());
    if (header.hasTileDescription()) {
        const Imf::TileDescription& t = header.tileDescription();
        const qint64 tx = std::max(1u, t.xSize), ty = std::max(1u, t.ySize);
        return (w + tx - 1) / tx * ((h + ty - 1) / ty);
    }
    const int lines = linesPerChunk(header.compression());
    return (h + lines - 1) / lines;
}

int threads() {
    static std::once_flag once;
    std::call_once(once, [] {
        if (Imf::globalThreadCount() == 0)
            Imf::setGlobalThreadCount(std::clamp(QThread::idealThreadCount(), 1, 8));
    });
    return Imf::globalThreadCount();
}

QString UntrustedFile::open(const QString& path, qint64 maxBytes) {
    const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return errno == ENOENT ? QStringLiteral("no such file")
                               : QString::fromLocal8Bit(std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        return QStringLiteral("not a regular file (a folder, FIFO, socket or device)");
    }
    if (!m_file.open(fd, QIODevice::ReadOnly, QFileDevice::AutoCloseHandle)) {
        ::close(fd);
        return m_file.errorString();
    }
    if (m_file.size() > maxBytes)
        return QStringLiteral("%1 bytes is larger than the limit of %2 GiB")
            .arg(m_file.size())
            .arg(maxBytes >> 30);
    if (const uchar* mapped = m_file.map(0, m_file.size())) {
        m_bytes = QByteArrayView(mapped, m_file.size());
    } else {
        m_read = m_file.readAll();
        m_bytes = m_read;
    }
    return {};
}

} // namespace lr::exrio
