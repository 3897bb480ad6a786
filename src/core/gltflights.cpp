#include "gltflights.h"

#include "rigjson.h"

#include <QJsonDocument>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <numbers>

namespace lr {

const ExportLossInfo kExportLosses[int(ExportLoss::Count)] = {
    {ExportLoss::ClassicUnits, "classic-units", "Classic intensities",
     "classic shading has no physical units: intensity × π read as candela (point, spot) or lux "
     "(directional), which lights a white Lambert surface as the classic light did"},
    {ExportLoss::Falloff, "falloff", "Falloff",
     "glTF's inverse-square falloff (with the light's range window, when it has a range), as bright as the "
     "original at the model's centre"},
    {ExportLoss::Cone, "cone", "Spot cone", "glTF's smooth cone (exponent 2) with the same outer angle"},
    {ExportLoss::HalfLambert, "half-lambert", "Half-Lambert diffuse", "Lambert (N·L)"},
    {ExportLoss::Specular, "specular", "Specular factor", "the light's colour (factor 1)"},
    {ExportLoss::LightAmbient, "light-ambient", "Light ambient",
     "nothing (glTF lights have no ambient term)"},
    {ExportLoss::Rim, "rim", "Rim light", "nothing (glTF has no rim light)"},
    {ExportLoss::Area, "area", "Area light", "a point (glTF has no area lights)"},
    {ExportLoss::AreaLight, "area-light", "Rect or disk light",
     "a spot of luminance × area candela at its centre along its axis with a 90° cone (two-sided: a point "
     "light of half that, the same flux); exact far away on its axis, cos² θ off it where the emitter has "
     "cos θ"},
    {ExportLoss::Shadow, "shadow", "Shadow", "nothing (KHR_lights_punctual lights carry no shadow settings)"},
    {ExportLoss::Disabled, "disabled", "Switched-off light", "nothing (glTF lights cannot be switched off)"},
    {ExportLoss::Ambient, "ambient", "Ambient",
     "a note in extras.lightrig.ambient (glTF has no ambient light)"},
    {ExportLoss::Environment, "environment", "Environment",
     "a note in extras.lightrig.environment (glTF has no environment lighting)"},
    {ExportLoss::Ground, "ground", "Ground", "a note in extras.lightrig.ground (the plane is not exported)"},
    {ExportLoss::Link, "link", "Linking",
     "the rig's \"link\" in the light node's extras.lightrig.link (glTF lights light every part and every "
     "part casts their shadows; other viewers ignore it)"},
    {ExportLoss::Gobo, "gobo", "Gobo",
     "the rig's \"gobo\" in the light node's extras.lightrig.gobo (the spot lights its whole cone in "
     "other viewers; the image file is named, not embedded)"},
    {ExportLoss::BarnDoors, "barn-doors", "Barn doors",
     "the rig's \"barnDoors\" in the light node's extras.lightrig.barnDoors (the stand-in spot lights its "
     "whole "
     "90° cone; other viewers ignore it)"},
    {ExportLoss::Ies, "ies", "IES profile",
     "EXT_lights_ies on the light's node in place of its KHR_lights_punctual light: the file's candela × "
     "multiplier with inverse-square falloff (a spot's cone and a falloff's range are not applied; viewers "
     "without EXT_lights_ies show no light there)"},
};

const ExportLossInfo& exportLossInfo(ExportLoss kind) {
    return kExportLosses[int(kind)];
}

QString describeLoss(const LossyConversion& loss) {
    const ExportLossInfo& info = exportLossInfo(loss.kind);
    return QStringLiteral("%1: %2: %3 → %4")
        .arg(loss.subject, QString::fromUtf8(info.title).toLower(), loss.detail,
             QString::fromUtf8(info.written));
}

namespace {

QJsonArray array3(const glm::dvec3& v) {
    return {v.x, v.y, v.z};
}

QString num(double v) {
    return QString::number(v, 'g', 4);
}

// The falloff's own text for messages: "range-power (range 8, exponent 2)".
QString falloffText(const Falloff& f) {
    QString s = toString(f.model);
    QStringList keys;
    if (f.model == FalloffModel::InversePolynomial)
        keys << QStringLiteral("constant %1, linear %2, quadratic %3")
                    .arg(num(f.constant), num(f.linear), num(f.quadratic));
    if (f.hasRange()) keys << QStringLiteral("range %1").arg(num(f.range));
    if (f.model == FalloffModel::RangePower) keys << QStringLiteral("exponent %1").arg(num(f.exponent));
    return keys.isEmpty() ? s : s + QStringLiteral(" (") + keys.join(QStringLiteral(", ")) + QLatin1Char(')');
}

// A non-glTF falloff as inverse-square with the light's range: the intensity that gives the original's
// attenuation at the reference distance (world units), and that distance.
void convertFalloff(const Rig& rig, const SceneFrame& frame, const Light& l, const glm::dvec3& worldPos,
                    double intensity, GltfLight& g, std::vector<LossyConversion>& losses) {
    const Falloff& f = l.falloff;
    const double s = distanceScale(rig, frame); // rig units per world unit
    g.range = f.hasRange() ? f.range / s : -1.0;
    if (f.model == FalloffModel::InverseSquare) {
        g.intensity = intensity / (s * s); // 1/d² with d in rig units
        return;
    }
    const double radius = frame.radius > 0.0 && std::isfinite(frame.radius) ? frame.radius : 1.0;
    double dRef = glm::length(worldPos - frame.center);
    if (g.range > 0.0) dRef = std::min(dRef, 0.5 * g.range);
    dRef = std::max(dRef, 0.01 * radius);
    lighting::ShadeLight<double> sl;
    sl.falloff = f.model;
    sl.range = f.range, sl.falloffExponent = f.exponent;
    sl.constant = f.constant, sl.linear = f.linear, sl.quadratic = f.quadratic;
    const double a = lighting::evalFalloff(sl, dRef * s);
    const double w = g.range > 0.0 ? lighting::rangeWindow(dRef, g.range) : 1.0;
    g.intensity = w > 0.0 ? intensity * a * dRef * dRef / w : 0.0;
    losses.push_back({ExportLoss::Falloff, l.name,
                      QStringLiteral("%1 at %2 m from the model's centre").arg(falloffText(f), num(dRef))});
}

void convertCone(const Light& l, GltfLight& g, std::vector<LossyConversion>& losses) {
    const Cone& c = l.cone;
    const double outer = glm::radians(std::clamp(c.outer, 0.0, 90.0));
    double inner = glm::radians(std::clamp(c.inner, 0.0, c.outer));
    QString was;
    switch (c.model) {
    case ConeModel::Smooth:
        if (c.exponent != 2.0)
            was = QStringLiteral("smooth %1°/%2°, exponent %3")
                      .arg(num(c.inner), num(c.outer), num(c.exponent));
        break;
    case ConeModel::AnglePower:
        inner = 0.0;
        was = QStringLiteral("angle-power %1°, exponent %2").arg(num(c.outer), num(c.exponent));
        break;
    case ConeModel::Hard:
        inner = outer * 0.99;
        was = QStringLiteral("hard %1° (a 1% soft edge)").arg(num(c.outer));
        break;
    }
    // glTF needs inner < outer: an edge LightRig draws hard (inner = outer) gets the narrowest soft one.
    if (!(inner < outer * 0.999)) {
        inner = outer * 0.999;
        if (was.isEmpty()) was = QStringLiteral("hard edge at %1° (a 0.1% soft edge)").arg(num(c.outer));
    }
    g.innerConeAngle = inner;
    g.outerConeAngle = outer;
    if (!was.isEmpty()) losses.push_back({ExportLoss::Cone, l.name, was});
}

// A rect or disk light as KHR_lights_punctual can hold it (kExportLosses' area-light row). Far from a
// Lambertian emitter of luminance L and area A its intensity is L·A·cos θ (candela, A in world units² read
// as m²): a spot of L·A with a 90° cone (inner 0: glTF's cone gives cos² θ) at its centre along its axis; a
// two-sided one emits to both sides, a point light of L·A/2 (the same total flux, 2πLA). Its intensity means
// the same under both shadings (lighting_area.h's 1/π under classic is the Lambert lobe's): no × π.
GltfLight areaStandIn(const Rig& rig, const SceneFrame& frame, const glm::dmat3& fileFromWorld,
                      const Light& l, std::vector<LossyConversion>& losses) {
    const double s = distanceScale(rig, frame); // rig units per world unit
    const bool disk = l.type == LightType::Disk;
    const double area =
        (disk ? std::numbers::pi * l.area.radius * l.area.radius : l.area.width * l.area.height) / (s * s);
    GltfLight g;
    g.name = l.name;
    g.translation = fileFromWorld * rigToWorld(rig, frame, l.position);
    g.rotation = lookRotation(fileFromWorld * l.direction, fileFromWorld * glm::dvec3(0, 1, 0));
    const glm::dvec3 c = glm::max(l.effectiveColor(), glm::dvec3(0.0));
    const double m = std::max({c.x, c.y, c.z});
    g.color = m > 0.0 ? c / m : glm::dvec3(0.0);
    const double intensity = l.intensity * (m > 0.0 ? m : 1.0) * area;
    if (l.area.twoSided) {
        g.type = QStringLiteral("point");
        g.intensity = 0.5 * intensity;
    } else {
        g.type = QStringLiteral("spot");
        g.intensity = intensity;
        g.innerConeAngle = 0.0;
        g.outerConeAngle = std::numbers::pi / 2.0;
    }
    const QString size = disk ? QStringLiteral("radius %1").arg(num(l.area.radius))
                              : QStringLiteral("%1 × %2").arg(num(l.area.width), num(l.area.height));
    losses.push_back(
        {ExportLoss::AreaLight, l.name,
         QStringLiteral("%1 %2%3 at %4 nits: a %5 of %6 cd")
             .arg(toString(l.type), size, l.area.twoSided ? QStringLiteral(" two-sided") : QString(),
                  num(l.intensity), g.type, num(g.intensity))});
    if (l.diffuse == DiffuseModel::HalfLambert)
        losses.push_back({ExportLoss::HalfLambert, l.name, QStringLiteral("half-lambert")});
    if (l.specularIsColor || l.specular.x != 1.0)
        losses.push_back(
            {ExportLoss::Specular, l.name, QStringLiteral("specular %1").arg(num(l.specular.x))});
    if (l.ambient && *l.ambient != glm::dvec3(0.0))
        losses.push_back({ExportLoss::LightAmbient, l.name, QStringLiteral("its own ambient")});
    if (l.hasShadow()) losses.push_back({ExportLoss::Shadow, l.name, QStringLiteral("casts a shadow")});
    return g;
}

// A light's "link" as the rig file writes it, and what it links for the loss's detail.
QJsonObject linkJson(const LightLink& link) {
    const auto lists = [](const PartSet& s) {
        QJsonObject o;
        if (!s.include.isEmpty()) o.insert(QStringLiteral("include"), QJsonArray::fromStringList(s.include));
        if (!s.exclude.isEmpty()) o.insert(QStringLiteral("exclude"), QJsonArray::fromStringList(s.exclude));
        return o;
    };
    QJsonObject o = lists(link.lit);
    if (!link.shadow.isEverything()) o.insert(QStringLiteral("shadow"), lists(link.shadow));
    return o;
}

void noteLink(const Light& l, GltfLight* g, std::vector<LossyConversion>& losses) {
    if (l.link.isDefault()) return;
    QStringList what;
    if (!l.link.lit.isEverything()) what << QStringLiteral("lights only some parts");
    if (!l.link.shadow.isEverything()) what << QStringLiteral("only some parts cast its shadow");
    losses.push_back({ExportLoss::Link, l.name, what.join(QStringLiteral(", "))});
    if (g) g->link = linkJson(l.link);
}

// The rig's settings glTF has no place for, as their rig-file JSON (the note in extras.lightrig).
QJsonObject noteFor(const Rig& rig, double unit) {
    const QJsonObject file = QJsonDocument::fromJson(writeRigJson(rig)).object();
    QJsonObject note{{QStringLiteral("generator"), QStringLiteral("LightRig")},
                     {QStringLiteral("rig"), rig.name},
                     {QStringLiteral("shading"), toString(rig.shading.model)},
                     {QStringLiteral("ambientLux"), array3(rig.ambient * unit)}};
    for (const char* key : {"environment", "ground"})
        if (file.contains(QLatin1String(key)))
            note.insert(QLatin1String(key), file.value(QLatin1String(key)));
    return note;
}

} // namespace

glm::dquat lookRotation(const glm::dvec3& forward, const glm::dvec3& up) {
    const glm::dvec3 f = lighting::safeNormalize(forward, glm::dvec3(0, 0, -1));
    glm::dvec3 right = glm::cross(f, up);
    if (!(glm::dot(right, right) > 1e-12))
        right = glm::cross(f, std::abs(f.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, -1));
    right = glm::normalize(right);
    const glm::dvec3 trueUp = glm::cross(right, f);
    return glm::normalize(glm::quat_cast(glm::dmat3(right, trueUp, -f)));
}

GltfRigExport convertRigToGltf(const Rig& rig, const SceneFrame& frame, const glm::dmat3& fileFromWorld) {
    GltfRigExport out;
    const bool classic = rig.shading.model == ShadingModel::Classic;
    const double unit = classic ? kClassicToPhysical : 1.0;
    const QString rigSubject = QStringLiteral("rig");
    if (classic && !rig.lights.empty())
        out.losses.push_back({ExportLoss::ClassicUnits, rigSubject, QStringLiteral("shading \"classic\"")});
    for (const Light& l : rig.lights) {
        if (l.isArea() && l.enabled) {
            GltfLight g = areaStandIn(rig, frame, fileFromWorld, l, out.losses);
            noteLink(l, &g, out.losses);
            if (l.type == LightType::Rect && l.barnDoors) { // issue 39: kept for LightRig, listed as lost
                g.barnDoors = QJsonObject{{QStringLiteral("angle"), l.barnDoors->angle},
                                          {QStringLiteral("length"), l.barnDoors->length}};
                out.losses.push_back({ExportLoss::BarnDoors, l.name,
                                      QStringLiteral("angle %1°, length %2")
                                          .arg(num(l.barnDoors->angle), num(l.barnDoors->length))});
            }
            out.lights.push_back(g);
            continue;
        }
        if (l.type == LightType::Rim) {
            out.losses.push_back(
                {ExportLoss::Rim, l.name, QStringLiteral("exponent %1").arg(num(l.rimExponent))});
            continue;
        }
        if (!l.enabled) {
            out.losses.push_back({ExportLoss::Disabled, l.name, QStringLiteral("switched off")});
            continue;
        }
        GltfLight g;
        g.name = l.name;
        g.type = QString::fromLatin1(traitsOf(l.type).gltfType);
        const double intensity = l.intensity * unit;
        g.intensity = intensity;
        const glm::dvec3 worldPos = rigToWorld(rig, frame, l.position);
        if (l.usesPosition()) g.translation = fileFromWorld * worldPos;
        if (l.usesDirection())
            g.rotation = lookRotation(fileFromWorld * l.direction, fileFromWorld * glm::dvec3(0, 1, 0));
        if (l.usesFalloff()) convertFalloff(rig, frame, l, worldPos, intensity, g, out.losses);
        if (l.usesCone()) convertCone(l, g, out.losses);
        if (l.diffuse == DiffuseModel::HalfLambert)
            out.losses.push_back({ExportLoss::HalfLambert, l.name, QStringLiteral("half-lambert")});
        if (l.specularIsColor || l.specular.x != 1.0)
            out.losses.push_back({ExportLoss::Specular, l.name,
                                  l.specularIsColor
                                      ? QStringLiteral("specular colour [%1, %2, %3]")
                                            .arg(num(l.specular.x), num(l.specular.y), num(l.specular.z))
                                      : QStringLiteral("specular %1").arg(num(l.specular.x))});
        if (l.ambient && *l.ambient != glm::dvec3(0.0))
            out.losses.push_back({ExportLoss::LightAmbient, l.name,
                                  QStringLiteral("ambient [%1, %2, %3]")
                                      .arg(num(l.ambient->x), num(l.ambient->y), num(l.ambient->z))});
        if (l.hasShadow()) {
            out.losses.push_back({ExportLoss::Shadow, l.name, QStringLiteral("casts a shadow")});
            if (l.shadow.size > 0.0 || l.shadow.angle > 0.0)
                out.losses.push_back({ExportLoss::Area, l.name,
                                      l.shadow.size > 0.0
                                          ? QStringLiteral("emitter %1 wide").arg(num(l.shadow.size))
                                          : QStringLiteral("emitter %1° wide").arg(num(l.shadow.angle))});
        }
        const glm::dvec3 c = glm::max(l.effectiveColor(), glm::dvec3(0.0));
        const double m = std::max({c.x, c.y, c.z});
        g.color = m > 0.0 ? c / m : glm::dvec3(0.0);
        g.intensity *= m > 0.0 ? m : 1.0;
        if (l.ies) convertIes(l, fileFromWorld, unit, g, out.losses); // issue 39: EXT_lights_ies
        noteLink(l, &g, out.losses);
        if (l.gobo && l.type == LightType::Spot) {
            g.gobo = {{QStringLiteral("file"), l.gobo->file},
                      {QStringLiteral("scale"), l.gobo->scale},
                      {QStringLiteral("rotation"), l.gobo->rotation}};
            out.losses.push_back({ExportLoss::Gobo, l.name,
                                  QStringLiteral("gobo %1 (scale %2, rotation %3°)")
                                      .arg(l.gobo->file, num(l.gobo->scale), num(l.gobo->rotation))});
        }
        out.lights.push_back(g);
    }
    if (rig.ambient != glm::dvec3(0.0))
        out.losses.push_back({ExportLoss::Ambient, rigSubject,
                              QStringLiteral("[%1, %2, %3]%4")
                                  .arg(num(rig.ambient.x), num(rig.ambient.y), num(rig.ambient.z),
                                       classic ? QStringLiteral(" (× π as lux)") : QString())});
    const Environment& env = rig.environment;
    if (env.source != EnvironmentSource::None) {
        out.losses.push_back({ExportLoss::Environment, rigSubject,
                              env.source == EnvironmentSource::Image
                                  ? QStringLiteral("image %1").arg(env.file)
                                  : QStringLiteral("procedural studio")});
        if (env.source == EnvironmentSource::Studio && !env.studio.softboxes.empty())
            out.losses.push_back({ExportLoss::Area, rigSubject,
                                  QStringLiteral("%1 studio softboxes (in the environment note)")
                                      .arg(env.studio.softboxes.size())});
    }
    if (rig.ground.mode != GroundMode::Off)
        out.losses.push_back({ExportLoss::Ground, rigSubject, toString(rig.ground.mode)});
    out.note = noteFor(rig, unit);
    return out;
}

GltfCamera makeGltfCamera(const QString& name, const glm::dvec3& eye, const glm::dvec3& forward,
                          const glm::dvec3& up, double yfovDegrees, double znear, double zfar,
                          const glm::dmat3& fileFromWorld) {
    GltfCamera c;
    c.name = name;
    c.translation = fileFromWorld * eye;
    c.rotation = lookRotation(fileFromWorld * forward, fileFromWorld * up);
    c.yfov = glm::radians(std::clamp(yfovDegrees, 1.0, 170.0));
    c.znear = znear > 0.0 ? znear : 0.01;
    c.zfar = zfar;
    return c;
}

QJsonObject GltfLight::lightJson() const {
    QJsonObject o{{QStringLiteral("name"), name},
                  {QStringLiteral("type"), type},
                  {QStringLiteral("color"), array3(color)},
                  {QStringLiteral("intensity"), intensity}};
    if (range > 0.0) o.insert(QStringLiteral("range"), range);
    if (type == QLatin1String("spot"))
        o.insert(QStringLiteral("spot"), QJsonObject{{QStringLiteral("innerConeAngle"), innerConeAngle},
                                                     {QStringLiteral("outerConeAngle"), outerConeAngle}});
    return o;
}

namespace {
void setTransform(QJsonObject& node, const glm::dvec3& t, const glm::dquat& q) {
    if (t != glm::dvec3(0.0)) node.insert(QStringLiteral("translation"), array3(t));
    if (q != glm::dquat(1.0, 0.0, 0.0, 0.0))
        node.insert(QStringLiteral("rotation"), QJsonArray{q.x, q.y, q.z, q.w});
}
} // namespace

QJsonObject GltfLight::nodeJson(int lightIndex) const {
    QJsonObject instance{{QStringLiteral("light"), lightIndex}};
    if (ies) {
        instance.insert(QStringLiteral("multiplier"), ies->multiplier);
        instance.insert(QStringLiteral("color"), array3(ies->color));
    }
    QJsonObject node{{QStringLiteral("name"), name},
                     {QStringLiteral("extensions"), QJsonObject{{ies ? QStringLiteral("EXT_lights_ies")
                                                                     : QStringLiteral("KHR_lights_punctual"),
                                                                 instance}}}};
    setTransform(node, translation, rotation);
    QJsonObject lightrig;
    if (!link.isEmpty()) lightrig.insert(QStringLiteral("link"), link);
    if (!gobo.isEmpty()) lightrig.insert(QStringLiteral("gobo"), gobo);
    if (!barnDoors.isEmpty()) lightrig.insert(QStringLiteral("barnDoors"), barnDoors);
    if (!lightrig.isEmpty())
        node.insert(QStringLiteral("extras"), QJsonObject{{QStringLiteral("lightrig"), lightrig}});
    return node;
}

QJsonObject GltfCamera::cameraJson() const {
    QJsonObject p{{QStringLiteral("yfov"), yfov}, {QStringLiteral("znear"), znear}};
    if (zfar > znear) p.insert(QStringLiteral("zfar"), zfar);
    return {{QStringLiteral("name"), name},
            {QStringLiteral("type"), QStringLiteral("perspective")},
            {QStringLiteral("perspective"), p}};
}

QJsonObject GltfCamera::nodeJson(int cameraIndex) const {
    QJsonObject node{{QStringLiteral("name"), name}, {QStringLiteral("camera"), cameraIndex}};
    setTransform(node, translation, rotation);
    return node;
}

} // namespace lr
