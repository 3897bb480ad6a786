// Robustness of the reader on damaged input: a hundred thousand seeded random mutations of real rig
// files (presets, test data) never crash or hang, always answer consistently (a rig xor errors, every
// message naming the file), and whatever loads saves and reloads unchanged. Run it under
// -DLIGHTRIG_SANITIZE=address,undefined to catch memory errors too.
#include "rigtest.h"

#include <QDir>
#include <QRandomGenerator>

using namespace lr;
using namespace lr::test;

namespace {
const QByteArray kTokens[] = {
    "{",
    "}",
    "[",
    "]",
    ",",
    ":",
    "\"",
    "\\",
    "\\u",
    "\\ud800",
    "\\udc00",
    "1e999",
    "-1e-400",
    "-",
    "0",
    "01",
    "1.",
    ".5",
    "null",
    "true",
    "NaN",
    "-Infinity",
    "\xff",
    "\xc3",
    "\xe2\x82",
    "\x00",
    "\"range\": -1, ",
    "\"type\": \"rim\", ",
    "\"name\": \"n\", ",
    "\"cone\": {}, ",
    "\"falloff\": {\"model\": \"none\"}, ",
    "\"inner\": 90, ",
    "\"version\": 2, ",
    "\"shadow\": {\"enabled\": true}, ",
    "\"shadow\": {\"enabled\": true, \"resolution\": 3000, \"angle\": 1}, ",
    "\"size\": 0.5, ",
    "\"ground\": {\"mode\": \"catcher\"}, ",
    "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[",
    "\t",
    "\n",
    " ",
};

QByteArray mutate(QByteArray data, QRandomGenerator& rng) {
    const int edits = 1 + int(rng.bounded(4));
    for (int e = 0; e < edits; ++e) {
        const qsizetype at = data.isEmpty() ? 0 : qsizetype(rng.bounded(int(data.size())));
        switch (rng.bounded(6)) {
        case 0: // flip a byte
            if (!data.isEmpty()) data[at] = char(rng.bounded(256));
            break;
        case 1: // delete a run
            data.remove(at, qsizetype(rng.bounded(16)));
            break;
        case 2: // duplicate a run
            data.insert(at, data.mid(at, qsizetype(rng.bounded(64))));
            break;
        case 3: { // insert a token
            const QByteArray& t = kTokens[rng.bounded(int(std::size(kTokens)))];
            data.insert(at, t.isEmpty() ? QByteArray(1, '\0') : t);
            break;
        }
        case 4: // truncate
            data.truncate(at);
            break;
        default: { // swap a digit for another number
            const qsizetype d = data.indexOf(QByteArrayView("0123456789").at(rng.bounded(10)), at);
            if (d >= 0) data.replace(d, 1, QByteArray::number(rng.generateDouble() * 2e3 - 1e3, 'g', 17));
        }
        }
    }
    return data;
}
} // namespace

class TestRigMutate : public QObject {
    Q_OBJECT
  private slots:
    void mutatedFiles();
};

void TestRigMutate::mutatedFiles() {
    QList<QByteArray> seeds;
    for (const QString& name : builtinPresetNames())
        seeds << readAll(builtinPresetPath(name));
    for (const char* dir : {"good", "bad"}) {
        const QDir d(dataPath(QString::fromLatin1(dir)));
        for (const QString& f : d.entryList({QStringLiteral("*.json")}, QDir::Files))
            seeds << readAll(d.filePath(f));
    }
    QVERIFY(seeds.size() > 30);
    QRandomGenerator rng(4242);
    const QString file = QStringLiteral("m.json");
    int loaded = 0;
    constexpr int kRuns = 100000;
    for (int i = 0; i < kRuns; ++i) {
        const QByteArray data = mutate(seeds[rng.bounded(int(seeds.size()))], rng);
        const RigReadResult r = readRigJson(data, file);
        QVERIFY(r.ok() == r.errors.isEmpty());
        QVERIFY(r.errors.size() <= 201 && r.warnings.size() <= 201);
        for (const QString& m : r.errors + r.warnings)
            QVERIFY2(m.startsWith(file + QStringLiteral(": ")) && m.size() > file.size() + 2, qPrintable(m));
        if (!r.ok()) continue;
        ++loaded;
        const QByteArray saved = writeRigJson(*r.rig);
        const RigReadResult again = readRigJson(saved, file);
        QVERIFY2(again.ok() && again.warnings.isEmpty(), qPrintable(describe(again)));
        QVERIFY2(*again.rig == *r.rig, saved.constData());
        QCOMPARE(writeRigJson(*again.rig), saved);
    }
    // The mix must exercise both outcomes, or the test checks little.
    QVERIFY2(loaded > kRuns / 200 && loaded < kRuns / 2, qPrintable(QString::number(loaded)));
}

QTEST_GUILESS_MAIN(TestRigMutate)
#include "tst_rigmutate.moc"
