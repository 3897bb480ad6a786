// An area light's "area" object (docs/rig-format.md, issue 16): which keys a rect and a disk have, their
// defaults (lr::AreaShape) and ranges, and which format version introduced the types.
#include "rigjson_check.h"

#include <algorithm>

namespace lr::rigjson {

using json::Value;

int firstFormatVersion(LightType type) {
    return traitsOf(type).isArea ? 2 : 1;
}

int formatVersionFor(const Rig& rig) {
    int version = 1;
    for (const Light& l : rig.lights) {
        version = std::max({version, firstFormatVersion(l.type), l.link.isDefault() ? 1 : kLinkFormatVersion,
                            l.gobo ? kGoboFormatVersion : 1, l.ies ? kIesFormatVersion : 1});
        if (l.barnDoors && l.type == LightType::Rect) version = std::max(version, kBarnDoorsFormatVersion);
    }
    return version;
}

std::optional<AreaShape> readArea(Checker& c, const Value& v, const QString& path,
                                  std::optional<LightType> type) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    AreaShape a;
    // Unknown type: every key allowed (its values still checked).
    const bool rect = !type || traitsOf(*type).usesRectSize;
    const bool disk = !type || traitsOf(*type).usesDiskRadius;
    const QString light = type ? QStringLiteral("a %1 light").arg(toString(*type)) : QString();
    const auto size = [&](const char* key, double& out) {
        if (const Value* x = o.take(key)) o.keep(c.number(*x, o.path(key), nonNegative(kMaxRigLength)), out);
    };
    if (rect) {
        size("width", a.width);
        size("height", a.height);
    } else {
        for (const char* key : {"width", "height"})
            o.reject(key,
                     QStringLiteral("%1 has no %2: its size is \"radius\" (only %3 lights have a "
                                    "width and a height)")
                         .arg(light, QLatin1String(key), lightTypesWith(&LightTypeTraits::usesRectSize)));
    }
    if (disk)
        size("radius", a.radius);
    else
        o.reject("radius", QStringLiteral("%1 has no radius: its size is \"width\" and \"height\" (only "
                                          "%2 lights have a radius)")
                               .arg(light, lightTypesWith(&LightTypeTraits::usesDiskRadius)));
    if (const Value* r = o.take("roll"))
        o.keep(c.number(*r, o.path("roll"), {-180.0, true, 180.0, true}), a.roll);
    if (const Value* t = o.take("twoSided")) o.keep(c.boolean(*t, o.path("twoSided")), a.twoSided);
    return o.result(a);
}

} // namespace lr::rigjson
