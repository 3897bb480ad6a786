// Internal to the OpenEXR readers and writer (environmentdecode.cpp, exrdecode.cpp, exrencode.cpp): an
// input stream over bytes in memory, the first header read alone (before OpenEXR sizes its tables by it),
// an untrusted file opened without blocking and mapped, and OpenEXR's thread pool.
#pragma once

#include <ImfHeader.h>
#include <ImfIO.h>

#include <QByteArray>
#include <QByteArrayView>
#include <QFile>
#include <QString>

namespace lr::exrio {

// OpenEXR reads through this; reading or seeking past the end throws (OpenEXR catches nothing of ours:
// the decoders turn every exception into an error).
class MemoryIStream : public Imf::IStream {
  public:
    explicit MemoryIStream(QByteArrayView bytes) : Imf::IStream("memory"), m_bytes(bytes) {}
    bool isMemoryMapped() const override { return true; }
    char* readMemoryMapped(int n) override;
    bool read(char c[], int n) override;
    uint64_t tellg() override { return uint64_t(m_pos); }
    void seekg(uint64_t pos) override;

  private:
    void advance(int n);
    QByteArrayView m_bytes;
    qsizetype m_pos = 0;
};

// The file's version field and its first (or only) part's header; throws on a short or corrupt header.
// The stream is left after that header.
int readFirstHeader(MemoryIStream& stream, QByteArrayView bytes, Imf::Header* header);

// The data window's width and height, as 64-bit (a corrupt box may be negative or huge).
qint64 windowWidth(const Imath::Box2i& box);
qint64 windowHeight(const Imath::Box2i& box);

// The chunks (a tile, or 1 to 256 scanlines by compression) of a part with this header: each has an 8-byte
// offset in the table after the header, so a header whose table does not fit in the file is lying.
qint64 chunkCount(const Imf::Header& header);

// The threads OpenEXR compresses and decompresses blocks on (its global pool, started here once with up to
// 8 threads when nobody started it): pass to InputFile and OutputFile.
int threads();

// A file from the user, opened without blocking (a FIFO with no writer would wait) and checked to be a
// regular file before a byte is read (/dev/zero was once read until the worker's memory ran out), then
// mapped (or read when it cannot be).
class UntrustedFile {
  public:
    // Empty when open, else why not: "no such file", "not a regular file (...)", "N bytes is larger
    // than the limit of M GiB", the system's reason.
    QString open(const QString& path, qint64 maxBytes);
    QByteArrayView bytes() const { return m_bytes; }

  private:
    QFile m_file;
    QByteArray m_read;
    QByteArrayView m_bytes;
};

} // namespace lr::exrio
