// A rect light's "barnDoors" object (docs/rig-format.md, issue 39; core/barndoors.h): the angle and length of
// its four flaps, as Unreal Engine 5's rect light defines them.
//   "barnDoors": {"angle": 45, "length": 0.3}
// Format version 4: an older reader would ignore the key with a warning and light the whole spill, so a
// rig with barn doors says version 4 and an older reader refuses it.
#include "barndoors.h"
#include "rigjson_check.h"

namespace lr::rigjson {

using json::Value;

std::optional<BarnDoors> readBarnDoors(Checker& c, const Value& v, const QString& path, int version) {
    if (version < kBarnDoorsFormatVersion) {
        c.error(path, QStringLiteral("barn doors came with version %1 of the format, but the file says "
                                     "\"version\": %2; write \"version\": %1")
                          .arg(kBarnDoorsFormatVersion)
                          .arg(version));
        return std::nullopt;
    }
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    BarnDoors b;
    if (const Value* a = o.take("angle"))
        o.keep(c.number(*a, o.path("angle"), {0.0, true, barndoors::kMaxAngle, true}), b.angle);
    if (const Value* l = o.take("length"))
        o.keep(c.number(*l, o.path("length"), nonNegative(kMaxRigLength)), b.length);
    return o.result(b);
}

QByteArray writeBarnDoors(const BarnDoors& b) {
    return "{\"angle\": " + json::formatNumber(b.angle) + ", \"length\": " + json::formatNumber(b.length) +
           '}';
}

} // namespace lr::rigjson
