// Reading bad rig files: every validation rule of docs/rig-format.md rejects its bad input with an error
// naming the right JSON path, all errors are reported, and the reader's limits (file size, lights,
// nesting, numbers) and file kinds (missing, FIFO) give their own messages. Valid files: tst_rigread.
#include "rigtest.h"

#include <QDir>
#include <QTemporaryDir>
#include <atomic>
#include <chrono>
#include <cmath>
#include <fcntl.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

using namespace lr;
using namespace lr::test;

class TestRigReadErrors : public QObject {
    Q_OBJECT
  private slots:
    void badFiles_data();
    void badFiles();
    void everyBadFileIsChecked();
    void reportsAllErrors();
    void duplicateKeysAnywhere();
    void nameLengthInCharacters();
    void keysInPaths();
    void numbersOutOfRange();
    void overLargeFile();
    void tooManyLights();
    void farTooManyLights();
    void nonFiniteSpellings();
    void nestingLimit();
    void missingFile();
    void fifoIsRefused();
};

// Every file in tests/data/rig/bad and the start of the error it must give ("json.path: reason" or
// "line L, column C (in json.path): reason"; positions counted by hand, columns in characters).
static const struct {
    const char* file;
    const char* expected;
} kBadFiles[] = {
    {"empty.json", "the file is empty"},
    {"whitespace.json", "the file is empty"},
    {"truncated.json", "line 2, column 54 (in lights[0].position[2]): unexpected end of file"},
    {"truncated-string.json", "line 1, column 19 (in format): unexpected end of file"},
    {"binary.json", "line 1, column 1: not valid UTF-8 text (byte 0x89; is this a binary file?)"},
    {"invalid-utf8.json", "line 1, column 50: not valid UTF-8 text (byte 0xe9"},
    {"nul-byte.json", "line 1, column 48: contains a NUL byte"},
    {"utf16.json", "line 1, column 1: the file is UTF-16 (little-endian); rig files must be UTF-8"},
    {"utf16-be-no-bom.json", "line 1, column 1: the file is UTF-16 (big-endian); rig files must be UTF-8"},
    {"duplicate-key.json", "lights[1].intensity: duplicate key"},
    {"duplicate-escaped-key.json", "lights: duplicate key"},
    {"overflow.json", "lights[0].intensity: must be a finite number from 0 to 1000000, got 1e999 (out of the "
                      "range of a double)"},
    {"underflow.json",
     "lights[0].falloff.range: must be a finite number > 0 and <= 1e12, got 1e-400 (out of the range"},
    {"nan.json", "line 1, column 50 (in ambient[0]): NaN is not a JSON number"},
    {"infinity.json", "line 1, column 53 (in ambient[1]): -Infinity is not a JSON number"},
    {"newer-version.json", "version: the file is version 5, newer than this LightRig reads (version 4)"},
    {"not-lightrig.json", "format: missing"},
    {"wrong-format.json", "format: must be \"lightrig\""},
    {"top-level-array.json", "(top level): must be a JSON object"},
    {"trailing-comma.json", "line 1, column 51: unexpected '}', expected a key in double quotes"},
    {"trailing-text.json", "line 2, column 1: unexpected text after the end of the JSON document"},
    {"comment.json", "line 1, column 38: unexpected '/', expected a key in double quotes"},
    {"single-quotes.json", "line 1, column 2: unexpected ''', expected a key in double quotes"},
    {"leading-zero.json", "line 1, column 36 (in version): numbers must not have leading zeros"},
    {"bad-escape.json", "line 1, column 50 (in name): invalid escape '\\L' in a string"},
    {"lone-surrogate.json",
     "line 1, column 53 (in name): \\u escape: a high surrogate must be followed by a low one"},
    {"control-character.json", "line 1, column 50 (in name): control character U+000a inside a string"},
    {"deep-nesting.json", "line 1, column 78 (in "
                          "extra[0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0]["
                          "0][0][0][0][0][0]): nested deeper than 32 levels"},
    {"studio.json", "lights[2].falloff.range: must be a finite number > 0 and <= 1e12, got -5"},
    {"many-errors.json", "space: must be \"world\" or \"model\""},
};

void TestRigReadErrors::badFiles_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("expected");
    for (const auto& b : kBadFiles)
        QTest::newRow(b.file) << QString::fromLatin1(b.file) << QString::fromUtf8(b.expected);
}

void TestRigReadErrors::badFiles() {
    QFETCH(QString, file);
    QFETCH(QString, expected);
    const QString path = dataPath(QStringLiteral("bad/") + file);
    const RigReadResult r = readRigFile(path);
    QVERIFY2(!r.ok() && !r.rig.has_value(), qPrintable(describe(r)));
    QVERIFY2(hasMessage(r.errors, path, expected),
             qPrintable(QStringLiteral("expected \"%1\"\n").arg(expected) + describe(r)));
    // The same bytes through readRigJson give the same messages under the given display name.
    const RigReadResult fromBytes = readRigJson(readAll(path), file);
    QVERIFY2(hasMessage(fromBytes.errors, file, expected), qPrintable(describe(fromBytes)));
}

void TestRigReadErrors::everyBadFileIsChecked() {
    QStringList listed;
    for (const auto& b : kBadFiles)
        listed << QString::fromLatin1(b.file);
    listed.sort();
    const QStringList files =
        QDir(dataPath(QStringLiteral("bad"))).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QCOMPARE(files, listed);
}

void TestRigReadErrors::reportsAllErrors() {
    const QString path = dataPath(QStringLiteral("bad/many-errors.json"));
    const RigReadResult r = readRigFile(path);
    const QStringList expected = {
        QStringLiteral("space: must be"),
        QStringLiteral("ambient: must be an RGB colour"),
        QStringLiteral("shading.specular: must be"),
        QStringLiteral("shading.shininess: must be"),
        QStringLiteral("lights[0].position: must be a point"),
        QStringLiteral("lights[0].falloff.range: missing"),
        QStringLiteral("lights[0].cone: a point light has no cone"),
        QStringLiteral("lights[1].direction: must not be the zero vector"),
        QStringLiteral("lights[1].cone.inner: must be <= outer (40), got 50"),
        QStringLiteral("lights[2].intensity: must be a finite number from 0"),
        QStringLiteral("lights[2].falloff: a directional light has no falloff"),
        QStringLiteral("lights[3].diffuse: a rim light has no diffuse term"),
        QStringLiteral("lights[3].exponent: must be a finite number > 0"),
    };
    for (const QString& e : expected)
        QVERIFY2(hasMessage(r.errors, path, e),
                 qPrintable(QStringLiteral("missing \"%1\"\n").arg(e) + describe(r)));
    QCOMPARE(r.errors.size(), expected.size());
}

void TestRigReadErrors::duplicateKeysAnywhere() {
    const QByteArray deep = rigJson(spotWithCone(R"({"model": "hard", "outer": 10, "outer": 20})"));
    RigReadResult r = readRigJson(deep, QStringLiteral("d.json"));
    QVERIFY2(
        hasMessage(r.errors, QStringLiteral("d.json"), QStringLiteral("lights[0].cone.outer: duplicate key")),
        qPrintable(describe(r)));
    // The first of two equal keys wins for the other checks; both are errors anyway.
    r = readRigJson(R"({"format": "lightrig", "version": 1, "version": 1, "lights": []})",
                    QStringLiteral("v.json"));
    QCOMPARE(r.errors,
             QStringList{QStringLiteral("v.json: version: duplicate key; each key may appear only once")});
    // Many keys (the hashed path of the detector) in an unknown object.
    QByteArray big = "{";
    for (int i = 0; i < 100; ++i)
        big += "\"k" + QByteArray::number(i) + "\": 0, ";
    big += "\"k57\": 1}";
    r = readRigJson(rigJson({}, "\"extra\": " + big + ','), QStringLiteral("h.json"));
    QVERIFY2(hasMessage(r.errors, QStringLiteral("h.json"), QStringLiteral("extra.k57: duplicate key")),
             qPrintable(describe(r)));
    QCOMPARE(r.errors.size(), 1);
}

// Names are limited in characters (code points), not UTF-16 units or bytes: 256 emoji are fine.
void TestRigReadErrors::nameLengthInCharacters() {
    const QByteArray emoji = "\xf0\x9f\x92\xa1"; // U+1F4A1, two UTF-16 units, four bytes
    QByteArray name;
    for (int i = 0; i < kMaxRigNameLength; ++i)
        name += emoji;
    RigReadResult r =
        readRigJson(rigJson(with(kRim, "\"name\": \"" + name + '"'), "\"name\": \"" + name + "\","),
                    QStringLiteral("n.json"));
    LR_VERIFY_OK(r);
    QCOMPARE(r.rig->name.size(), 2 * kMaxRigNameLength);
    r = readRigJson(rigJson(with(kRim, "\"name\": \"" + name + "x\"")), QStringLiteral("n.json"));
    QCOMPARE(r.errors,
             QStringList{QStringLiteral("n.json: lights[0].name: must be at most 256 characters, got 257")});
}

// Paths quote keys that are not identifiers and shorten absurdly long ones, so that many messages about
// keys under one long key stay small.
void TestRigReadErrors::keysInPaths() {
    RigReadResult r =
        readRigJson(rigJson({}, R"("my key": 1, "\u00e9t\u00e9": 2,)"), QStringLiteral("k.json"));
    LR_VERIFY_OK(r);
    QVERIFY2(hasMessage(r.warnings, QStringLiteral("k.json"), QStringLiteral("[\"my key\"]: unknown key")),
             qPrintable(describe(r)));
    QVERIFY2(hasMessage(r.warnings, QStringLiteral("k.json"),
                        QString::fromUtf8("[\"\u00e9t\u00e9\"]: unknown key")),
             qPrintable(describe(r)));
    const QByteArray longKey(100'000, 'k');
    QByteArray inner;
    for (int i = 0; i < 150; ++i)
        inner += "\"d\": 0, ";
    r = readRigJson(rigJson({}, "\"" + longKey + "\": {" + inner + "\"e\": 0},"), QStringLiteral("l.json"));
    QCOMPARE(r.errors.size(), 149);
    qsizetype total = 0;
    for (const QString& e : r.errors)
        total += e.size();
    QVERIFY2(total < 149 * 200, qPrintable(r.errors.first()));
    QVERIFY2(r.errors.first().startsWith(QStringLiteral("l.json: [\"") + QString(48, QLatin1Char('k')) +
                                         QStringLiteral("\"...].d: duplicate key")),
             qPrintable(r.errors.first()));
}

void TestRigReadErrors::numbersOutOfRange() {
    for (const char* text : {"1e999", "-1e999", "1e-400", "123e456789"}) {
        const RigReadResult r = readRigJson(rigJson(with(kPoint, QByteArray(R"("intensity": )") + text)),
                                            QStringLiteral("n.json"));
        QVERIFY2(hasMessage(r.errors, QStringLiteral("n.json"),
                            QStringLiteral("lights[0].intensity: must be a finite number from 0 to 1000000, "
                                           "got %1 (out of the range of a double)")
                                .arg(QLatin1String(text))),
                 qPrintable(describe(r)));
    }
    // The largest finite double and a subnormal are numbers (rejected or accepted by their field's rule).
    RigReadResult r = readRigJson(rigJson(with(kPoint, R"("intensity": 1.7976931348623157e308)")),
                                  QStringLiteral("m.json"));
    QVERIFY2(hasMessage(r.errors, QStringLiteral("m.json"),
                        QStringLiteral("lights[0].intensity: must be a finite number from 0 to 1000000, got "
                                       "1.7976931348623157e308")),
             qPrintable(describe(r)));
    r = readRigJson(rigJson(with(kPoint, R"("intensity": 5e-324)")), QStringLiteral("s.json"));
    LR_VERIFY_OK(r);
    QCOMPARE(r.rig->lights[0].intensity, 5e-324);
}

void TestRigReadErrors::overLargeFile() {
    // A valid rig padded with spaces past 16 MiB: refused for its size alone, before parsing.
    QByteArray data = rigJson(kPoint);
    data.append(QByteArray(kMaxRigFileBytes - data.size() + 1, ' '));
    const RigReadResult r = readRigJson(data, QStringLiteral("big.json"));
    QCOMPARE(r.errors, QStringList{QStringLiteral(
                           "big.json: the file is 16777217 bytes; rig files are limited to 16 MiB")});
    data.chop(1); // exactly 16 MiB is allowed
    LR_VERIFY_OK(readRigJson(data, QStringLiteral("ok.json")));

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("big.json"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QVERIFY(f.resize(qint64(kMaxRigFileBytes) * 4)); // sparse: 64 MiB of NULs, never read
    f.close();
    const RigReadResult fromFile = readRigFile(path);
    QCOMPARE(
        fromFile.errors,
        QStringList{path + QStringLiteral(": the file is 67108864 bytes; rig files are limited to 16 MiB")});
}

void TestRigReadErrors::tooManyLights() {
    QByteArray lights;
    for (int i = 0; i < kMaxRigLights; ++i)
        lights += (i ? ", " : "") + kDirectional;
    RigReadResult r = readRigJson(rigJson(lights), QStringLiteral("max.json"));
    LR_VERIFY_OK(r);
    QCOMPARE(r.rig->lights.size(), size_t(kMaxRigLights));
    r = readRigJson(rigJson(lights + ", " + kDirectional), QStringLiteral("over.json"));
    QCOMPARE(r.errors,
             QStringList{QStringLiteral("over.json: lights: 4097 lights; at most 4096 are allowed")});
}

// 150,000 lights (1.5 million values) run into the JSON parser's value limit before the light count is
// known (the issue's 100,000 lights stopped in lights[74897].color[0]): the error is still about the
// number of lights, not "more than 1048576 values" inside some light.
void TestRigReadErrors::farTooManyLights() {
    QByteArray lights;
    const QByteArray light =
        R"({"type": "point", "position": [1, 2, 3], "color": [1, 0.5, 0.25]})"; // 10 values
    for (int i = 0; i < 150'000; ++i)
        lights += (i ? ", " : "") + light;
    const RigReadResult r = readRigJson(rigJson(lights), QStringLiteral("huge.json"));
    QCOMPARE(r.errors, QStringList{QStringLiteral(
                           "huge.json: lights: more than 104857 lights; at most 4096 are allowed")});
    // Too many values elsewhere (not lights) keep the parser's message.
    QByteArray numbers = "[";
    for (int i = 0; i < (1 << 20) + 1; ++i)
        numbers += i ? ",0" : "0";
    const RigReadResult other =
        readRigJson(rigJson({}, "\"extra\": " + numbers + "],"), QStringLiteral("x.json"));
    QVERIFY2(other.errors.size() == 1 && other.errors[0].contains(QStringLiteral("more than 1048576 values")),
             qPrintable(describe(other)));
}

// Every spelling of a non-finite number other languages write gets the specific message, with the text
// as written, not a generic syntax error.
void TestRigReadErrors::nonFiniteSpellings() {
    for (const char* word : {"NaN", "-NaN", "+NaN", "NAN", "nan", "-nan", "Infinity", "+Infinity",
                             "-Infinity", "INF", "-inf", "+Inf"}) {
        const RigReadResult r = readRigJson(rigJson({}, QByteArray("\"ambient\": [") + word + ", 0, 0],"),
                                            QStringLiteral("n.json"));
        QVERIFY2(r.errors.size() == 1 &&
                     r.errors[0] == QStringLiteral("n.json: line 1, column 50 (in ambient[0]): %1 is not a "
                                                   "JSON number; numbers must be finite")
                                        .arg(QLatin1String(word)),
                 qPrintable(QLatin1String(word) + QLatin1Char('\n') + describe(r)));
    }
}

void TestRigReadErrors::nestingLimit() {
    const auto nested = [](int depth) { return QByteArray(depth, '[') + QByteArray(depth, ']'); };
    // The document object is level 1, so an unknown value may nest 31 more levels.
    RigReadResult r = readRigJson(rigJson({}, "\"extra\": " + nested(31) + ','), QStringLiteral("ok.json"));
    LR_VERIFY_OK(r);
    QCOMPARE(r.warnings.size(), 1);
    r = readRigJson(rigJson({}, "\"extra\": " + nested(32) + ','), QStringLiteral("deep.json"));
    QVERIFY2(!r.ok() && r.errors.size() == 1 &&
                 r.errors[0].contains(QStringLiteral("nested deeper than 32 levels")),
             qPrintable(describe(r)));
    // Far deeper input (a stack-overflow attempt) fails the same way.
    r = readRigJson(nested(1'000'000), QStringLiteral("bomb.json"));
    QVERIFY2(!r.ok() && r.errors.size() == 1 && r.errors[0].contains(QStringLiteral("nested deeper")),
             qPrintable(describe(r)));
}

void TestRigReadErrors::missingFile() {
    const QString path = dataPath(QStringLiteral("does-not-exist.json"));
    RigReadResult r = readRigFile(path);
    QVERIFY(!r.ok());
    QCOMPARE(r.errors.size(), 1);
    QVERIFY2(r.errors[0].startsWith(path + QStringLiteral(": cannot open")), qPrintable(r.errors[0]));
    r = readRigFile(dataPath(QStringLiteral("bad")));
    QCOMPARE(r.errors, QStringList{dataPath(QStringLiteral("bad")) +
                                   QStringLiteral(": is a directory, not a rig file")});
}

// A FIFO (or socket, or device) is refused before it is opened: opening a FIFO without a writer blocks
// forever. If the reader did open it, a watchdog opens the writing end after 3 s so the test fails with
// the wrong message instead of hanging.
void TestRigReadErrors::fifoIsRefused() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString fifo = dir.filePath(QStringLiteral("f.json"));
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    std::atomic<bool> done{false};
    std::thread watchdog([&] {
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
        while (!done && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        if (done) return;
        const int fd = ::open(QFile::encodeName(fifo).constData(), O_WRONLY | O_NONBLOCK);
        if (fd >= 0) ::close(fd);
    });
    const RigReadResult r = readRigFile(fifo);
    done = true;
    watchdog.join();
    QCOMPARE(r.errors, QStringList{fifo + QStringLiteral(": is not a regular file (a FIFO, socket or "
                                                         "device); rig files must be regular files")});
}

QTEST_GUILESS_MAIN(TestRigReadErrors)
#include "tst_rigreaderrors.moc"
