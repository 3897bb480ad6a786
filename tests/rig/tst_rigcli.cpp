// `lightrig validate` and `lightrig format`, run as the user runs them (QProcess on the built executable):
// output lines and exit codes 0 (all good), 1 (a file is bad), 2 (usage).
#include "rigtest.h"
#include "support/cli.h"

#include <QTemporaryDir>
#include <sys/stat.h>

using namespace lr;
using namespace lr::test;

namespace {
using Run = lrtest::CliRun;

Run lightrig(const QStringList& args, bool withDisplay = true) {
    const QProcessEnvironment noDisplay = lrtest::environmentWithoutDisplay();
    return lrtest::runLightrig(args, withDisplay ? nullptr : &noDisplay, 30000);
}

QString show(const Run& r) {
    return r.show();
}

void copy(const QString& from, const QString& to) {
    QFile::remove(to);
    QVERIFY(QFile::copy(from, to));
    QVERIFY(QFile::setPermissions(to, QFile::ReadOwner | QFile::WriteOwner));
}
} // namespace

class TestRigCli : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase();
    void validateGood();
    void validateBad();
    void validateUsage();
    void editorWithoutADisplay();
    void validateEmbeddedPreset();
    void validateEnvironment();
    void validateAreaLights();
    void validateIesProfiles();
    void fifoIsRefused();
    void typoIsAUsageError();
    void formatCheck();
    void formatRewrites();
    void formatLeavesBadFilesAlone();

  private:
    QTemporaryDir m_dir;
};

void TestRigCli::initTestCase() {
    QVERIFY2(QFile::exists(QStringLiteral(LIGHTRIG_EXECUTABLE)), LIGHTRIG_EXECUTABLE);
    QVERIFY(m_dir.isValid());
}

void TestRigCli::validateGood() {
    const QString a = dataPath(QStringLiteral("good/issue-example.json"));
    const QString b = dataPath(QStringLiteral("good/unknown-keys.json"));
    const Run r = lightrig({QStringLiteral("validate"), a, b});
    QVERIFY2(r.code == 0, qPrintable(show(r)));
    QVERIFY2(r.lines().contains(a + QStringLiteral(": ok")), qPrintable(show(r)));
    QVERIFY2(r.lines().contains(b + QStringLiteral(": ok")), qPrintable(show(r)));
    QVERIFY2(r.lines().contains(b + QStringLiteral(": warning: lights[0].colour: unknown key (ignored)")),
             qPrintable(show(r)));
}

void TestRigCli::validateBad() {
    const QString good = dataPath(QStringLiteral("good/minimal.json"));
    const QString bad = dataPath(QStringLiteral("bad/studio.json"));
    const QString missing = m_dir.filePath(QStringLiteral("missing.json"));
    const Run r = lightrig({QStringLiteral("validate"), good, bad, missing});
    QVERIFY2(r.code == 1, qPrintable(show(r)));
    QVERIFY2(r.lines().contains(good + QStringLiteral(": ok")), qPrintable(show(r)));
    QVERIFY2(r.lines().contains(
                 bad + QStringLiteral(
                           ": lights[2].falloff.range: must be a finite number > 0 and <= 1e12, got -5")),
             qPrintable(show(r)));
    QVERIFY2(!r.lines().contains(bad + QStringLiteral(": ok")), qPrintable(show(r)));
    QVERIFY2(r.out.contains(missing + QStringLiteral(": cannot open")), qPrintable(show(r)));
}

void TestRigCli::validateUsage() {
    Run r = lightrig({QStringLiteral("validate")});
    QVERIFY2(r.code == 2 && r.err.contains(QStringLiteral("no files")), qPrintable(show(r)));
    r = lightrig({QStringLiteral("validate"), QStringLiteral("--frobnicate"),
                  dataPath(QStringLiteral("good/minimal.json"))});
    QVERIFY2(r.code == 2 && r.err.contains(QStringLiteral("frobnicate")), qPrintable(show(r)));
    r = lightrig({QStringLiteral("validate"), QStringLiteral("--help")});
    QVERIFY2(r.code == 0 && r.out.startsWith(QStringLiteral("Usage: lightrig validate")),
             qPrintable(show(r)));
    r = lightrig({QStringLiteral("format"), QStringLiteral("--help")});
    QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("--check")), qPrintable(show(r)));
    r = lightrig({QStringLiteral("format"), QStringLiteral("--check")});
    QVERIFY2(r.code == 2, qPrintable(show(r)));
}

// The editor's own options work without a display, and the editor itself says it needs one (no abort).
void TestRigCli::editorWithoutADisplay() {
    Run r = lightrig({QStringLiteral("--version")}, false);
    QVERIFY2(r.code == 0 && r.out.startsWith(QStringLiteral("lightrig ")), qPrintable(show(r)));
    r = lightrig({QStringLiteral("--help")}, false);
    QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("--rig")), qPrintable(show(r)));
    r = lightrig({QStringLiteral("--frobnicate")}, false);
    QVERIFY2(r.code == 2 && r.err.contains(QStringLiteral("frobnicate")), qPrintable(show(r)));
    r = lightrig({}, false);
    QVERIFY2(r.code == 1 && r.err.contains(QStringLiteral("needs a display")), qPrintable(show(r)));
    // With a display, Qt's own options are Qt's, not usage errors.
    if (qEnvironmentVariableIsSet("DISPLAY")) {
        r = lightrig({QStringLiteral("-style"), QStringLiteral("fusion"), QStringLiteral("--version")});
        QVERIFY2(r.code == 0 && r.out.startsWith(QStringLiteral("lightrig ")), qPrintable(show(r)));
    }
}

// The presets are compiled into the executable too: Qt resource paths are files to it.
void TestRigCli::validateEmbeddedPreset() {
    const QString path = builtinPresetPath(QStringLiteral("default"));
    const Run r = lightrig({QStringLiteral("validate"), path});
    QVERIFY2(r.code == 0 && r.lines() == QStringList{path + QStringLiteral(": ok")}, qPrintable(show(r)));
}

// Issue 15: validate also loads a rig's environment: the studio loads; an image file that does not (missing
// here; beside the rig, where a relative file is looked for) is an error at environment.file naming it.
void TestRigCli::validateEnvironment() {
    const QString studio = dataPath(QStringLiteral("good/environment.json"));
    const QString missing = m_dir.filePath(QStringLiteral("sky.json"));
    QFile f(missing);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "lightrig", "version": 1, "environment": {"source": "image", "file": "hdr/sky.exr"},
        "lights": []})");
    f.close();
    const Run r = lightrig({QStringLiteral("validate"), studio, missing});
    QVERIFY2(r.code == 1, qPrintable(show(r)));
    QVERIFY2(r.lines().contains(studio + QStringLiteral(": ok")), qPrintable(show(r)));
    QVERIFY2(!r.lines().contains(missing + QStringLiteral(": ok")), qPrintable(show(r)));
    bool named = false;
    for (const QString& line : r.lines())
        named = named || (line.startsWith(missing + QStringLiteral(": environment.file: ")) &&
                          line.contains(QStringLiteral("sky.exr")));
    QVERIFY2(named, qPrintable(show(r)));
}

// Issue 39: `validate` reads the IES profiles a rig names (relative to the rig): a good one is ok, a
// truncated one is reported as "RIG: lights[0].ies.file: IESFILE:LINE: reason", exit 1.
void TestRigCli::validateIesProfiles() {
    const QString ies = QStringLiteral(LIGHTRIG_TEST_DATA "/ies/");
    copy(ies + QStringLiteral("full.ies"), m_dir.filePath(QStringLiteral("good.ies")));
    copy(ies + QStringLiteral("truncated.ies"), m_dir.filePath(QStringLiteral("cut.ies")));
    const auto rig = [&](const QString& name, const QString& file) {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        f.open(QIODevice::WriteOnly);
        f.write(R"({"format": "lightrig", "version": 4, "lights": [{"type": "point", "position": [0, 2, 0],
            "falloff": {"model": "inverse-square"}, "ies": {"file": ")" +
                file.toUtf8() + R"("}}]})");
        return path;
    };
    const QString good = rig(QStringLiteral("ies-good.json"), QStringLiteral("good.ies"));
    const QString bad = rig(QStringLiteral("ies-bad.json"), QStringLiteral("cut.ies"));
    const Run r = lightrig({QStringLiteral("validate"), good, bad});
    QVERIFY2(r.code == 1, qPrintable(show(r)));
    QVERIFY2(r.lines().contains(good + QStringLiteral(": ok")), qPrintable(show(r)));
    bool named = false;
    for (const QString& line : r.lines())
        named = named || line.startsWith(bad + QStringLiteral(": lights[0].ies.file: ") +
                                         m_dir.filePath(QStringLiteral("cut.ies")) + QStringLiteral(":9: "));
    QVERIFY2(named, qPrintable(show(r)));
}

// Issue 16: `validate` reads rect and disk lights through the same reader as render and bench: a softbox rig
// is ok (and `format --check` finds it canonical), a bad area.width is reported with the file, the field and
// the reason, a rect in a version 1 file names the version that introduced it; exit 1 for either.
void TestRigCli::validateAreaLights() {
    const QString good = dataPath(QStringLiteral("good/area.json"));
    const QString bad = m_dir.filePath(QStringLiteral("softbox.json"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(rigJson2(with(kRect, R"("area": {"width": -2, "height": 1})")));
    f.close();
    const QString old = m_dir.filePath(QStringLiteral("old.json"));
    QFile o(old);
    QVERIFY(o.open(QIODevice::WriteOnly));
    o.write(rigJson(kDisk));
    o.close();
    Run r = lightrig({QStringLiteral("validate"), good, bad, old});
    QVERIFY2(r.code == 1, qPrintable(show(r)));
    QVERIFY2(r.lines().contains(good + QStringLiteral(": ok")), qPrintable(show(r)));
    QVERIFY2(
        r.lines().contains(bad + QStringLiteral(": lights[0].area.width: must be a finite number from 0 to "
                                                "1e12, got -2")),
        qPrintable(show(r)));
    QVERIFY2(
        r.lines().contains(old + QStringLiteral(": lights[0].type: disk lights came with version 2 of the "
                                                "format, but the file says \"version\": 1; write "
                                                "\"version\": 2")),
        qPrintable(show(r)));
    QVERIFY2(!r.lines().contains(bad + QStringLiteral(": ok")), qPrintable(show(r)));
    r = lightrig(
        {QStringLiteral("validate"), good, builtinPresetPath(QStringLiteral("pbr-softbox-product"))});
    QVERIFY2(r.code == 0, qPrintable(show(r)));
    r = lightrig({QStringLiteral("format"), QStringLiteral("--check"), good});
    QVERIFY2(r.code == 0, qPrintable(show(r)));
}

// `mkfifo f.json; lightrig validate f.json` blocked forever; now every reader of rig files refuses it.
void TestRigCli::fifoIsRefused() {
    const QString fifo = m_dir.filePath(QStringLiteral("fifo.json"));
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    const QString expected =
        fifo +
        QStringLiteral(": is not a regular file (a FIFO, socket or device); rig files must be regular files");
    for (const char* sub : {"validate", "format"}) {
        const Run r = lightrig({QLatin1String(sub), fifo}); // code -1 after 30 s: it blocked
        QVERIFY2(r.code == 1 && r.lines().contains(expected), qPrintable(show(r)));
    }
}

// `lightrig <typo>` took the word for a model file and opened the editor (headless: "needs a display",
// which looks like a hang under xvfb-run). A first word that is neither a subcommand nor an existing file
// is a usage error naming the subcommands; with and without a display.
void TestRigCli::typoIsAUsageError() {
    for (const bool display : {false, true}) {
        if (display && !qEnvironmentVariableIsSet("DISPLAY")) continue;
        const Run r =
            lightrig({QStringLiteral("valdiate"), dataPath(QStringLiteral("good/minimal.json"))}, display);
        QVERIFY2(r.code == 2, qPrintable(show(r)));
        QVERIFY2(r.err.contains(QStringLiteral("valdiate")) &&
                     r.err.contains(QStringLiteral("validate, format, render, bench")),
                 qPrintable(show(r)));
        // A single word that is not a file, too (the editor's MODEL argument).
        const Run one = lightrig({QStringLiteral("rendr")}, display);
        QVERIFY2(one.code == 2 && one.err.contains(QStringLiteral("rendr")), qPrintable(show(one)));
    }
}

void TestRigCli::formatCheck() {
    const QString canonical = m_dir.filePath(QStringLiteral("canonical.json"));
    copy(QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/presets/three-point.json"), canonical);
    const QString loose = m_dir.filePath(QStringLiteral("loose.json"));
    copy(dataPath(QStringLiteral("good/issue-example.json")), loose);
    const QByteArray before = readAll(loose);
    Run r = lightrig({QStringLiteral("format"), QStringLiteral("--check"), canonical});
    QVERIFY2(r.code == 0, qPrintable(show(r)));
    r = lightrig({QStringLiteral("format"), QStringLiteral("--check"), canonical, loose});
    QVERIFY2(r.code == 1 && r.out.contains(loose + QStringLiteral(": not in canonical form")),
             qPrintable(show(r)));
    QCOMPARE(readAll(loose), before); // --check changes nothing
}

void TestRigCli::formatRewrites() {
    const QString loose = m_dir.filePath(QStringLiteral("rewrite.json"));
    copy(dataPath(QStringLiteral("good/issue-example.json")), loose);
    const RigReadResult original = readRigFile(loose);
    LR_VERIFY_OK(original);
    Run r = lightrig({QStringLiteral("format"), loose});
    QVERIFY2(r.code == 0 && r.out.contains(loose + QStringLiteral(": formatted")), qPrintable(show(r)));
    const RigReadResult after = readRigFile(loose);
    LR_VERIFY_OK(after);
    QVERIFY(*after.rig == *original.rig);
    QCOMPARE(readAll(loose), writeRigJson(*original.rig));
    r = lightrig({QStringLiteral("format"), QStringLiteral("--check"), loose});
    QVERIFY2(r.code == 0, qPrintable(show(r)));
}

void TestRigCli::formatLeavesBadFilesAlone() {
    const QString bad = m_dir.filePath(QStringLiteral("bad.json"));
    copy(dataPath(QStringLiteral("bad/many-errors.json")), bad);
    const QString unknown = m_dir.filePath(QStringLiteral("unknown.json"));
    copy(dataPath(QStringLiteral("good/unknown-keys.json")), unknown);
    const QByteArray badBefore = readAll(bad), unknownBefore = readAll(unknown);
    const Run r = lightrig({QStringLiteral("format"), bad, unknown});
    QVERIFY2(r.code == 1, qPrintable(show(r)));
    QVERIFY2(r.out.contains(bad + QStringLiteral(": lights[1].direction: must not be the zero vector")),
             qPrintable(show(r)));
    QVERIFY2(r.out.contains(unknown + QStringLiteral(": not formatted")), qPrintable(show(r)));
    QCOMPARE(readAll(bad), badBefore);
    QCOMPARE(readAll(unknown), unknownBefore);
}

QTEST_GUILESS_MAIN(TestRigCli)
#include "tst_rigcli.moc"
