// The rig reader's limits on hostile input (docs/rig-format.md): file size, nesting depth, number of lights,
// string lengths, and the number of messages — each must hold without the cost growing with the attack.
// Also reads every reproducer the fuzzer ever found (tests/data/rig/fuzz-regressions; scripts/fuzz).
#include "core/rigjson.h"

#include <QDir>
#include <QFile>
#include <QtTest>

using namespace lr;

namespace {

QByteArray header() {
    return R"({"format": "lightrig", "version": 1, )";
}

QByteArray nested(int depth) {
    return header() + "\"x\": " + QByteArray(depth, '[') + QByteArray(depth, ']') + ", \"lights\": []}";
}

QByteArray withLights(int n) {
    QByteArray out = header() + "\"lights\": [";
    for (int i = 0; i < n; ++i)
        out += QByteArray(i ? "," : "") + R"({"type": "directional", "direction": [0, -1, 0]})";
    return out + "]}";
}

qsizetype totalChars(const QStringList& list) {
    qsizetype n = 0;
    for (const QString& s : list)
        n += s.size();
    return n;
}

} // namespace

class TestReaderLimits : public QObject {
    Q_OBJECT
  private slots:
    void size() {
        QByteArray big = header() + "\"lights\": [], \"pad\": \"";
        big += QByteArray(kMaxRigFileBytes - big.size(), 'a');
        big += "\"}";
        QVERIFY(big.size() > kMaxRigFileBytes);
        const RigReadResult r = readRigJson(big, QStringLiteral("big.json"));
        QVERIFY(!r.ok());
        QCOMPARE(r.errors.size(), 1);
        QVERIFY2(r.errors.first().contains(QLatin1String("limited to 16 MiB")), qPrintable(r.errors.first()));
    }

    void depth() {
        // The top-level object is one level; 31 more fit, 32 more do not.
        QVERIFY2(readRigJson(nested(31), QStringLiteral("d.json")).ok(),
                 qPrintable(readRigJson(nested(31), QStringLiteral("d.json")).errors.join(u'\n')));
        const RigReadResult r = readRigJson(nested(32), QStringLiteral("d.json"));
        QVERIFY(!r.ok());
        QVERIFY2(r.errors.join(u'\n').contains(QLatin1String("nested deeper than 32")),
                 qPrintable(r.errors.join(u'\n')));
        // Far deeper than any stack could recurse: refused at the limit, no stack overflow.
        QVERIFY(!readRigJson(nested(1 << 20), QStringLiteral("d.json")).ok());
    }

    void lightCount() {
        const RigReadResult ok = readRigJson(withLights(kMaxRigLights), QStringLiteral("n.json"));
        QVERIFY2(ok.ok(), qPrintable(ok.errors.join(u'\n')));
        QCOMPARE(int(ok.rig->lights.size()), kMaxRigLights);
        const RigReadResult r = readRigJson(withLights(kMaxRigLights + 1), QStringLiteral("n.json"));
        QVERIFY(!r.ok());
        QVERIFY2(r.errors.first().contains(QLatin1String("at most 4096")), qPrintable(r.errors.first()));
    }

    void nameLength() {
        const auto rig = [](const QByteArray& name) {
            return readRigJson(header() + "\"name\": \"" + name + "\", \"lights\": []}",
                               QStringLiteral("s.json"));
        };
        QVERIFY(rig(QByteArray(kMaxRigNameLength, 'n')).ok());
        QVERIFY(!rig(QByteArray(kMaxRigNameLength + 1, 'n')).ok());
        // Characters, not bytes or UTF-16 units: 256 emoji (4 bytes, 2 units each) fit.
        QByteArray emoji;
        for (int i = 0; i < kMaxRigNameLength; ++i)
            emoji += "\xF0\x9F\x98\x80";
        QVERIFY(rig(emoji).ok());
        // A 10 MB name is refused with a short message (the name is not echoed back).
        const RigReadResult r = rig(QByteArray(10'000'000, 'n'));
        QVERIFY(!r.ok());
        QVERIFY(totalChars(r.errors) < 1000);
    }

    // Every string the reader echoes into a message is shortened, so messages stay small however long the
    // offending strings are.
    void longStringsInMessages() {
        const QByteArray longText(1'000'000, 'q');
        const RigReadResult r = readRigJson(header() + "\"space\": \"" + longText +
                                                "\", \"lights\": [{\"type\": \"" + longText + "\"}]}",
                                            QStringLiteral("s.json"));
        QVERIFY(!r.ok());
        QVERIFY2(totalChars(r.errors) < 10'000, qPrintable(QString::number(totalChars(r.errors))));
    }

    // Duplicate keys are errors reported with their JSON path. Thousands of duplicates under a long key
    // must not make a message per duplicate holding that key (quadratic time and memory: found by review
    // while writing the fuzz target; 64 KiB x 100,000 duplicates would need ~13 GB).
    void manyDuplicateKeysUnderALongKey() {
        QByteArray doc = header() + "\"lights\": [], \"" + QByteArray(64 * 1024, 'k') + "\": {";
        for (int i = 0; i < 100'000; ++i)
            doc += i ? ",\"a\":0" : "\"a\":0";
        doc += "}}";
        const RigReadResult r = readRigJson(doc, QStringLiteral("dup.json"));
        QVERIFY(!r.ok());
        QVERIFY(r.errors.size() <= 202);
        QVERIFY2(r.errors.last().contains(QLatin1String("more errors not listed")),
                 qPrintable(r.errors.last().left(200)));
        QVERIFY(totalChars(r.errors) < 50'000'000);
    }

    void manyUnknownKeys() {
        QByteArray doc = header() + "\"lights\": []";
        for (int i = 0; i < 100'000; ++i)
            doc += ",\"u" + QByteArray::number(i) + "\":0";
        doc += "}";
        const RigReadResult r = readRigJson(doc, QStringLiteral("unknown.json"));
        QVERIFY(r.ok());
        QVERIFY(r.warnings.size() <= 202);
    }

    // Reproducers saved from fuzzing: each reads (or fails) without crashing, and what reads survives the
    // canonical round trip like the fuzz target demands.
    void fuzzRegressions_data() {
        QTest::addColumn<QString>("path");
        const QDir dir(QStringLiteral(LIGHTRIG_TEST_DATA "/rig/fuzz-regressions"));
        const QStringList files = dir.entryList(QDir::Files, QDir::Name);
        for (const QString& f : files)
            QTest::newRow(qPrintable(f)) << dir.filePath(f);
        if (files.isEmpty()) QTest::newRow("none yet") << QString();
    }
    void fuzzRegressions() {
        QFETCH(QString, path);
        if (path.isEmpty()) QSKIP("no fuzz reproducers saved (the fuzzer has found nothing)");
        const RigReadResult r = readRigFile(path);
        QCOMPARE(r.ok(), r.errors.isEmpty());
        if (!r.ok()) return;
        const QByteArray written = writeRigJson(*r.rig);
        const RigReadResult again = readRigJson(written, path);
        QVERIFY2(again.ok(), qPrintable(again.errors.join(u'\n')));
        QVERIFY(*again.rig == *r.rig);
        QCOMPARE(writeRigJson(*again.rig), written);
    }
};

QTEST_GUILESS_MAIN(TestReaderLimits)
#include "tst_readerlimits.moc"
