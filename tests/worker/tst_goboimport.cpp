// Gobo images through the import worker (issue 39, model/gobodecode.h decodeGoboImage): PNG levels come
// back linear with row 0 at the top, OpenEXR values clamped to [0, 1]; bad files (not an image, truncated,
// too large, missing, a folder) and a crashing worker give an error naming the file and the reason.
// Runs against LIGHTRIG_EXECUTABLE.
#include "core/colour.h"
#include "model/exrencode.h"
#include "model/gobodecode.h"
#include "model/importprotocol.h"
#include "model/isolatedimport.h"

#include <QBuffer>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;

namespace {

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

struct CrashMode {
    explicit CrashMode(const QByteArray& mode) { qputenv(importprotocol::kTestCrashVariable, mode); }
    ~CrashMode() { qunsetenv(importprotocol::kTestCrashVariable); }
};

} // namespace

class TestGoboImport : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE)); }
    void pngIsLinearTopRowFirst() {
        QTemporaryDir dir;
        QImage img(3, 2, QImage::Format_RGB888);
        img.setPixelColor(0, 0, QColor(255, 0, 0));
        img.setPixelColor(1, 0, QColor(128, 128, 128));
        img.setPixelColor(2, 0, QColor(0, 0, 0));
        img.setPixelColor(0, 1, QColor(0, 64, 255));
        img.setPixelColor(1, 1, QColor(255, 255, 255));
        img.setPixelColor(2, 1, QColor(10, 20, 30));
        const QString path = dir.filePath("g.png");
        QVERIFY(img.save(path));
        QString error;
        const auto g = decodeGoboImage(path, &error);
        QVERIFY2(g, qPrintable(error));
        QCOMPARE(g->width, 3);
        QCOMPARE(g->height, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) {
                const QColor c = img.pixelColor(x, y);
                const int levels[3] = {c.red(), c.green(), c.blue()};
                for (int k = 0; k < 3; ++k) {
                    const double want = colour::srgbToLinear(levels[k] / 255.0);
                    const double got = g->rgb[(size_t(y) * 3 + size_t(x)) * 3 + size_t(k)];
                    QVERIFY2(std::abs(got - want) < 1e-6,
                             qPrintable(QStringLiteral("(%1, %2)[%3]: %4, want %5")
                                            .arg(x)
                                            .arg(y)
                                            .arg(k)
                                            .arg(got)
                                            .arg(want)));
                }
            }
    }
    // The largest side accepted decodes within the worker's limits, from a small file (a checkerboard).
    void largestImageDecodes() {
        QTemporaryDir dir;
        QImage img(kMaxGoboSide, kMaxGoboSide, QImage::Format_Grayscale8);
        for (int y = 0; y < img.height(); ++y) {
            uchar* row = img.scanLine(y);
            for (int x = 0; x < img.width(); ++x)
                row[x] = ((x / 512 + y / 512) % 2) ? 255 : 0;
        }
        const QString path = dir.filePath("big.png");
        QVERIFY(img.save(path));
        QString error;
        const auto g = decodeGoboImage(path, &error);
        QVERIFY2(g, qPrintable(error));
        QCOMPARE(g->width, kMaxGoboSide);
        QCOMPARE(g->rgb[0], 0.0f);
        QCOMPARE(g->rgb[3 * 512], 1.0f);
    }
    void exrClampedToOne() {
        QTemporaryDir dir;
        const float rgba[2 * 4] = {0.25f, 0.5f, 4.0f, 1.0f, 0.0f, 1.0f, 0.75f, 1.0f};
        const QString path = dir.filePath("g.exr");
        QString why;
        writeFile(path, encodeExrRgba(2, 1, rgba, {}, &why));
        QVERIFY2(why.isEmpty(), qPrintable(why));
        QString error;
        const auto g = decodeGoboImage(path, &error);
        QVERIFY2(g, qPrintable(error));
        QCOMPARE(g->width, 2);
        const std::vector<float> want{0.25f, 0.5f, 1.0f, 0.0f, 1.0f, 0.75f};
        QCOMPARE(g->rgb, want);
    }
    void badFiles_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("reason");
        QTest::newRow("text") << QByteArray("not an image at all") << QStringLiteral("not a PNG or OpenEXR");
        QImage img(16, 16, QImage::Format_RGB888);
        img.fill(Qt::white);
        QByteArray png;
        {
            QBuffer b(&png);
            b.open(QIODevice::WriteOnly);
            img.save(&b, "PNG");
        }
        QTest::newRow("truncated png") << png.left(png.size() / 2) << QStringLiteral("PNG");
        QImage wide(kMaxGoboSide + 1, 1, QImage::Format_Grayscale8);
        wide.fill(0);
        QByteArray widePng;
        {
            QBuffer b(&widePng);
            b.open(QIODevice::WriteOnly);
            wide.save(&b, "PNG");
        }
        QTest::newRow("too wide") << widePng << QStringLiteral("larger than the limit");
        QTest::newRow("truncated exr")
            << QByteArray("\x76\x2f\x31\x01\x02\x00", 6) << QStringLiteral("OpenEXR");
    }
    void badFiles() {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        const QString path = dir.filePath("bad.png");
        writeFile(path, bytes);
        QString error;
        QVERIFY(!decodeGoboImage(path, &error));
        QVERIFY2(error.startsWith(path + QStringLiteral(": ")), qPrintable(error));
        QVERIFY2(error.contains(reason), qPrintable(error));
    }
    void missingAndFolder() {
        QTemporaryDir dir;
        QString error;
        QVERIFY(!decodeGoboImage(dir.filePath("none.png"), &error));
        QVERIFY2(error.contains(QStringLiteral("none.png: no such file")), qPrintable(error));
        QVERIFY(!decodeGoboImage(dir.path(), &error));
        QVERIFY2(error.contains(QStringLiteral("not a regular file")), qPrintable(error));
    }
    void workerCrashIsAnError() {
        QTemporaryDir dir;
        const QString path = dir.filePath("g.png");
        QImage img(2, 2, QImage::Format_RGB888);
        img.fill(Qt::white);
        QVERIFY(img.save(path));
        const CrashMode crash("segv");
        QString error;
        QVERIFY(!decodeGoboImage(path, &error));
        QVERIFY2(error.startsWith(path) && error.contains(QStringLiteral("crashed")), qPrintable(error));
    }
    void replyWithNaNIsRefused() {
        QTemporaryDir dir;
        const QString path = dir.filePath("g.png");
        QImage img(2, 2, QImage::Format_RGB888);
        img.fill(Qt::white);
        QVERIFY(img.save(path));
        const CrashMode crash("env-nan");
        QString error;
        QVERIFY(!decodeGoboImage(path, &error));
        QVERIFY2(error.contains(QStringLiteral("malformed reply")), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestGoboImport)
#include "tst_goboimport.moc"
