// Multi-layer OpenEXR from untrusted bytes (issue 37; model/exrdecode.h): truncated, garbage and corrupt
// files, headers claiming more than the limits or than the file holds, windows, parts, deep data and
// subsampled channels give an error, never a crash; crops, other origins and uint channels are read; the
// worker reply's encoding and the parent's checks of it; files that are not regular.
#include "exrfixtures.h"
#include "model/importbudget.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>

#include <QDir>
#include <QTemporaryDir>
#include <cstring>
#include <random>
#include <sys/stat.h>

using namespace lr;
using namespace exrtest;

namespace {

QByteArray aovFile() {
    return encodeOrFail(19, 70, aovLayers(19, 70), ExrPixel::Half);
}

// Rewrites a box2i attribute (dataWindow, displayWindow) in place.
QByteArray withBox(QByteArray exr, const char* attribute, int x0, int y0, int x1, int y1) {
    const QByteArray key = QByteArray(attribute) + QByteArray("\0box2i\0", 7);
    const qsizetype at = exr.indexOf(key);
    if (at < 0) qFatal("no %s", attribute);
    const qint32 box[4] = {x0, y0, x1, y1};
    exr.replace(at + key.size() + 4, 16, QByteArray(reinterpret_cast<const char*>(box), 16));
    return exr;
}

QByteArray withSize(const QByteArray& exr, int w, int h) {
    return withBox(withBox(exr, "dataWindow", 0, 0, w - 1, h - 1), "displayWindow", 0, 0, w - 1, h - 1);
}

QByteArray withCompression(QByteArray exr, char compression) {
    const QByteArray key("compression\0compression\0", 24);
    const qsizetype at = exr.indexOf(key);
    if (at < 0) qFatal("no compression");
    exr[at + key.size() + 4] = compression;
    return exr;
}

void expectRefused(const QByteArray& bytes, const QString& part) {
    QString error;
    const std::optional<ExrFile> file = decodeExrLayers(bytes, &error);
    QVERIFY2(!file, qPrintable(part));
    QVERIFY2(!error.isEmpty() && error.contains(part), qPrintable(error + " lacks " + part));
}

// A file written with OpenEXR itself, for what exrencode.h does not write.
QByteArray writeWithOpenExr(const Imf::Header& header,
                            const std::vector<std::pair<std::string, Imf::PixelType>>& channels,
                            const QString& path) {
    Imf::Header h = header;
    const Imath::Box2i dw = h.dataWindow();
    const int w = dw.max.x - dw.min.x + 1, rows = dw.max.y - dw.min.y + 1;
    std::vector<std::vector<float>> floats;
    std::vector<std::vector<unsigned>> uints;
    Imf::FrameBuffer fb;
    for (const auto& [name, type] : channels) {
        h.channels().insert(name, Imf::Channel(type));
        if (type == Imf::UINT) {
            auto& v = uints.emplace_back(size_t(w) * size_t(rows));
            for (size_t i = 0; i < v.size(); ++i)
                v[i] = unsigned(i * 7 + 1);
            fb.insert(name, Imf::Slice::Make(Imf::UINT, v.data(), dw));
        } else {
            auto& v = floats.emplace_back(size_t(w) * size_t(rows));
            for (size_t i = 0; i < v.size(); ++i)
                v[i] = 0.25f * float(i + 1);
            fb.insert(name, Imf::Slice::Make(Imf::FLOAT, v.data(), dw));
        }
    }
    {
        Imf::OutputFile out(path.toStdString().c_str(), h);
        out.setFrameBuffer(fb);
        out.writePixels(rows);
    }
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read back %s", qPrintable(path));
    return f.readAll();
}

} // namespace

class TestExrLayersHostile : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

  private slots:
    void truncated() {
        const QByteArray bytes = aovFile();
        for (qsizetype keep = 0; keep < bytes.size(); keep += std::max<qsizetype>(1, bytes.size() / 97)) {
            QString error;
            QVERIFY2(!decodeExrLayers(bytes.left(keep), &error), qPrintable(QString::number(keep)));
            QVERIFY(!error.isEmpty());
        }
        expectRefused(bytes.chopped(1), "truncated or corrupt OpenEXR");
    }
    void garbage() {
        expectRefused(QByteArray(), "not an OpenEXR file");
        expectRefused(QByteArray(4096, '\x5a'), "not an OpenEXR file");
        std::mt19937 random(37);
        const QByteArray valid = aovFile();
        for (int round = 0; round < 200; ++round) {
            QByteArray bytes = valid.left(8); // magic and version, then noise
            bytes.resize(8 + qsizetype(random() % 4096));
            for (qsizetype i = 8; i < bytes.size(); ++i)
                bytes[i] = char(random());
            QString error;
            QVERIFY(!decodeExrLayers(bytes, &error) && !error.isEmpty());
            // Noise over a valid file's bytes: an error or a sane image, never a crash.
            QByteArray noisy = valid;
            for (int k = 0; k < 8; ++k)
                noisy[qsizetype(random() % quint32(noisy.size()))] = char(random());
            error.clear();
            const std::optional<ExrFile> file = decodeExrLayers(noisy, &error);
            QVERIFY(file ? file->width == 19 && file->height == 70 && error.isEmpty() : !error.isEmpty());
        }
    }
    void oversizedHeaders() {
        const QByteArray bytes = aovFile();
        expectRefused(withSize(bytes, 40000, 10),
                      "40000×10 pixels is larger than the limit of 32768 on a side");
        expectRefused(withSize(bytes, 20000, 20000), "is more than the limit of 256 Mpx");
        // ZIPS: one row a chunk, each with an 8-byte offset: twice as many rows as the file has room for.
        const int rows = int(bytes.size() / 4);
        QVERIFY(rows <= kMaxExrSide);
        expectRefused(withCompression(withSize(bytes, 100, rows), char(2)),
                      QStringLiteral("the header claims 100×%1 pixels but the file holds only %2 bytes")
                          .arg(rows)
                          .arg(bytes.size()));
        // DWAB: 256 rows a chunk, so 16 chunk offsets suffice; 17 channels of 4096² decode to 1088 MiB.
        const QByteArray lying = withCompression(withSize(bytes, 4096, 4096), char(9));
        expectRefused(lying,
                      QStringLiteral("the header claims 4096×4096 pixels of 17 channels (1088 MiB decoded) "
                                     "but the file holds only %1 bytes (at most 4096 bytes decoded per "
                                     "byte of file are accepted)")
                          .arg(bytes.size()));
        expectRefused(withBox(bytes, "dataWindow", -1, 0, 18, 69),
                      "its data window (-1, 0)-(18, 69) is not inside");
        expectRefused(withBox(bytes, "dataWindow", 0, 0, 18, 70),
                      "is not inside its display window (0, 0)-(18, 69)");
        expectRefused(withBox(bytes, "displayWindow", 5, 0, 4, 69), "its size 0×70 is empty");
    }
    void partsDeepAndSubsampling() {
        QByteArray deep = aovFile();
        deep[5] = char(deep[5] | 0x08); // the version's NON_IMAGE flag
        expectRefused(deep, "deep data");

        Imf::Header a(4, 2), b(4, 2);
        a.setName("a");
        b.setName("b");
        a.setType(Imf::SCANLINEIMAGE);
        b.setType(Imf::SCANLINEIMAGE);
        a.channels().insert("R", Imf::Channel(Imf::FLOAT));
        b.channels().insert("R", Imf::Channel(Imf::FLOAT));
        const QString multi = m_dir.filePath("multi.exr");
        {
            const Imf::Header headers[2] = {a, b};
            Imf::MultiPartOutputFile out(multi.toStdString().c_str(), headers, 2);
            std::vector<float> pixels(8, 1.0f);
            for (int part = 0; part < 2; ++part) {
                Imf::OutputPart p(out, part);
                Imf::FrameBuffer fb;
                fb.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data()), 4, 16));
                p.setFrameBuffer(fb);
                p.writePixels(2);
            }
        }
        QFile f(multi);
        QVERIFY(f.open(QIODevice::ReadOnly));
        expectRefused(f.readAll(), "it has several parts");

        Imf::Header sub(4, 2);
        sub.channels().insert("BY", Imf::Channel(Imf::HALF, 2, 2));
        sub.channels().insert("Y", Imf::Channel(Imf::HALF));
        { // no pixels: the header is what is read
            Imf::OutputFile out(m_dir.filePath("sub.exr").toStdString().c_str(), sub);
        }
        QFile s(m_dir.filePath("sub.exr"));
        QVERIFY(s.open(QIODevice::ReadOnly));
        expectRefused(s.readAll(), "channel \"BY\" is subsampled (2×2)");

        std::vector<std::pair<std::string, Imf::PixelType>> wide;
        for (int i = 0; i < 300; ++i)
            wide.emplace_back("c" + std::to_string(i), Imf::FLOAT);
        expectRefused(writeWithOpenExr(Imf::Header(2, 2), wide, m_dir.filePath("wide.exr")),
                      "300 channels is more than the limit of 256");
        // OpenEXR writes no file without channels: an empty list (its terminating NUL alone) in place of one.
        QByteArray none = aovFile();
        const QByteArray key("channels\0chlist\0", 16);
        const qsizetype at = none.indexOf(key) + key.size();
        qint32 size = 0;
        std::memcpy(&size, none.constData() + at, 4);
        const qint32 one = 1;
        none.replace(at, 4 + size, QByteArray(reinterpret_cast<const char*>(&one), 4) + QByteArray(1, '\0'));
        expectRefused(none, "it has no channels");
    }
    // A data window inside the display window (a crop), at any origin: read into place, 0 around it.
    void cropsAndOrigins() {
        const Imath::Box2i display({-3, -2}, {4, 3}), data({-1, 0}, {2, 1});
        const QByteArray bytes =
            writeWithOpenExr(Imf::Header(display, data), {{"id", Imf::UINT}, {"key.R", Imf::FLOAT}},
                             m_dir.filePath("crop.exr"));
        QString error;
        const std::optional<ExrFile> file = decodeExrLayers(bytes, &error);
        QVERIFY2(file, qPrintable(error));
        QCOMPARE(file->width, 8);
        QCOMPARE(file->height, 6);
        const ExrLayer* id = file->layer("");
        const ExrLayer* key = file->layer("key");
        QVERIFY(id && key);
        QCOMPARE(id->channels, QStringList{"id"});
        int inside = 0;
        for (int y = display.min.y; y <= display.max.y; ++y)
            for (int x = display.min.x; x <= display.max.x; ++x) {
                const size_t at = size_t(y - display.min.y) * 8 + size_t(x - display.min.x);
                const bool in = data.intersects(Imath::V2i(x, y));
                const size_t i = size_t(y - data.min.y) * 4 + size_t(x - data.min.x); // in the data window
                QCOMPARE(id->pixels[at], in ? float(i * 7 + 1) : 0.0f);
                QCOMPARE(key->pixels[at], in ? 0.25f * float(i + 1) : 0.0f);
                inside += in;
            }
        QCOMPARE(inside, 8);
    }
    void reply() {
        QString error, why;
        const std::optional<ExrFile> file = decodeExrLayers(aovFile(), &error);
        QVERIFY2(file, qPrintable(error));
        const QByteArray reply = encodeExrLayersReply(*file);
        QCOMPARE(reply.left(exrLayersReplyHead(*file).size()), exrLayersReplyHead(*file));
        ExrFile back;
        QVERIFY2(decodeExrLayersReply(reply, &back, &why), qPrintable(why));
        QCOMPARE(back.width, file->width);
        QCOMPARE(back.height, file->height);
        QCOMPARE(back.attributes, file->attributes);
        QCOMPARE(back.layers.size(), file->layers.size());
        for (size_t l = 0; l < back.layers.size(); ++l) {
            QCOMPARE(back.layers[l].name, file->layers[l].name);
            QCOMPARE(back.layers[l].channels, file->layers[l].channels);
            QCOMPARE(back.layers[l].pixels, file->layers[l].pixels);
        }
        QVERIFY(reply.size() <= maxExrLayersReplyBytes(aovFile().size()));
        for (qsizetype keep = 0; keep < reply.size(); keep += std::max<qsizetype>(1, reply.size() / 211))
            QVERIFY2(!decodeExrLayersReply(reply.left(keep), &back, &why), qPrintable(QString::number(keep)));
        QVERIFY(!decodeExrLayersReply(reply + QByteArray(4, '\0'), &back, &why));
        QVERIFY2(why.contains("bytes of pixels"), qPrintable(why));
        const auto refusedWith = [&](ExrFile bad, const QString& part) {
            QString reason;
            ExrFile out;
            QVERIFY2(!decodeExrLayersReply(encodeExrLayersReply(bad), &out, &reason), qPrintable(part));
            QVERIFY2(reason.contains(part), qPrintable(reason + " lacks " + part));
        };
        ExrFile twice = *file;
        twice.layers[2].name = twice.layers[1].name;
        refusedWith(twice, "two layers named");
        ExrFile emptyChannel = *file;
        emptyChannel.layers[1].channels[0].clear();
        refusedWith(emptyChannel, "a channel named \"\"");
        ExrFile noLayers = *file;
        noLayers.layers.clear();
        refusedWith(noLayers, "0 layers");
        ExrFile huge = *file;
        huge.width = 40000;
        refusedWith(huge, "larger than the limit of 32768");
        ExrFile attribute = *file;
        attribute.attributes.push_back(attribute.attributes.front());
        refusedWith(attribute, "(empty or twice)");
    }
    // The worker's address space for a layers file holds the most the decoder accepts from a file of that
    // size, and the file mapped beside it (within the default 8 GiB hard limit).
    void workerBudgetCoversTheDecoder() {
        for (const qint64 fileBytes :
             {qint64(0), qint64(4096), qint64(1) << 20, qint64(300) << 20, kMaxExrFileBytes}) {
            const ImportBudget b = importBudget(BudgetKind::ExrLayers, fileBytes, 8ll << 30, 120'000);
            QVERIFY2(b.memoryBytes >= maxExrDecodedBytes(fileBytes) + fileBytes + (256 << 20),
                     qPrintable(QString::number(fileBytes)));
            QVERIFY(b.memoryBytes <= 8ll << 30);
        }
    }
    void notRegularFiles() {
        QString error;
        const QString absent = m_dir.filePath("absent.exr");
        QVERIFY(!decodeExrLayersFile(absent, &error));
        QCOMPARE(error, QStringLiteral("could not read %1: no such file").arg(absent));
        QVERIFY(!decodeExrLayersFile(m_dir.path(), &error));
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
        const QString fifo = m_dir.filePath("fifo.exr");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QVERIFY(!decodeExrLayersFile(fifo, &error)); // refused at once, not waited on
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
        const QString good = m_dir.filePath("good.exr");
        QFile f(good);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(aovFile());
        f.close();
        const std::optional<ExrFile> file = decodeExrLayersFile(good, &error);
        QVERIFY2(file, qPrintable(error));
        QCOMPARE(file->layers.size(), aovLayers(1, 1).size());
    }
};

QTEST_GUILESS_MAIN(TestExrLayersHostile)
#include "tst_exrlayershostile.moc"
