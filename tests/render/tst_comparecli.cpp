// `lightrig compare MODEL A.json B.json` as the user runs it (issue 17, part 4; QProcess on the built
// executable, tiny images): identical rigs give an infinite PSNR and a black difference image; different rigs
// a finite PSNR whose printed figures are those of the -a and -b images it wrote, a difference image that is
// not black and a side-by-side image of the two; a bad rig fails with exit 1 naming which rig, its file and
// field, and writes nothing; usage errors exit 2.
#include "core/imagecompare.h"
#include "glfixture.h"
#include "support/cli.h"
#include "support/files.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

namespace {

using Run = lrtest::CliRun;

QString suzanne() {
    return QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/models/suzanne/Suzanne.gltf");
}

// A rig of one white directional light from the front-left, of this intensity.
QByteArray rigJson(double intensity) {
    return QStringLiteral(R"({"format": "lightrig", "version": 1, "lights": [
  {"name": "Key", "type": "directional", "color": [1, 1, 1], "intensity": %1, "direction": [0.4, -0.5, -1]}]})")
        .arg(intensity)
        .toUtf8();
}

bool allBlack(const QImage& image) {
    const QImage i = image.convertToFormat(QImage::Format_RGBA8888);
    for (int y = 0; y < i.height(); ++y)
        for (int x = 0; x < i.width(); ++x)
            if (i.pixel(x, y) != qRgba(0, 0, 0, 255)) return false;
    return true;
}

} // namespace

class TestCompareCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QProcessEnvironment m_env = QProcessEnvironment::systemEnvironment();

    QString path(const QString& name) const { return m_dir.filePath(name); }
    Run compare(const QStringList& args, const QProcessEnvironment* env = nullptr) {
        return lrtest::runLightrig(QStringList{QStringLiteral("compare")} + args, env ? env : &m_env);
    }
    void write(const QString& name, const QByteArray& data) {
        QFile f(path(name));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(data);
    }

  private slots:
    void initTestCase() {
        QVERIFY2(QFile::exists(QStringLiteral(LIGHTRIG_EXECUTABLE)), LIGHTRIG_EXECUTABLE);
        QVERIFY(m_dir.isValid());
        QDir(m_dir.path()).mkdir(QStringLiteral("xdg"));
        QFile::setPermissions(path(QStringLiteral("xdg")),
                              QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        m_env.insert(QStringLiteral("XDG_RUNTIME_DIR"), path(QStringLiteral("xdg")));
        write(QStringLiteral("a.json"), rigJson(1.0));
        write(QStringLiteral("b.json"), rigJson(2.5));
    }

    void usageErrorsExit2_data() {
        QTest::addColumn<QStringList>("args");
        const QString m = suzanne(), a = path(QStringLiteral("a.json"));
        QTest::newRow("nothing") << QStringList{};
        QTest::newRow("one rig") << QStringList{m, a};
        QTest::newRow("four arguments") << QStringList{m, a, a, a};
        QTest::newRow("--rig") << QStringList{m, a, a, QStringLiteral("--rig"), a};
        QTest::newRow("amplify 0") << QStringList{m, a, a, QStringLiteral("--amplify"), QStringLiteral("0")};
        QTest::newRow("diff not an image")
            << QStringList{m, a, a, QStringLiteral("-o"), path(QStringLiteral("d.txt"))};
        QTest::newRow("bad size") << QStringList{m, a, a, QStringLiteral("--size"), QStringLiteral("0x9")};
    }
    void usageErrorsExit2() {
        QFETCH(QStringList, args);
        const Run r = compare(args);
        QVERIFY2(r.code == 2, qPrintable(r.show()));
        QVERIFY2(r.err.contains(QLatin1String("Usage: lightrig compare MODEL A.json B.json")),
                 qPrintable(r.show()));
        QVERIFY(!QFile::exists(path(QStringLiteral("d.txt"))));
    }

    void identicalRigs_infinitePsnrAndABlackDifference() {
        LR_REQUIRE_DISPLAY();
        const QString diff = path(QStringLiteral("same.png"));
        const Run r =
            compare({suzanne(), path(QStringLiteral("a.json")), path(QStringLiteral("a.json")),
                     QStringLiteral("-o"), diff, QStringLiteral("--size"), QStringLiteral("48x36")});
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        QVERIFY2(
            r.lines().contains(QStringLiteral(
                "PSNR inf dB, mean 0.00 levels, max 0 levels, 0.0 % of pixels differ by more than 1 level")),
            qPrintable(r.show()));
        const QImage image(diff);
        QCOMPARE(image.size(), QSize(48, 36));
        QVERIFY(allBlack(image));
    }

    void differentRigs_finitePsnrOfTheImagesItWrote() {
        LR_REQUIRE_DISPLAY();
        const QString diff = path(QStringLiteral("diff.png")), a = path(QStringLiteral("A.png")),
                      b = path(QStringLiteral("B.png")), both = path(QStringLiteral("ab.png"));
        const Run r = compare({suzanne(), path(QStringLiteral("a.json")), path(QStringLiteral("b.json")),
                               QStringLiteral("-o"), diff, QStringLiteral("-a"), a, QStringLiteral("-b"), b,
                               QStringLiteral("--side-by-side"), both, QStringLiteral("--size"),
                               QStringLiteral("48x36"), QStringLiteral("--view"), QStringLiteral("front")});
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        static const QRegularExpression re(QStringLiteral(
            "^PSNR ([0-9.]+) dB, mean ([0-9.]+) levels, max ([0-9]+) levels, ([0-9.]+) % of pixels differ"));
        QRegularExpressionMatch m;
        for (const QString& line : r.lines())
            if ((m = re.match(line)).hasMatch()) break;
        QVERIFY2(m.hasMatch(), qPrintable(r.show()));
        const double psnr = m.captured(1).toDouble(), mean = m.captured(2).toDouble();
        QVERIFY2(psnr > 5.0 && psnr < 60.0, qPrintable(r.show()));
        QVERIFY(mean > 0.0);
        const double share = m.captured(4).toDouble();
        QVERIFY2(share > 0.0 && share < 100.0, qPrintable(r.show())); // the model, not the background
        // The printed figures are those of the two images it wrote.
        const QImage ia = QImage(a).convertToFormat(QImage::Format_RGBA8888);
        const QImage ib = QImage(b).convertToFormat(QImage::Format_RGBA8888);
        QCOMPARE(ia.size(), QSize(48, 36));
        QCOMPARE(ib.size(), QSize(48, 36));
        const lr::ErrorFigures f = lr::compareSrgb8(ia.constBits(), ib.constBits(), 48 * 36);
        QCOMPARE(QString::number(f.meanLevels, 'f', 2), m.captured(2));
        QCOMPARE(f.maxLevels, m.captured(3).toInt());
        const QImage d(diff);
        QCOMPARE(d.size(), QSize(48, 36));
        QVERIFY(!allBlack(d));
        // Black where A and B agree (the background).
        QCOMPARE(d.pixel(0, 0), qRgba(0, 0, 0, 255));
        const QImage s = QImage(both).convertToFormat(QImage::Format_RGBA8888);
        QCOMPARE(s.size(), QSize(96, 36));
        QCOMPARE(s.copy(0, 0, 48, 36), ia);
        QCOMPARE(s.copy(48, 0, 48, 36), ib);
    }

    // Issue 41: exit 1 means nothing was written. The side-by-side image's name leaves no room for the
    // temporary beside it (NAME_MAX), so its write fails after the other two were written: they get their
    // previous bytes back.
    void failedWrite_leavesEveryOutputAsItWas() {
        LR_REQUIRE_DISPLAY();
        const QString diff = path(QStringLiteral("kept-diff.png")), a = path(QStringLiteral("kept-a.png"));
        const QString tooLong = path(QString(240, QLatin1Char('x')) + QStringLiteral(".png"));
        write(QStringLiteral("kept-diff.png"), "previous diff");
        write(QStringLiteral("kept-a.png"), "previous a");
        const Run r =
            compare({suzanne(), path(QStringLiteral("a.json")), path(QStringLiteral("b.json")),
                     QStringLiteral("-o"), diff, QStringLiteral("-a"), a, QStringLiteral("--side-by-side"),
                     tooLong, QStringLiteral("--size"), QStringLiteral("32x24")});
        QVERIFY2(r.code == 1, qPrintable(r.show()));
        QVERIFY2(r.err.contains(QStringLiteral("cannot write ") + tooLong), qPrintable(r.show()));
        QCOMPARE(lrtest::readFile(diff), QByteArray("previous diff"));
        QCOMPARE(lrtest::readFile(a), QByteArray("previous a"));
        QVERIFY(!QFile::exists(tooLong));
        QCOMPARE(QDir(m_dir.path()).entryList({QStringLiteral("*.tmp")}, QDir::Files), QStringList());
    }

    // Issue 41: two outputs that are one file (another spelling), or an output that is an input, are
    // refused before anything is written.
    void outputThatIsAnInputOrAnotherOutput_isRefused() {
        const QString a = path(QStringLiteral("one.png"));
        write(QStringLiteral("one.png"), "previous");
        Run r = compare({suzanne(), path(QStringLiteral("a.json")), path(QStringLiteral("b.json")),
                         QStringLiteral("-a"), a, QStringLiteral("-b"),
                         m_dir.path() + QStringLiteral("/./one.png"), QStringLiteral("--size"),
                         QStringLiteral("32x24")});
        QVERIFY2(r.code == 1 && r.err.contains(QLatin1String("it is also the --image-a image")),
                 qPrintable(r.show()));
        QCOMPARE(lrtest::readFile(a), QByteArray("previous"));
        QVERIFY(QFile::link(path(QStringLiteral("a.json")), path(QStringLiteral("rig-a.png"))));
        const QByteArray rigA = lrtest::readFile(path(QStringLiteral("a.json")));
        r = compare({suzanne(), path(QStringLiteral("a.json")), path(QStringLiteral("b.json")),
                     QStringLiteral("-o"), path(QStringLiteral("rig-a.png")), QStringLiteral("--size"),
                     QStringLiteral("32x24")});
        QVERIFY2(r.code == 1 && r.err.contains(QLatin1String("it is rig A")), qPrintable(r.show()));
        QCOMPARE(lrtest::readFile(path(QStringLiteral("a.json"))), rigA);
    }

    void badRig_exit1NamingTheRigAndWritingNothing() {
        LR_REQUIRE_DISPLAY();
        const QString diff = path(QStringLiteral("never.png"));
        const QString bad = QStringLiteral(LIGHTRIG_TEST_DATA "/rig/bad/many-errors.json");
        Run r = compare({suzanne(), path(QStringLiteral("a.json")), bad, QStringLiteral("-o"), diff,
                         QStringLiteral("--size"), QStringLiteral("32x24")});
        QVERIFY2(r.code == 1, qPrintable(r.show()));
        QCOMPARE(r.errorLines().size(), 1);
        QVERIFY2(r.errorLines().first().startsWith(QLatin1String("lightrig compare: rig B: ")),
                 qPrintable(r.show()));
        QVERIFY2(r.err.contains(QLatin1String("many-errors.json: ")), qPrintable(r.show()));
        QVERIFY(!QFile::exists(diff));

        r = compare({suzanne(), path(QStringLiteral("missing.json")), path(QStringLiteral("a.json")),
                     QStringLiteral("-o"), diff});
        QVERIFY2(r.code == 1, qPrintable(r.show()));
        QVERIFY2(r.err.contains(QLatin1String("rig A: ")) && r.err.contains(QLatin1String("missing.json")),
                 qPrintable(r.show()));
        QVERIFY(!QFile::exists(diff));
    }

    void noDisplay_exit1() {
        const QProcessEnvironment env = lrtest::environmentWithoutDisplay();
        const QString diff = path(QStringLiteral("nodisplay.png"));
        const Run r = compare({suzanne(), path(QStringLiteral("a.json")), path(QStringLiteral("b.json")),
                               QStringLiteral("-o"), diff},
                              &env);
        QVERIFY2(r.code == 1, qPrintable(r.show()));
        QVERIFY2(r.err.contains(QLatin1String("needs an X display")), qPrintable(r.show()));
        QVERIFY(!QFile::exists(diff));
    }
};

LR_GL_TEST_MAIN(TestCompareCli)
#include "tst_comparecli.moc"
