// Issue 11's fault injection, as a test: `lightrig render MODEL -o DIR/o.png` on a full file system used to
// exit 0, print "wrote ..." and leave a 0-byte o.png. Now it exits 1 with "no space left on device" and the
// old o.png is byte for byte what it was; images written in-process (render/imagefile.h: screenshots,
// thumbnails, charts) behave the same. The file system is a small tmpfs, mounted when root (else skipped).
#include "render/imagefile.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/tmpfs.h"

#include <QDir>
#include <QImage>
#include <QTest>

using namespace lr;

namespace {

QImage noise(int w, int h) { // incompressible enough that its PNG is far larger than what is left free
    QImage image(w, h, QImage::Format_RGB32);
    quint32 x = 12345;
    for (int y = 0; y < h; ++y)
        for (int i = 0; i < w; ++i)
            image.setPixel(i, y, (x = x * 1664525u + 1013904223u) >> 8);
    return image;
}

} // namespace

class TestFullDisk : public QObject {
    Q_OBJECT
  private slots:
    void imageWrite_keepsTheOldFile() {
        lrtest::SmallTmpfs fs(1024 * 1024);
        if (!fs.available()) QSKIP(qPrintable(fs.reason()));
        const QString path = fs.filePath(QStringLiteral("shot.png"));
        QCOMPARE(writeImageAtomically(noise(64, 64), path), QString());
        const QByteArray old = lrtest::readFile(path);
        QVERIFY(!old.isEmpty());
        QVERIFY(fs.fill(8 * 1024));
        QCOMPARE(writeImageAtomically(noise(256, 256), path, "PNG"),
                 QStringLiteral("no space left on device"));
        QCOMPARE(lrtest::readFile(path), old);
        QCOMPARE(writeImageAtomically(noise(256, 256), fs.filePath(QStringLiteral("new.jpg"))),
                 QStringLiteral("no space left on device"));
        QVERIFY(!QFile::exists(fs.filePath(QStringLiteral("new.jpg"))));
        QStringList left = QDir(fs.path()).entryList(QDir::Files | QDir::Hidden);
        left.sort();
        QCOMPARE(left, (QStringList{"FILLER", "shot.png"}));
    }

    void renderCli_exits1_andKeepsTheOldFile() {
        if (!lrtest::haveDisplay())
            QSKIP("lightrig render needs an X display with OpenGL: run under xvfb-run -a");
        lrtest::SmallTmpfs fs(1024 * 1024);
        if (!fs.available()) QSKIP(qPrintable(fs.reason()));
        const QString out = fs.filePath(QStringLiteral("o.png"));
        const QString model = QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/models/suzanne/Suzanne.gltf");
        const QStringList args = {QStringLiteral("render"), model,
                                  QStringLiteral("-o"),     out,
                                  QStringLiteral("--size"), QStringLiteral("320x240")};
        lrtest::CliRun r = lrtest::runLightrig(args);
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        const QByteArray old = lrtest::readFile(out);
        QVERIFY(old.size() > 8 * 1024); // the next render does not fit in what is left free

        QVERIFY(fs.fill(4 * 1024));
        r = lrtest::runLightrig(args);
        QVERIFY2(r.code == 1, qPrintable(r.show()));
        QVERIFY2(!r.out.contains(QLatin1String("wrote")), qPrintable(r.show()));
        QVERIFY2(r.err.contains(QStringLiteral("cannot write %1: no space left on device").arg(out)),
                 qPrintable(r.show()));
        QCOMPARE(lrtest::readFile(out), old);
        QStringList left = QDir(fs.path()).entryList(QDir::Files | QDir::Hidden);
        left.sort();
        QCOMPARE(left, (QStringList{"FILLER", "o.png"}));
    }
};

QTEST_GUILESS_MAIN(TestFullDisk)
#include "tst_fulldisk.moc"
