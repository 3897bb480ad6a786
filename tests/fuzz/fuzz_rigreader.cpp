// libFuzzer target for the rig reader (scripts/fuzz builds and runs it; -DLIGHTRIG_FUZZ=ON, clang).
//
// Any input: readRigJson must return (errors or a rig) without crashing, leaking or tripping a sanitizer.
// Every rig it accepts must survive the canonical round trip: read -> write -> read gives an equal rig, and
// writing that rig again gives identical bytes (the writer is canonical, so its output is a fixed point).
#include "core/rigjson.h"

#include <QByteArray>
#include <QString>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

[[noreturn]] void fail(const char* what, const QByteArray& a, const QByteArray& b) {
    std::fprintf(stderr, "fuzz_rigreader: %s\n--- first ---\n%.*s\n--- second ---\n%.*s\n", what,
                 int(std::min<qsizetype>(a.size(), 4000)), a.constData(),
                 int(std::min<qsizetype>(b.size(), 4000)), b.constData());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const QByteArray input = QByteArray::fromRawData(reinterpret_cast<const char*>(data), qsizetype(size));
    const lr::RigReadResult first = lr::readRigJson(input, QStringLiteral("fuzz.json"));
    if (first.ok() != first.errors.isEmpty()) fail("ok() disagrees with the error list", input, QByteArray());
    if (!first.ok()) return 0;

    const QByteArray written = lr::writeRigJson(*first.rig);
    const lr::RigReadResult second = lr::readRigJson(written, QStringLiteral("fuzz-written.json"));
    if (!second.ok())
        fail(qPrintable(QStringLiteral("the written rig does not read back: ") + second.errors.join(u'\n')),
             input, written);
    if (!second.warnings.isEmpty()) fail("the written rig reads back with warnings", input, written);
    if (!(*second.rig == *first.rig)) fail("read -> write -> read changed the rig", input, written);
    const QByteArray rewritten = lr::writeRigJson(*second.rig);
    if (rewritten != written) fail("writing the re-read rig gave different bytes", written, rewritten);
    return 0;
}
