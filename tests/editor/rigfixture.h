// Rigs for the editor tests, built in code (independent of the presets).
#pragma once

#include "core/rig.h"
#include "core/rigjson.h"
#include "editor/document.h"

#include <QStringList>
#include <QTest>

// QTest's QCOMPARE prints values with toString(); lr::toString<E> (types.h) is an unconstrained template that
// would make the call ambiguous for every type in namespace lr, so these exact overloads win.
namespace lr {
inline char* toString(const Rig& rig) {
    return qstrdup(writeRigJson(rig).constData());
}
inline char* toString(const Light& light) {
    Rig rig;
    rig.lights.push_back(light);
    return toString(rig);
}
inline char* toString(const Cone& c) {
    return qstrdup(QStringLiteral("cone(%1, %2, %3, %4)")
                       .arg(int(c.model))
                       .arg(c.inner)
                       .arg(c.outer)
                       .arg(c.exponent)
                       .toUtf8()
                       .constData());
}
inline char* toString(LightType v) {
    return qstrdup(QByteArray::number(int(v)).constData());
}
inline char* toString(LightProperty v) {
    return qstrdup(QByteArray::number(int(v)).constData());
}
inline char* toString(RigProperty v) {
    return qstrdup(QByteArray::number(int(v)).constData());
}
inline char* toString(RigChange::Kind v) {
    return qstrdup(QByteArray::number(int(v)).constData());
}
} // namespace lr

namespace lrtest {

// Six lights covering every type and the main falloff/cone models, unique names L0..L5.
inline lr::Rig sampleRig() {
    using namespace lr;
    Rig rig;
    rig.name = QStringLiteral("Sample");
    rig.ambient = glm::dvec3(0.03);
    Light p = makeLight(LightType::Point, QStringLiteral("L0"));
    p.position = {1, 2, 3};
    Light s = makeLight(LightType::Spot, QStringLiteral("L1"));
    s.cone = {ConeModel::Smooth, 20, 35, 1};
    Light d = makeLight(LightType::Directional, QStringLiteral("L2"));
    d.diffuse = DiffuseModel::HalfLambert;
    Light r = makeLight(LightType::Rim, QStringLiteral("L3"));
    Light q = makeLight(LightType::Point, QStringLiteral("L4"));
    q.falloff = {FalloffModel::InversePolynomial, -1.0, 2.0, 0.0, 0.1, 0.0};
    q.color = {0.6, 0.7, 1.0};
    Light h = makeLight(LightType::Spot, QStringLiteral("L5"));
    h.cone = {ConeModel::Hard, 20, 30, 1};
    h.falloff = {FalloffModel::InverseSquare, -1.0, 2.0, 1.0, 0.0, 0.0};
    rig.lights = {p, s, d, r, q, h};
    return rig;
}

// n point lights named P0..P(n-1).
inline lr::Rig pointRig(int n) {
    lr::Rig rig;
    rig.lights.reserve(size_t(n));
    for (int i = 0; i < n; ++i) {
        lr::Light l = lr::makeLight(lr::LightType::Point, QStringLiteral("P%1").arg(i));
        l.position = {double(i), 0.0, 0.0};
        rig.lights.push_back(l);
    }
    return rig;
}

inline QByteArray bytes(const lr::Document& doc) {
    return lr::writeRigJson(doc.rig());
}

// Pushes through `push`, then checks: one new undo step; undo gives the exact old bytes; redo the new
// ones; a second undo/redo cycle too (commands must be repeatable).
template <typename F> void checkDoUndoRedo(lr::Document& doc, F push) {
    const QByteArray before = bytes(doc);
    const int count = doc.undoStack()->count();
    QVERIFY(push());
    QCOMPARE(doc.undoStack()->count(), count + 1);
    const QByteArray after = bytes(doc);
    QVERIFY2(after != before, "the command changed nothing");
    for (int cycle = 0; cycle < 2; ++cycle) {
        doc.undoStack()->undo();
        QCOMPARE(bytes(doc), before);
        doc.undoStack()->redo();
        QCOMPARE(bytes(doc), after);
    }
}

inline QStringList names(const lr::Document& doc) {
    QStringList out;
    for (const lr::Light& l : doc.rig().lights)
        out << l.name;
    return out;
}

} // namespace lrtest
