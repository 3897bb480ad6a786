// writeRigJson: the canonical form of a rig file (docs/rig-format.md, "Canonical form"). Fixed key order,
// only the fields a light's type and models use, shortest round-trip numbers, two-space indentation,
// one light key per line, small objects and vectors on one line, a final newline.
#include "fallofftraits.h"
#include "rigjson.h"
#include "rigjson_check.h"
#include "rigjson_json.h"

#include <optional>
#include <utility>
#include <vector>

namespace lr {

namespace {

using Fields = std::vector<std::pair<const char*, QByteArray>>;

QByteArray num(double v) {
    return json::formatNumber(v);
}
QByteArray str(const QString& s) {
    return json::quote(s);
}
template <typename E> QByteArray name(E e) {
    return json::quote(toString(e));
}
QByteArray vec(const glm::dvec3& v) {
    return '[' + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ']';
}

QByteArray inlineObject(const Fields& fields) {
    QByteArray out = "{";
    for (size_t i = 0; i < fields.size(); ++i) {
        if (i) out += ", ";
        out += '"' + QByteArray(fields[i].first) + "\": " + fields[i].second;
    }
    return out + '}';
}

QByteArray blockObject(const Fields& fields, const QByteArray& indent) {
    QByteArray out = "{\n";
    for (size_t i = 0; i < fields.size(); ++i) {
        out += indent + "  \"" + fields[i].first + "\": " + fields[i].second;
        out += i + 1 < fields.size() ? ",\n" : "\n";
    }
    return out + indent + '}';
}

QByteArray falloff(const Falloff& f) {
    Fields fields{{"model", name(f.model)}};
    const FalloffTraits& t = falloffTraitsOf(f.model);
    for (int k = 0; k < t.keyCount; ++k) {
        const FalloffField& field = falloffField(t.keys[size_t(k)]);
        // An optional range is written only when the falloff has one.
        if (field.key == FalloffKey::Range && t.range == RangeRule::Optional && !f.hasRange()) continue;
        fields.push_back({field.json, num(f.*field.member)});
    }
    return inlineObject(fields);
}

QByteArray cone(const Cone& c) {
    Fields fields{{"model", name(c.model)}};
    if (c.model == ConeModel::Smooth) fields.push_back({"inner", num(c.inner)});
    fields.push_back({"outer", num(c.outer)});
    if (c.model != ConeModel::Hard) fields.push_back({"exponent", num(c.exponent)});
    return inlineObject(fields);
}

// A light's shadow is written when any value its type uses differs from lr::Shadow's defaults, and then in
// full (as falloff and cone are), so existing files without shadows stay byte-identical.
std::optional<QByteArray> shadow(const Light& l) {
    const Shadow& s = l.shadow;
    const Shadow d;
    const bool positioned = l.usesPosition();
    const bool area = l.isArea(); // its softness is its "area": neither size nor angle
    const bool isDefault = s.enabled == d.enabled && s.resolution == d.resolution && s.bias == d.bias &&
                           s.normalOffset == d.normalOffset &&
                           (area || (positioned ? s.size == d.size : s.angle == d.angle));
    if (!l.castsShadows() || isDefault) return std::nullopt;
    Fields fields{{"enabled", s.enabled ? "true" : "false"},
                  {"resolution", QByteArray::number(s.resolution)},
                  {"bias", num(s.bias)},
                  {"normalOffset", num(s.normalOffset)}};
    if (!area)
        fields.push_back(positioned ? std::pair{"size", num(s.size)} : std::pair{"angle", num(s.angle)});
    return inlineObject(fields);
}

// An area light's emitter, always written in full (as falloff and cone are): a rect's width and height or
// a disk's radius, then roll and twoSided.
QByteArray area(const Light& l) {
    const AreaShape& a = l.area;
    Fields fields;
    if (traitsOf(l.type).usesRectSize) {
        fields.push_back({"width", num(a.width)});
        fields.push_back({"height", num(a.height)});
    }
    if (traitsOf(l.type).usesDiskRadius) fields.push_back({"radius", num(a.radius)});
    fields.push_back({"roll", num(a.roll)});
    fields.push_back({"twoSided", a.twoSided ? "true" : "false"});
    return inlineObject(fields);
}

QByteArray light(const Light& l) {
    Fields f{{"name", str(l.name)},
             {"type", name(l.type)},
             {"enabled", l.enabled ? "true" : "false"},
             {"color", vec(l.color)}};
    if (!l.group.isEmpty()) f.insert(f.begin() + 1, {"group", str(l.group)});
    if (l.temperature) f.push_back({"temperature", num(*l.temperature)});
    f.push_back({"intensity", num(l.intensity)});
    if (l.usesPosition()) f.push_back({"position", vec(l.position)});
    if (l.usesDirection() || l.ies) f.push_back({"direction", vec(l.direction)}); // ies: its nadir
    if (l.usesFalloff()) f.push_back({"falloff", falloff(l.falloff)});
    if (l.usesCone()) f.push_back({"cone", cone(l.cone)});
    if (l.isArea()) f.push_back({"area", area(l)});
    if (l.usesSurfaceModels()) {
        if (l.diffuse != DiffuseModel::Lambert) f.push_back({"diffuse", name(l.diffuse)});
        if (l.specularIsColor)
            f.push_back({"specular", vec(l.specular)});
        else if (l.specular.x != 1.0)
            f.push_back({"specular", num(l.specular.x)});
        if (l.ambient) f.push_back({"ambient", vec(*l.ambient)});
    }
    if (l.usesRimExponent()) f.push_back({"exponent", num(l.rimExponent)});
    if (const auto s = shadow(l)) f.push_back({"shadow", *s});
    if (const auto k = rigjson::writeLink(l.link)) f.push_back({"link", *k});
    if (l.gobo && l.type == LightType::Spot) f.push_back({"gobo", rigjson::writeGobo(*l.gobo)});
    if (l.barnDoors && l.type == LightType::Rect)
        f.push_back({"barnDoors", rigjson::writeBarnDoors(*l.barnDoors)});
    if (l.ies) f.push_back({"ies", rigjson::writeIes(*l.ies)});
    return blockObject(f, "    ");
}

} // namespace

QByteArray writeRigJson(const Rig& rig) {
    QByteArray lights = "[]";
    if (!rig.lights.empty()) {
        lights = "[\n";
        for (size_t i = 0; i < rig.lights.size(); ++i) {
            lights += "    " + light(rig.lights[i]);
            lights += i + 1 < rig.lights.size() ? ",\n" : "\n";
        }
        lights += "  ]";
    }
    // Classic shading is the default and keeps its three keys; physically based shading has none of them.
    const Fields shading = rig.shading.model == ShadingModel::Pbr
                               ? Fields{{"model", name(rig.shading.model)}}
                               : Fields{{"specular", name(rig.shading.specular)},
                                        {"viewer", name(rig.shading.viewer)},
                                        {"shininess", num(rig.shading.shininess)}};
    Fields top{{"format", "\"lightrig\""},    {"version", QByteArray::number(rigjson::formatVersionFor(rig))},
               {"name", str(rig.name)},       {"space", name(rig.space)},
               {"ambient", vec(rig.ambient)}, {"shading", inlineObject(shading)}};
    // The ground only when not the default (off, grey), in full.
    if (rig.ground != Ground{})
        top.push_back(
            {"ground", inlineObject({{"mode", name(rig.ground.mode)}, {"color", vec(rig.ground.color)}})});
    if (const auto environment = rigjson::writeEnvironment(rig.environment))
        top.push_back({"environment", *environment});
    if (rig.view) top.push_back({"view", rigjson::writeView(*rig.view, false)});
    if (!rig.views.empty()) {
        QByteArray views = "[\n";
        for (size_t i = 0; i < rig.views.size(); ++i)
            views +=
                "    " + rigjson::writeView(rig.views[i], true) + (i + 1 < rig.views.size() ? ",\n" : "\n");
        top.push_back({"views", views + "  ]"});
    }
    top.push_back({"lights", lights});
    return blockObject(top, "") + '\n';
}

} // namespace lr
