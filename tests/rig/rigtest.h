// Helpers shared by the rig file tests: small JSON builders and assertions on RigReadResult.
#pragma once

#include "core/rigjson.h"

#include <QFile>
#include <QTest>

namespace lr::test {

inline QString dataPath(const QString& relative) {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/rig/") + relative;
}

inline QByteArray readAll(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot open %s", qPrintable(path));
    return f.readAll();
}

// {"format": "lightrig", "version": 1, EXTRA "lights": [LIGHTS]}
inline QByteArray rigJson(const QByteArray& lights, const QByteArray& extra = {}) {
    return R"({"format": "lightrig", "version": 1, )" + extra + R"( "lights": [)" + lights + "]}";
}

// The same as version 2, the first that has rect and disk lights (issue 16).
inline QByteArray rigJson2(const QByteArray& lights, const QByteArray& extra = {}) {
    return R"({"format": "lightrig", "version": 2, )" + extra + R"( "lights": [)" + lights + "]}";
}

// Valid lights of each type, to which rows add or change one thing.
inline const QByteArray kPoint = R"({"type": "point", "position": [0, 1, 0], "falloff": {"model": "none"}})";
inline const QByteArray kSpot = R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0],
    "falloff": {"model": "none"}, "cone": {"model": "smooth", "inner": 20, "outer": 35}})";
inline const QByteArray kDirectional = R"({"type": "directional", "direction": [0, -1, 0]})";
inline const QByteArray kRim = R"({"type": "rim", "direction": [0, 0, 1]})";
inline const QByteArray kRect = R"({"type": "rect", "position": [0, 2, 0], "direction": [0, -1, 0]})";
inline const QByteArray kDisk = R"({"type": "disk", "position": [0, 2, 0], "direction": [0, -1, 0]})";

// light with `members` added at the end: with(kPoint, R"("cone": {})")
inline QByteArray with(const QByteArray& light, const QByteArray& members) {
    return light.left(light.lastIndexOf('}')) + ", " + members + '}';
}
inline QByteArray pointWithFalloff(const QByteArray& falloff) {
    return R"({"type": "point", "position": [0, 1, 0], "falloff": )" + falloff + '}';
}
inline QByteArray spotWithCone(const QByteArray& cone) {
    return R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "falloff": {"model": "none"}, "cone": )" +
           cone + '}';
}

inline QString describe(const RigReadResult& r) {
    return QStringLiteral("errors:\n  %1\nwarnings:\n  %2")
        .arg(r.errors.join(QStringLiteral("\n  ")), r.warnings.join(QStringLiteral("\n  ")));
}

// Whether some message is "FILE: PREFIX..." (PREFIX being "json.path: reason start").
inline bool hasMessage(const QStringList& messages, const QString& file, const QString& prefix) {
    for (const QString& m : messages)
        if (m.startsWith(file + QStringLiteral(": ") + prefix)) return true;
    return false;
}

} // namespace lr::test

#define LR_VERIFY_OK(result)                                                                                 \
    QVERIFY2((result).ok() && (result).errors.isEmpty(), qPrintable(lr::test::describe(result)))
// QCOMPARE cannot print LightRig's enums and structs (QTest::toString and lr::toString collide).
#define LR_COMPARE(actual, expected) QVERIFY2((actual) == (expected), #actual " differs from " #expected)
