// A light's "shadow" object and the rig's "ground" object (docs/rig-format.md, issue 14): which keys each
// has, their defaults and ranges.
#include "rigjson_check.h"

namespace lr::rigjson {

using json::Value;

std::optional<Shadow> readShadow(Checker& c, const Value& v, const QString& path,
                                 std::optional<LightType> type) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    Shadow s;
    if (const Value* e =
            o.require("enabled", QStringLiteral("missing; a shadow says \"enabled\": true or false")))
        o.keep(c.boolean(*e, o.path("enabled")), s.enabled);

    if (const Value* r = o.take("resolution")) {
        if (r->isNumber() && r->finite && isShadowResolution(r->number)) {
            s.resolution = int(r->number);
        } else {
            o.invalidate();
            const QString range = QStringLiteral("a power of two between %1 and %2")
                                      .arg(kMinShadowResolution)
                                      .arg(kMaxShadowResolution);
            if (r->isNumber())
                c.error(o.path("resolution"), QStringLiteral("%1 is not %2").arg(c.describe(*r), range));
            else
                c.expected(*r, o.path("resolution"), range);
        }
    }
    const auto texels = [&](const char* key, double& out) {
        if (const Value* x = o.take(key)) o.keep(c.number(*x, o.path(key), nonNegative(kMaxShadowBias)), out);
    };
    texels("bias", s.bias);
    texels("normalOffset", s.normalOffset);

    // The emitter's extent: a diameter for lights at a position, an angular diameter for lights at infinity.
    // An area light's softness is its own size ("area"), so its shadow has neither.
    const bool area = type && traitsOf(*type).isArea;
    const bool positioned = !type || (traitsOf(*type).usesPosition && !area);
    const bool atInfinity = !type || !traitsOf(*type).usesPosition;
    const QString light = type ? QStringLiteral("a %1 light's shadow").arg(toString(*type)) : QString();
    if (area) {
        o.reject("size",
                 QStringLiteral("%1 has no size: the light's own \"area\" softens its shadow").arg(light));
    } else if (positioned) {
        if (const Value* x = o.take("size"))
            o.keep(c.number(*x, o.path("size"), nonNegative(kMaxRigLength)), s.size);
    } else {
        o.reject("size",
                 QStringLiteral("%1 has no size: its softness is \"angle\", the emitter's angular diameter "
                                "in degrees (only %2 lights have a size)")
                     .arg(light, lightTypesWith(&LightTypeTraits::usesPosition)));
    }
    if (atInfinity) {
        if (const Value* x = o.take("angle"))
            o.keep(c.number(*x, o.path("angle"), nonNegative(kMaxShadowAngle)), s.angle);
    } else {
        o.reject("angle",
                 QStringLiteral("%1 has no angle: its softness is \"size\", the emitter's diameter in "
                                "the rig's units (only directional lights have an angle)")
                     .arg(light));
    }
    return o.result(s);
}

std::optional<Ground> readGround(Checker& c, const Value& v, const QString& path) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    Ground g;
    if (const Value* m =
            o.require("mode", QStringLiteral("missing; one of %1").arg(allowedNames<GroundMode>())))
        o.keep(c.enumValue<GroundMode>(*m, o.path("mode")), g.mode);
    if (const Value* col = o.take("color")) o.keep(c.albedo(*col, o.path("color")), g.color);
    return o.result(g);
}

} // namespace lr::rigjson
