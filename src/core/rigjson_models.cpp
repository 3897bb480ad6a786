// The "falloff" and "cone" objects of point and spot lights (docs/rig-format.md): which keys each model
// uses, their defaults and ranges.
#include "fallofftraits.h"
#include "rigjson_check.h"

namespace lr::rigjson {

using json::Value;

namespace {
QString quoted(const QString& s) {
    return QLatin1Char('"') + s + QLatin1Char('"');
}
} // namespace

void rejectMisplaced(ObjectView& o, bool inFalloff, bool inCone, const QString& light, bool hasFalloff,
                     bool hasCone) {
    const auto reason = [&](const char* key, const char* where, bool has) {
        if (has || light.isEmpty()) return QStringLiteral("belongs in \"%1\"").arg(QLatin1String(where));
        return QStringLiteral("%1 has no %2 (it would belong in \"%3\")")
            .arg(light, QLatin1String(key), QLatin1String(where));
    };
    if (!inFalloff)
        for (const FalloffField& field : kFalloffFields)
            if (!field.sharedKey) o.reject(field.json, reason(field.json, "falloff", hasFalloff));
    if (!inCone)
        for (const char* key : {"inner", "outer"})
            o.reject(key, reason(key, "cone", hasCone));
    if (!inFalloff && !inCone) o.reject("model", QStringLiteral("belongs in \"falloff\" or \"cone\""));
}

std::optional<Falloff> readFalloff(Checker& c, const Value& v, const QString& path) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    Falloff f;
    std::optional<FalloffModel> model;
    if (const Value* m = o.take("model"))
        model = c.enumValue<FalloffModel>(*m, o.path("model"));
    else
        c.error(o.path("model"), QStringLiteral("missing; one of %1").arg(allowedNames<FalloffModel>()));
    const QString name = model ? quoted(toString(*model)) : QString();
    // An unknown model: check the values of every field, allow all of them.
    const FalloffTraits* traits = model ? &falloffTraitsOf(*model) : nullptr;
    if (traits && traits->range == RangeRule::Required && !v.find(u"range"))
        c.error(o.path("range"), QStringLiteral("missing; the %1 falloff needs a range > 0").arg(name));
    for (const FalloffField& field : kFalloffFields) {
        if (!traits || falloffUses(traits->model, field.key)) {
            const Interval limits{field.min, !field.minExclusive, field.max, true};
            o.read(field.json, f.*field.member,
                   [&](const Value& x, const QString& p) { return c.number(x, p, limits); });
        } else {
            QString reason = QString::fromLatin1(field.absent).arg(name);
            if (reason.contains(QLatin1String("%2"))) reason = reason.arg(falloffModelsWith(field.key));
            o.reject(field.json, reason);
        }
    }
    if (traits && traits->needsPositiveTerm && f.constant == 0.0 && f.linear == 0.0 && f.quadratic == 0.0)
        c.error(path, QStringLiteral(
                          "constant, linear and quadratic are all 0: the light would be infinitely bright"));
    rejectMisplaced(o, true, false);
    o.finish();
    if (!model) return std::nullopt;
    f.model = *model;
    return f;
}

std::optional<Cone> readCone(Checker& c, const Value& v, const QString& path) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    Cone cone;
    std::optional<ConeModel> model;
    if (const Value* m = o.take("model"))
        model = c.enumValue<ConeModel>(*m, o.path("model"));
    else
        c.error(o.path("model"), QStringLiteral("missing; one of %1").arg(allowedNames<ConeModel>()));
    const QString name = model ? quoted(toString(*model)) : QString();
    const auto angle = [&](const Value& x, const QString& p) {
        return c.number(x, p, rigjson::positive(90.0));
    };
    const auto exponent = [&](const Value& x, const QString& p) {
        return c.number(x, p, rigjson::positive(kMaxRigExponent));
    };

    bool outerOk = false, innerOk = false;
    if (const Value* outer = o.take("outer")) {
        if (const auto a = angle(*outer, o.path("outer"))) cone.outer = *a, outerOk = true;
    } else {
        c.error(o.path("outer"),
                QStringLiteral("missing; the cone's half-angle in degrees, 0 < outer <= 90"));
    }
    if (!model || model == ConeModel::Smooth) {
        if (const Value* inner = o.take("inner")) {
            if (const auto a = angle(*inner, o.path("inner"))) cone.inner = *a, innerOk = true;
        } else if (model) {
            c.error(o.path("inner"),
                    QStringLiteral("missing; the \"smooth\" cone needs inner, 0 < inner <= outer"));
        }
        if (innerOk && outerOk && cone.inner > cone.outer)
            c.error(o.path("inner"), QStringLiteral("must be <= outer (%1), got %2")
                                         .arg(QString::fromLatin1(json::formatNumber(cone.outer)),
                                              QString::fromLatin1(json::formatNumber(cone.inner))));
    } else {
        o.reject("inner",
                 QStringLiteral("the %1 cone has no inner angle (only \"smooth\" has one)").arg(name));
    }
    if (model == ConeModel::Hard)
        o.reject("exponent", QStringLiteral("the \"hard\" cone has no exponent"));
    else
        o.read("exponent", cone.exponent, exponent);
    rejectMisplaced(o, false, true);
    o.finish();
    if (!model) return std::nullopt;
    cone.model = *model;
    return cone;
}

} // namespace lr::rigjson
