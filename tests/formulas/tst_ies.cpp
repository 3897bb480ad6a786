// Issue 39: the LM-63 reader (core/ies.h) on the small profiles in tests/data/ies/: every symmetry unfolds to
// the same full distribution, the evaluation is bilinear in angle, and bad files are refused with
// "FILE:LINE: reason".
#include "core/ies.h"

#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <random>

using namespace lr;

namespace {

QString data(const QString& name) {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/ies/") + name;
}

std::shared_ptr<const IesProfile> load(const QString& name) {
    QString error;
    auto p = readIesFile(data(name), &error);
    if (!p) qWarning("%s", qPrintable(error));
    return p;
}

// The function the symmetric test files sample (tests/data/ies, 22.5° vertical, 45° horizontal steps).
double sampled(double theta, double phi) {
    const double c = std::cos(theta * M_PI / 360.0);
    return std::round(1000.0 * (c * c) * (1.0 + 0.5 * std::cos(phi * M_PI / 90.0)) * 1000.0) / 1000.0;
}

QString refusal(const QByteArray& text, const QString& name = QStringLiteral("x.ies")) {
    QString error;
    const auto p = readIesData(text, name, &error);
    return p ? QString() : error;
}

} // namespace

class TestIes : public QObject {
    Q_OBJECT
  private slots:
    void everySymmetryGivesTheFullDistribution();
    void evaluationIsBilinearInAngle();
    void rotationalAndVersions();
    void zeroCandela();
    void oneAngle();
    void tenThousandAngles();
    void badFilesNameFileLineAndReason_data();
    void badFilesNameFileLineAndReason();
    void limits();
    void beamAngle();
};

void TestIes::everySymmetryGivesTheFullDistribution() {
    const auto full = load(QStringLiteral("full.ies"));
    QVERIFY(full);
    QCOMPARE(full->symmetry, QStringLiteral("full"));
    // At the samples the file holds, the full profile is the function itself.
    for (double phi : {0.0, 45.0, 90.0, 270.0, 315.0})
        for (double theta : {0.0, 22.5, 90.0, 180.0})
            QVERIFY(std::abs(iesCandela(*full, theta, phi) - sampled(theta, phi)) < 1e-6);
    const QStringList others{"full-open.ies", "bilateral.ies", "quadrant.ies", "bilateral-90.ies"};
    const QStringList symmetries{"full", "bilateral", "quadrant", "bilateral-90"};
    std::mt19937 rng(39);
    std::uniform_real_distribution<double> theta(0.0, 180.0), phi(-360.0, 720.0);
    for (qsizetype i = 0; i < others.size(); ++i) {
        const auto p = load(others[i]);
        QVERIFY2(p, qPrintable(others[i]));
        QCOMPARE(p->symmetry, symmetries[i]);
        QCOMPARE(p->horizontal, full->horizontal);
        QCOMPARE(p->vertical, full->vertical);
        for (int k = 0; k < 2000; ++k) {
            const double t = theta(rng), f = phi(rng);
            QVERIFY2(std::abs(iesCandela(*p, t, f) - iesCandela(*full, t, f)) < 1e-9,
                     qPrintable(QStringLiteral("%1 at %2, %3").arg(others[i]).arg(t).arg(f)));
        }
    }
}

void TestIes::evaluationIsBilinearInAngle() {
    const auto p = load(QStringLiteral("full.ies"));
    QVERIFY(p);
    // Midway between four samples: the mean of the four.
    const double mid =
        0.25 * (sampled(22.5, 45.0) + sampled(45.0, 45.0) + sampled(22.5, 90.0) + sampled(45.0, 90.0));
    QVERIFY(std::abs(iesCandela(*p, 33.75, 67.5) - mid) < 1e-9);
    // A quarter of the way along the vertical angle, on a horizontal sample.
    const double v = 0.75 * sampled(90.0, 0.0) + 0.25 * sampled(112.5, 0.0);
    QVERIFY(std::abs(iesCandela(*p, 95.625, 0.0) - v) < 1e-9);
    // Outside the angles: wrapped; NaN gives nothing.
    QVERIFY(std::abs(iesCandela(*p, 22.5, 405.0) - sampled(22.5, 45.0)) < 1e-6);
    QVERIFY(std::abs(iesCandela(*p, 22.5, -45.0) - sampled(22.5, 315.0)) < 1e-6);
    QCOMPARE(iesCandela(*p, std::nan(""), 0.0), 0.0);
    // The frame: nadir -z, C0 +x, C90 = x × nadir = +y.
    const struct {
        double x, y, z;
    } nadir{0, 0, -1}, x{1, 0, 0}, y{0, 1, 0}, w{0, std::sqrt(0.5), -std::sqrt(0.5)};
    QVERIFY(std::abs(iesCandelaToward<double>(*p, w, nadir, x, y) - sampled(45.0, 90.0)) < 1e-9);
    // Float evaluates the same table.
    QVERIFY(std::abs(iesCandela(*p, 33.75f, 67.5f) - float(mid)) < 1e-3f * float(mid));
}

void TestIes::rotationalAndVersions() {
    const auto p = load(QStringLiteral("rotational.ies"));
    QVERIFY(p);
    QCOMPARE(p->symmetry, QStringLiteral("rotational"));
    QCOMPARE(p->format, QStringLiteral("LM-63-2002"));
    // The candela multiplier (2) is applied.
    const double c = std::cos(45.0 * M_PI / 360.0);
    QVERIFY(std::abs(iesCandela(*p, 45.0, 123.0) - 2.0 * std::round(500.0 * c * c * 1000.0) / 1000.0) < 1e-9);
    QCOMPARE(iesCandela(*p, 45.0, 10.0), iesCandela(*p, 45.0, 250.0));
    QCOMPARE(load(QStringLiteral("quadrant.ies"))->format,
             QStringLiteral("LM-63-1995")); // CRLF, TILT=INCLUDE
    QCOMPARE(load(QStringLiteral("full.ies"))->format, QStringLiteral("LM-63-2019"));
}

void TestIes::zeroCandela() {
    const auto p = load(QStringLiteral("zero.ies"));
    QVERIFY(p);
    QCOMPARE(p->peak, 0.0);
    QCOMPARE(iesCandela(*p, 30.0, 0.0), 0.0);
    QCOMPARE(iesBeamAngle(*p), 0.0);
}

void TestIes::oneAngle() {
    const auto p = load(QStringLiteral("one-angle.ies"));
    QVERIFY(p);
    QCOMPARE(p->peak, 250.0);
    for (double t : {0.0, 45.0, 120.0, 180.0})
        QCOMPARE(iesCandela(*p, t, 77.0), 250.0);
}

void TestIes::tenThousandAngles() {
    // 10,000 vertical angles by 2 horizontal (bilateral), I = 1 + θ/180 in C0 and 2·that in C180.
    const int n = 10000;
    QByteArray text = "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 10000 2 1 2 0 0 0\n1 1 0\n";
    for (int i = 0; i < n; ++i)
        text += QByteArray::number(180.0 * i / (n - 1), 'g', 17) + (i % 8 == 7 ? "\n" : " ");
    text += "\n0 180\n";
    for (int h = 0; h < 2; ++h)
        for (int i = 0; i < n; ++i)
            text += QByteArray::number((h + 1) * (1.0 + double(i) / (n - 1)), 'g', 17) +
                    (i % 8 == 7 ? "\n" : " ");
    QString error;
    const auto p = readIesData(text, QStringLiteral("big.ies"), &error);
    QVERIFY2(p, qPrintable(error));
    QCOMPARE(p->vertical.size(), std::size_t(n));
    QCOMPARE(p->fileHorizontal, 2);
    QVERIFY(std::abs(iesCandela(*p, 90.0, 0.0) - 1.5) < 1e-9);
    QVERIFY(std::abs(iesCandela(*p, 90.0, 180.0) - 3.0) < 1e-9);
    QVERIFY(std::abs(iesCandela(*p, 90.0, 270.0) - 2.25) < 1e-9); // 90 of the way from 180 back to 360
}

void TestIes::badFilesNameFileLineAndReason_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("reason");
    QTest::newRow("malformed number") << "malformed.ies" << 8 << "\"5O\" is not a number";
    QTest::newRow("truncated") << "truncated.ies" << 9 << "the file ends before candela value 3";
    QTest::newRow("descending") << "descending.ies" << 6 << "angles must ascend";
    QTest::newRow("type B") << "type-b.ies" << 4 << "photometric type 2 (B) is not read";
    QTest::newRow("no TILT") << "no-tilt.ies" << 7 << "before its TILT= line";
    QTest::newRow("missing") << "nothing-here.ies" << -1 << "no such file";
}

void TestIes::badFilesNameFileLineAndReason() {
    QFETCH(QString, file);
    QFETCH(int, line);
    QFETCH(QString, reason);
    QString error;
    QVERIFY(!readIesFile(data(file), &error));
    const QString prefix = line > 0 ? QStringLiteral("%1:%2: ").arg(data(file)).arg(line) : data(file) + ": ";
    QVERIFY2(error.startsWith(prefix), qPrintable(error));
    QVERIFY2(error.contains(reason), qPrintable(error));
}

void TestIes::limits() {
    const QByteArray head = "IESNA:LM-63-2002\nTILT=NONE\n";
    QVERIFY(refusal(head + "1 -1 1 20000 1 1 2 0 0 0\n")
                .contains("x.ies:3: the number of vertical angles is 20000"));
    QVERIFY(refusal(head + "1 -1 1 3000 3000 1 2 0 0 0\n").contains("3000 × 3000 candela values; at most"));
    QVERIFY(refusal(head + "1 -1 0 3 1 1 2 0 0 0\n").contains("candela multiplier is 0"));
    const QByteArray tail = "1 -1 1 3 1 1 2 0 0 0\n1 1 0\n0 45 90\n0\n";
    QVERIFY(!refusal(head + tail + "1 2 3\n").size());
    QVERIFY(refusal(head + tail + "1 nan 3\n").contains("x.ies:7: candela value 2"));
    QVERIFY(refusal(head + tail + "1 inf 3\n").contains("is not a number"));
    QVERIFY(refusal(head + tail + "1 1e999 3\n").contains(":7: "));
    QVERIFY(refusal(head + tail + "1 -2 3\n").contains("is negative"));
    QVERIFY(
        refusal(head + tail + "1 2 3 4\n").contains("x.ies:7: more numbers after the last candela value"));
    QVERIFY(refusal(head + "1 -1 1 3 1 1 2 0 0 0\n1 1 0\n0 45 190\n0\n1 2 3\n")
                .contains("must lie in 0 ... 180"));
    QVERIFY(refusal(head + "1 -1 1 3 2 1 2 0 0 0\n1 1 0\n0 45 90\n0 120\n1 2 3 1 2 3\n")
                .contains("no LM-63 symmetry"));
    QVERIFY(refusal(QByteArray()).contains("x.ies:1: the file ends before its TILT= line"));
    QVERIFY(refusal(QByteArray(1000, '\x01')).contains("TILT="));
    // A file too large to read is refused before it is read.
    QTemporaryDir dir;
    QFile big(dir.filePath(QStringLiteral("big.ies")));
    QVERIFY(big.open(QIODevice::WriteOnly) && big.resize(kMaxIesFileBytes + 1));
    big.close();
    QString error;
    QVERIFY(!readIesFile(big.fileName(), &error));
    QVERIFY2(error.contains("an IES file may have at most"), qPrintable(error));
}

void TestIes::beamAngle() {
    // I = 100 up to 20°, falling linearly to 0 at 40°: 50 % at 30°, so the beam is 60° across.
    const QByteArray text = "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 5 1 1 2 0 0 0\n1 1 0\n0 10 20 40 90\n0\n"
                            "100 100 100 0 0\n";
    QString error;
    const auto p = readIesData(text, QStringLiteral("beam.ies"), &error);
    QVERIFY2(p, qPrintable(error));
    QCOMPARE(p->peak, 100.0);
    QVERIFY(std::abs(iesBeamAngle(*p) - 60.0) < 1e-9);
}

QTEST_GUILESS_MAIN(TestIes)
#include "tst_ies.moc"
