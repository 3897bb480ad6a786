// Environment images decoded in process (model/environmentdecode.h): known texel values of the small
// files in tests/data/environment (written by make_environment_data.cpp), sanitising, hostile files
// (truncated, oversized or lying headers, garbage), the bundled environments, the worker reply's
// encoding and the parent's checks of it, and the eight shared EXRs (DWAB) when /work/shared is there.
#include "model/environmentdecode.h"

#include <QDir>
#include <QFile>
#include <QTest>
#include <cmath>
#include <limits>

using namespace lr;

namespace {

const QString kData = QStringLiteral(LIGHTRIG_TEST_DATA "/environment/");

QByteArray readData(const QString& name) {
    QFile f(kData + name);
    if (!f.open(QIODevice::ReadOnly)) qFatal("missing test file %s", qPrintable(name));
    return f.readAll();
}

// Sets the dataWindow of an uncompressed EXR to (0, 0) ... (w − 1, h − 1).
QByteArray withExrSize(QByteArray exr, int w, int h) {
    const QByteArray key("dataWindow\0box2i\0", 17);
    const qsizetype at = exr.indexOf(key);
    if (at < 0) qFatal("no dataWindow");
    const qint32 box[4] = {0, 0, w - 1, h - 1};
    exr.replace(at + key.size() + 4, 16, QByteArray(reinterpret_cast<const char*>(box), 16));
    return exr;
}

// ../shared/environments beside the clone, else /work/shared/environments (a worktree elsewhere).
QString sharedEnvironmentFolder() {
    const QString beside = QStringLiteral(LIGHTRIG_SHARED_MODELS "/../environments");
    return QDir(beside).exists() ? beside : QStringLiteral("/work/shared/environments");
}

void expectError(const EnvironmentDecodeResult& r, const QString& name, const QString& reasonPart) {
    QVERIFY2(!r.ok(), qPrintable(name));
    QVERIFY(r.image.isNull());
    QVERIFY2(r.error.startsWith(QStringLiteral("could not read %1: ").arg(name)), qPrintable(r.error));
    QVERIFY2(r.error.contains(reasonPart), qPrintable(r.error + " lacks " + reasonPart));
}

} // namespace

class TestEnvironmentDecode : public QObject {
    Q_OBJECT
  private slots:
    void exrKnownValues_data() {
        QTest::addColumn<QString>("file");
        QTest::newRow("uncompressed") << "tiny.exr";
        QTest::newRow("zip, alpha") << "tiny_zip.exr";
    }
    void exrKnownValues() {
        QFETCH(QString, file);
        const EnvironmentDecodeResult r = decodeEnvironment(readData(file), file);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.image.width, 4);
        QCOMPARE(r.image.height, 2);
        QVERIFY(r.warnings.isEmpty());
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 4; ++x)
                QCOMPARE(r.image.at(x, y), glm::vec3((x + 1) / 4.0f, (y + 1) / 2.0f, 0.125f * float(x * y)));
    }
    void hdrKnownValues() {
        const EnvironmentDecodeResult flat = decodeEnvironment(readData("tiny.hdr"), "tiny.hdr");
        QVERIFY2(flat.ok(), qPrintable(flat.error));
        QCOMPARE(flat.image.width, 4);
        QCOMPARE(flat.image.height, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 4; ++x)
                QCOMPARE(flat.image.at(x, y), glm::vec3(1.0f, 0.5f, 0.25f) * std::ldexp(1.0f, x - y));
        const EnvironmentDecodeResult rle = decodeEnvironment(readData("rle.hdr"), "sky/rle.hdr");
        QVERIFY2(rle.ok(), qPrintable(rle.error));
        QCOMPARE(rle.image.width, 16);
        for (int x = 0; x < 16; ++x) {
            QCOMPARE(rle.image.at(x, 0), glm::vec3(1.0f, 0.5f, 0.25f));
            QCOMPARE(rle.image.at(x, 1), glm::vec3(1.0f, 0.5f, 2.0f));
        }
        // 16 × 2 is not 2:1: accepted, with a warning naming the file.
        QCOMPARE(rle.warnings.size(), 1);
        QVERIFY2(rle.warnings[0].startsWith("rle.hdr: 16×2 is not 2:1"), qPrintable(rle.warnings[0]));
    }
    // Issue 41: a header with CRLF line ends (written on Windows) decodes as the LF one; it was refused as
    // "its Radiance header does not end". The pixels after the resolution line are binary and kept.
    void hdrWithCrlfHeader() {
        for (const QString file : {"tiny.hdr", "rle.hdr"}) {
            const QByteArray lf = readData(file);
            const qsizetype blank = lf.indexOf("\n\n");
            const qsizetype headerEnd = lf.indexOf('\n', blank + 2) + 1;
            QVERIFY(blank > 0 && headerEnd > blank);
            const QByteArray crlf = lf.first(headerEnd).replace("\n", "\r\n") + lf.sliced(headerEnd);
            const EnvironmentDecodeResult want = decodeEnvironment(lf, file);
            const EnvironmentDecodeResult got = decodeEnvironment(crlf, file);
            QVERIFY2(got.ok(), qPrintable(got.error));
            QCOMPARE(got.image.width, want.image.width);
            QCOMPARE(got.image.height, want.image.height);
            QVERIFY(got.image.texels == want.image.texels);
        }
    }
    void sanitised() {
        const EnvironmentDecodeResult r = decodeEnvironment(readData("nonfinite.exr"), "sky.exr");
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.warnings, (QStringList{"sky.exr: 2 texels were NaN or infinite and were set to 0",
                                          "sky.exr: 1 texels were negative (down to -1) and were set to 0"}));
        QCOMPARE(r.image.at(1, 0), glm::vec3(0.0f, 2.0f, 3.0f));
        QCOMPARE(r.image.at(2, 0), glm::vec3(1.0f, 0.0f, 3.0f));
        QCOMPARE(r.image.at(3, 1), glm::vec3(1.0f, 2.0f, 0.0f));
        QCOMPARE(r.image.at(0, 0), glm::vec3(1.0f, 2.0f, 3.0f));
        QVERIFY(checkEnvironmentImage(r.image).isEmpty());
    }
    void truncated() {
        for (const QString file : {"tiny.exr", "tiny_zip.exr", "tiny.hdr", "rle.hdr"}) {
            const QByteArray bytes = readData(file);
            for (const qsizetype keep : {qsizetype(3), bytes.size() / 2, bytes.size() - 1}) {
                const EnvironmentDecodeResult r = decodeEnvironment(bytes.left(keep), file);
                expectError(r, file, {});
            }
        }
    }
    void truncatedRunLengthData() {
        // 16 × 2, each channel a literal run of 16 bytes: 72 bytes a scanline, far above the header's
        // lower bound, so the end of the data is noticed while decoding, not before.
        QByteArray hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 16\n";
        for (int y = 0; y < 2; ++y) {
            hdr += QByteArray("\2\2\0\20", 4);
            for (int c = 0; c < 4; ++c)
                hdr += char(16) + QByteArray(16, char(c == 3 ? 129 : 100));
        }
        QVERIFY(decodeEnvironment(hdr, "whole.hdr").ok());
        QCOMPARE(decodeEnvironment(hdr, "whole.hdr").image.at(5, 1), glm::vec3(100.0f / 128.0f));
        expectError(decodeEnvironment(hdr.chopped(30), "cut.hdr"), "cut.hdr",
                    "the file ends before its pixel data does");
    }
    void oversizedHeaders() {
        expectError(decodeEnvironment(withExrSize(readData("tiny.exr"), 100000, 50000), "huge.exr"),
                    "huge.exr", "larger than the limit of 16384");
        expectError(decodeEnvironment(withExrSize(readData("tiny.exr"), 8192, 4096), "big.exr"), "big.exr",
                    "the header claims 8192×4096 texels but the file holds only");
        expectError(decodeEnvironment(withExrSize(readData("tiny.exr"), 16384, 8192), "mpx.exr"), "mpx.exr",
                    "more than the limit of 64 Mpx");
        const QByteArray hdr =
            "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 50000 +X 100000\n" + QByteArray(64, '\2');
        expectError(decodeEnvironment(hdr, "huge.hdr"), "huge.hdr", "larger than the limit of 16384");
        const QByteArray lying =
            "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1000 +X 2000\n" + QByteArray(64, '\2');
        expectError(decodeEnvironment(lying, "lying.hdr"), "lying.hdr",
                    "the header claims 2000×1000 texels but the file holds only");
    }
    // Issue 41: a 457-byte DWAB header claiming 64 Mpx made the worker allocate 793 MB before it found the
    // data missing. A header claiming more than 256 decoded bytes per byte of file is refused first.
    void headerClaimsMoreThanTheFileCanHold() {
        QByteArray exr = withExrSize(readData("tiny.exr"), 4096, 2048);
        const QByteArray key("compression\0compression\0", 24);
        const qsizetype at = exr.indexOf(key);
        QVERIFY(at >= 0);
        exr[at + key.size() + 4] = char(9); // DWAB: 256 scanlines a chunk, so 8 chunk offsets suffice
        expectError(decodeEnvironment(exr, "lying.exr"), "lying.exr",
                    QStringLiteral("the header claims 4096×2048 texels (96 MiB decoded) but the file holds "
                                   "only %1 bytes (at most 256 bytes decoded per byte of file are accepted)")
                        .arg(exr.size()));
    }
    // Issue 41: radiance of 1e35 ... 3.4e38 is finite but overflowed to inf when filtered.
    void overflowingRadianceIsClamped() {
        QByteArray hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
        hdr += QByteArray("\x96\x96\x96\xff\x80\x40\x20\x81", 8); // 1.2e38 grey, then (1, 0.5, 0.25)
        const EnvironmentDecodeResult r = decodeEnvironment(hdr, "sun.hdr");
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.warnings.first(), QStringLiteral("sun.hdr: 1 texels were brighter than 1e+10 and were "
                                                    "clamped to it (brighter values overflow when the "
                                                    "environment is filtered)"));
        QCOMPARE(r.image.at(0, 0), glm::vec3(kMaxEnvironmentRadiance));
        QCOMPARE(r.image.at(1, 0), glm::vec3(1.0f, 0.5f, 0.25f));
        QVERIFY(checkEnvironmentImage(r.image).isEmpty());
        EnvironmentImage bright = r.image;
        bright.texels[0].r = 1e35f;
        QVERIFY(checkEnvironmentImage(bright).contains("above the limit"));
    }
    void garbage() {
        expectError(decodeEnvironment(QByteArray(4096, '\x5a'), "junk.exr"), "junk.exr",
                    "not an OpenEXR or Radiance");
        expectError(decodeEnvironment(QByteArray(), "empty.hdr"), "empty.hdr", "not an OpenEXR or Radiance");
        QByteArray exr = readData("tiny_zip.exr");
        for (qsizetype i = exr.size() - 40; i < exr.size(); ++i)
            exr[i] = char(0xa5);
        const EnvironmentDecodeResult r = decodeEnvironment(exr, "noisy.exr");
        QVERIFY2(!r.ok() || checkEnvironmentImage(r.image).isEmpty(),
                 "a corrupt file either fails or is sane");
        expectError(decodeEnvironment("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X\n", "bad.hdr"),
                    "bad.hdr", "resolution line");
        expectError(decodeEnvironmentFile(kData + "absent.exr"), kData + "absent.exr", {});
    }
    void builtins() {
        const QStringList names = builtinEnvironmentNames();
        QVERIFY2(names.contains("studio") && names.contains("courtyard"), qPrintable(names.join(',')));
        for (const QString& name : names) {
            const EnvironmentDecodeResult r = decodeBuiltinEnvironment(name);
            QVERIFY2(r.ok(), qPrintable(r.error));
            QCOMPARE(r.image.width, 1024);
            QCOMPARE(r.image.height, 512);
            QVERIFY(checkEnvironmentImage(r.image).isEmpty());
            // Issue 41: studio.exr warned "3 texels were NaN, infinite or negative" on every load; they
            // are DWAB's ringing (down to -3e-6), set to 0 without a word.
            QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join('\n')));
        }
        expectError(decodeBuiltinEnvironment("nope"), "builtin:nope",
                    "no bundled environment is called \"nope\"");
    }
    void replyCodec() {
        const EnvironmentDecodeResult tiny = decodeEnvironment(readData("tiny.exr"), "tiny.exr");
        const QByteArray reply = encodeEnvironmentReply(tiny.image, {"a", "b"});
        EnvironmentImage image;
        QStringList warnings;
        QString why;
        QVERIFY(decodeEnvironmentReply(reply, &image, &warnings, &why));
        QCOMPARE(image.texels, tiny.image.texels);
        QCOMPARE(warnings, (QStringList{"a", "b"}));
        QVERIFY(!decodeEnvironmentReply(reply.chopped(1), &image, &warnings, &why));
        QVERIFY2(why.contains("bytes for an environment of 4×2"), qPrintable(why));
        QVERIFY(!decodeEnvironmentReply(reply + "x", &image, &warnings, &why));
        EnvironmentImage bad = tiny.image;
        bad.texels[5].g = -std::numeric_limits<float>::infinity();
        QVERIFY(!decodeEnvironmentReply(encodeEnvironmentReply(bad, {}), &image, &warnings, &why));
        QVERIFY2(why.contains("not finite and >= 0"), qPrintable(why));
        bad.texels[5].g = -0.5f;
        QVERIFY(!decodeEnvironmentReply(encodeEnvironmentReply(bad, {}), &image, &warnings, &why));
        QByteArray huge = reply;
        const quint32 side = 20000;
        std::memcpy(huge.data(), &side, 4);
        QVERIFY(!decodeEnvironmentReply(huge, &image, &warnings, &why));
        QVERIFY(!decodeEnvironmentReply(QByteArray(5, '\0'), &image, &warnings, &why));
        QCOMPARE(image.texels, tiny.image.texels); // untouched by the failures
    }
    void sharedEnvironments() {
        const QDir dir(sharedEnvironmentFolder());
        const QStringList files = dir.entryList({"*.exr"}, QDir::Files, QDir::Name);
        if (files.isEmpty())
            QSKIP("no shared environments (LIGHTRIG_SHARED_MODELS/../environments, /work/shared)");
        QCOMPARE(files.size(), 8);
        for (const QString& file : files) {
            const EnvironmentDecodeResult r = decodeEnvironmentFile(dir.filePath(file));
            QVERIFY2(r.ok(), qPrintable(r.error));
            QCOMPARE(r.image.width, 1024);
            QCOMPARE(r.image.height, 512);
            QVERIFY(checkEnvironmentImage(r.image).isEmpty());
            double sum = 0.0;
            for (const glm::vec3& t : r.image.texels)
                sum += t.r + t.g + t.b;
            QVERIFY2(sum > 0.0, qPrintable(file)); // not decoded as black
        }
    }
};

QTEST_GUILESS_MAIN(TestEnvironmentDecode)
#include "tst_environmentdecode.moc"
