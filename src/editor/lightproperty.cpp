// The light-property table's lookups (its rows are in lightproperty_rows.cpp), validation of a value, a
// light and a rig, and applying a value to a light.
#include "editor/lightproperty.h"

#include "core/fallofftraits.h"
#include "core/rigjson.h"
#include "editor/propertyvalue.h"
#include "editor/rigproperty.h"

#include <QCoreApplication>
#include <array>

namespace lr {

namespace {

using namespace propertyvalue;
using K = LightValueKind;

// Row index by id (the table is in display order, not enum order).
const std::array<int, kLightPropertyCount>& rowIndex() {
    static const std::array<int, kLightPropertyCount> index = [] {
        std::array<int, kLightPropertyCount> out{};
        out.fill(-1);
        const std::span<const LightPropertyInfo> rows = lightProperties();
        for (int i = 0; i < kLightPropertyCount; ++i)
            out[size_t(rows[size_t(i)].id)] = i;
        for (int i : out)
            Q_ASSERT_X(i >= 0, "kLightProperties", "a LightProperty has no row");
        return out;
    }();
    return index;
}

// The generic check of a row by its kind (rows with their own `check` use that instead).
QString checkByKind(const LightPropertyInfo& row, const QVariant& v) {
    QString what = row.displayName();
    if (row.unit) what += QStringLiteral(" (%1)").arg(QLatin1String(row.unit));
    switch (row.kind) {
    case K::OptionalNumber:
        if (isNone(v)) return {};
        [[fallthrough]];
    case K::Number:
        return checkRange(what, toDouble(v), row.min, row.max, row.minExclusive);
    case K::OptionalColor:
        if (isNone(v)) return {};
        [[fallthrough]];
    case K::Color:
        return checkVec3(what, toVec3(v, true), row.min, row.max);
    case K::Vector:
        return checkVec3(what, toVec3(v, false), row.min, row.max);
    default:
        return QStringLiteral("not an editable light value");
    }
}

} // namespace

QString LightPropertyInfo::displayName() const {
    return QCoreApplication::translate("lr::LightProperty", name);
}

QString LightPropertyInfo::displayLabel() const {
    return QCoreApplication::translate("lr::LightProperty", label);
}

bool LightPropertyInfo::applies(const Light& light) const {
    const LightTypeTraits& t = traitsOf(light.type);
    return (!usedBy || t.*usedBy) && (!unless || !(t.*unless));
}

bool LightPropertyInfo::isShown(const Light& light) const {
    return applies(light) && (!shown || shown(light));
}

const LightPropertyInfo* lightPropertyInfo(LightProperty p) {
    if (int(p) < 0 || int(p) >= kLightPropertyCount) return nullptr;
    return &lightProperties()[size_t(rowIndex()[size_t(p)])];
}

QString lightPropertyName(LightProperty p) {
    const LightPropertyInfo* row = lightPropertyInfo(p);
    return row ? row->displayName() : QStringLiteral("light");
}

bool lightPropertyApplies(const Light& l, LightProperty p) {
    const LightPropertyInfo* row = lightPropertyInfo(p);
    return row && row->applies(l);
}

QVariant lightValue(const Light& l, LightProperty p) {
    const LightPropertyInfo* row = lightPropertyInfo(p);
    return row ? row->get(l) : QVariant();
}

QString validateLightValue(LightProperty p, const QVariant& v) {
    const LightPropertyInfo* row = lightPropertyInfo(p);
    if (!row) return QStringLiteral("not an editable light value");
    return row->check ? row->check(*row, v) : checkByKind(*row, v);
}

QString validateLightValue(const Light& l, LightProperty p, const QVariant& v) {
    if (QString e = validateLightValue(p, v); !e.isEmpty()) return e;
    // Checks against the light's other values, on the light as it would be after the change.
    const Light after = withLightValue(l, p, v);
    const Falloff& f = after.falloff;
    if (after.usesFalloff()) {
        const FalloffTraits& t = falloffTraitsOf(f.model);
        if (!f.hasRange() && t.range == RangeRule::Required)
            return QStringLiteral("the %1 falloff needs a range").arg(toString(f.model));
        if (t.needsPositiveTerm && !(f.constant > 0 || f.linear > 0 || f.quadratic > 0))
            return QStringLiteral(
                "at least one of the constant, linear and quadratic attenuation must be > 0");
    }
    if (after.usesCone() && after.cone.model == ConeModel::Smooth && after.cone.inner > after.cone.outer)
        return p == LightProperty::ConeInner
                   ? QStringLiteral("cone inner angle must be <= the outer angle (%1°), got %2")
                         .arg(num(after.cone.outer), num(after.cone.inner))
                   : QStringLiteral("cone outer angle must be >= the inner angle (%1°), got %2")
                         .arg(num(after.cone.inner), num(after.cone.outer));
    return {};
}

QString validateLight(const Light& l) {
    for (int i = 0; i < kLightPropertyCount; ++i) {
        const auto p = LightProperty(i);
        // Names and groups from files and model imports are taken as they are (the table shows them; edits
        // are checked).
        if (p == LightProperty::Name || p == LightProperty::Group) continue;
        if (!lightPropertyApplies(l, p) && p != LightProperty::Type) continue;
        if (QString e = validateLightValue(l, p, lightValue(l, p)); !e.isEmpty())
            return QStringLiteral("light \"%1\": %2").arg(l.name, e);
    }
    return {};
}

QString checkShadowCasterCount(int casters) {
    if (casters <= kMaxShadowCasters) return {};
    return QStringLiteral("%1 lights would cast shadows; at most %2 can (one shadow map each): switch off "
                          "another light's shadow first")
        .arg(casters)
        .arg(kMaxShadowCasters);
}

QString validateRig(const Rig& r) {
    if (r.lights.size() > size_t(kMaxRigLights))
        return QStringLiteral("a rig holds at most %1 lights, got %2")
            .arg(kMaxRigLights)
            .arg(r.lights.size());
    if (QString e = checkShadowCasterCount(shadowCasterCount(r.lights)); !e.isEmpty()) return e;
    for (int i = 0; i < kRigPropertyCount; ++i)
        if (QString e = validateRigValue(RigProperty(i), rigValue(r, RigProperty(i))); !e.isEmpty()) return e;
    for (const Light& l : r.lights)
        if (QString e = validateLight(l); !e.isEmpty()) return e;
    return {};
}

Light withLightValue(const Light& light, LightProperty p, const QVariant& v) {
    Light l = light;
    if (const LightPropertyInfo* row = lightPropertyInfo(p)) row->set(l, v);
    return l;
}

} // namespace lr
