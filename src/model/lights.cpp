// The file's lights (aiLight) into a world-space Rig and its cameras (aiCamera) into Camera, placed by
// their nodes. Conventions and the Assimp 5.2.5 quirks they undo are documented in modelloader.h.
#include "importdetail.h"

#include "core/fallofftraits.h"
#include "core/prepare.h"
#include "core/rigjson.h"

#include <QFileInfo>
#include <assimp/scene.h>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vector_relational.hpp>
#include <limits>
#include <numbers>

namespace lr::detail {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

glm::dvec3 unitOr(glm::dvec3 v, const glm::dvec3& fallback) {
    if (!isFinite(v)) return fallback;
    const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(m > 0.0)) return fallback;
    v /= m;
    return v / std::sqrt(glm::dot(v, v));
}

const aiNode* findNode(const aiScene* scene, const aiString& name) {
    return scene->mRootNode && name.length ? scene->mRootNode->FindNode(name) : nullptr;
}

// glTF's optional light range, which Assimp keeps in the light node's metadata.
double gltfRange(const aiNode* node) {
    if (!node || !node->mMetaData) return -1.0;
    float f = 0.0f;
    double d = 0.0;
    if (node->mMetaData->Get("PBR_LightRange", f))
        d = f;
    else if (!node->mMetaData->Get("PBR_LightRange", d))
        return -1.0;
    return std::isfinite(d) && d > 0.0 ? d : -1.0;
}

// Splits a colour with intensity folded in into (colour with max component 1, intensity).
void splitIntensity(const aiColor3D& c, Light& light) {
    glm::dvec3 rgb(c.r, c.g, c.b);
    for (int i = 0; i < 3; ++i)
        rgb[i] = std::isfinite(rgb[i]) ? std::max(rgb[i], 0.0) : 0.0;
    const double m = std::max({rgb.r, rgb.g, rgb.b});
    if (m > 0.0 && std::isfinite(m)) {
        light.intensity = m;
        light.color = rgb / m;
    } else {
        light.intensity = 0.0;
        light.color = glm::dvec3(1.0);
    }
}

void setFalloff(const aiLight& al, bool gltf, const aiNode* node, Light& light) {
    const double c = al.mAttenuationConstant, l = al.mAttenuationLinear, q = al.mAttenuationQuadratic;
    const bool valid = std::isfinite(c) && std::isfinite(l) && std::isfinite(q) && c >= 0 && l >= 0 && q >= 0;
    light.falloff.model = FalloffModel::InverseSquare;
    light.falloff.range = gltf ? gltfRange(node) : -1.0;
    if (gltf || !valid || (c == 0.0 && l == 0.0)) {
        if (!gltf && valid && q > 0.0 && q != 1.0) light.intensity /= q; // 1 / (q d²)
        return;
    }
    light.falloff.model = FalloffModel::InversePolynomial;
    light.falloff.constant = c;
    light.falloff.linear = l;
    light.falloff.quadratic = q;
}

void setCone(const aiLight& al, bool gltf, Light& light) {
    // glTF: half-angles as KHR_lights_punctual writes them. Elsewhere: full cone angles.
    const double scale = (gltf ? 1.0 : 0.5) * kRadToDeg;
    double outer = double(al.mAngleOuterCone) * scale, inner = double(al.mAngleInnerCone) * scale;
    if (!(outer > 0.0)) outer = 45.0;
    outer = std::min(outer, 90.0);
    // glTF's default innerConeAngle is 0 (and the export writes 0 for a rect's stand-in spot), but the rig's
    // smooth cone needs 0 < inner: the smallest such angle, whose cosine is 1 to 1.5e-10 (the same cone).
    constexpr double kSmallestInner = 1e-3; // degrees
    inner = std::isfinite(inner) ? std::clamp(inner, kSmallestInner, std::max(outer, kSmallestInner))
                                 : kSmallestInner;
    light.cone.model = ConeModel::Smooth;
    light.cone.inner = inner;
    light.cone.outer = outer;
    light.cone.exponent = gltf ? 2.0 : 1.0;
}

QString number(double v) {
    return QString::number(v, 'g', 6);
}

// An area light (aiLightSource_AREA: a Blender area lamp, an FBX area light) as a rect light: mSize is its
// width along the light's right (direction × up) and its height along its up (mUp, made perpendicular to the
// direction), which gives the roll against areaAxes' convention (core/prepare.h). Assimp says nothing of
// sides or units: one-sided, and the file's colour × intensity is taken as the face's radiance.
void setArea(const aiLight& al, const glm::dmat4& world, const QString& where, Light& light,
             QStringList& warnings) {
    const double w = al.mSize.x, h = al.mSize.y;
    if (std::isfinite(w) && std::isfinite(h) && w >= 0.0 && h >= 0.0) {
        light.area.width = std::min(w, kMaxRigLength);
        light.area.height = std::min(h, kMaxRigLength);
    } else {
        warnings << QStringLiteral("%1: area light size [%2, %3] is not usable; 1 × 1 instead")
                        .arg(where, number(w), number(h));
    }
    const glm::dvec3 up = glm::dmat3(world) * glm::dvec3(al.mUp.x, al.mUp.y, al.mUp.z);
    light.area.roll = rollForUp(light.direction, up);
}

// The rig format's limits (core/rigjson.h) applied to a light read from a model file, which would
// otherwise skip them (a glTF light of colour [-1, 2, 1e30] and intensity -5 was rendered, and the rig
// could not be saved): out-of-range values are clamped and a light that still would not load is
// dropped, each with a warning. `raw` is the file's colour with its intensity folded in. False: drop it.
bool applyRigLimits(const aiColor3D& raw, const QString& where, Light& light, QStringList& warnings) {
    if (!std::isfinite(raw.r) || !std::isfinite(raw.g) || !std::isfinite(raw.b) || raw.r < 0 || raw.g < 0 ||
        raw.b < 0)
        warnings << QStringLiteral("%1: colour × intensity [%2, %3, %4] has negative or non-finite "
                                   "components; clamped to 0")
                        .arg(where, number(raw.r), number(raw.g), number(raw.b));
    if (light.intensity > kMaxRigIntensity) {
        warnings << QStringLiteral("%1: intensity %2 clamped to %3")
                        .arg(where, number(light.intensity), number(kMaxRigIntensity));
        light.intensity = kMaxRigIntensity;
    }
    if (light.name.size() > kMaxRigNameLength) {
        warnings << QStringLiteral("%1: name shortened to %2 characters").arg(where).arg(kMaxRigNameLength);
        light.name.truncate(kMaxRigNameLength);
    }
    for (const FalloffField& field : kFalloffFields) // the rig format's limits (core/fallofftraits.h)
        if (double& value = light.falloff.*field.member; value > field.max) {
            warnings << QStringLiteral("%1: falloff value %2 clamped to %3")
                            .arg(where, number(value), number(field.max));
            value = field.max;
        }
    if (light.usesPosition() &&
        glm::any(glm::greaterThan(glm::abs(light.position), glm::dvec3(kMaxRigLength)))) {
        warnings << QStringLiteral("%1: position beyond ±%2 (the rig format's limit); skipped")
                        .arg(where, number(kMaxRigLength));
        return false;
    }
    // Whatever else the format refuses: check the light as a rig file would be read.
    Rig one;
    one.lights = {light};
    const RigReadResult check = readRigJson(writeRigJson(one), QStringLiteral("-"));
    if (!check.ok()) {
        warnings << QStringLiteral("%1: not a valid rig light (%2); skipped")
                        .arg(where, check.errors.first().mid(3));
        return false;
    }
    return true;
}

// Assimp's light sources by their glTF (KHR_lights_punctual) names, which kLightTypeTraits maps to types
// (area lights, which glTF has none of, are handled before).
QString gltfTypeName(aiLightSourceType type) {
    switch (type) {
    case aiLightSource_POINT:
        return QStringLiteral("point");
    case aiLightSource_SPOT:
        return QStringLiteral("spot");
    case aiLightSource_DIRECTIONAL:
        return QStringLiteral("directional");
    default:
        return {};
    }
}

} // namespace

double rollForUp(const glm::dvec3& direction, const glm::dvec3& up) {
    const AreaAxes a = areaAxes(direction, 0.0);
    const double x = glm::dot(up, a.x), y = glm::dot(up, a.y);
    if (!std::isfinite(x) || !std::isfinite(y) || std::hypot(x, y) <= 1e-12 * glm::length(up)) return 0.0;
    return std::clamp(std::atan2(x, y) * kRadToDeg, -180.0, 180.0); // y' = sin(roll) x + cos(roll) y
}

void convertLightsAndCameras(const aiScene* scene, bool gltf, const QString& displayName, Model& model) {
    Rig& rig = model.lights;
    rig.name = QFileInfo(displayName).completeBaseName();
    rig.space = RigSpace::World;
    for (unsigned i = 0; i < scene->mNumLights && scene->mLights; ++i) {
        const aiLight* al = scene->mLights[i];
        if (!al) continue;
        const QString name =
            al->mName.length ? QString::fromUtf8(al->mName.C_Str()) : QStringLiteral("Light %1").arg(i);
        const aiNode* node = findNode(scene, al->mName);
        const glm::dmat4 world = node ? worldTransform(node) : glm::dmat4(1.0);
        Light light;
        light.name = name;
        splitIntensity(al->mColorDiffuse, light);
        light.position =
            glm::dvec3(world * glm::dvec4(al->mPosition.x, al->mPosition.y, al->mPosition.z, 1.0));
        light.direction =
            unitOr(glm::dmat3(world) * glm::dvec3(al->mDirection.x, al->mDirection.y, al->mDirection.z),
                   glm::dvec3(0.0, 0.0, -1.0));
        if (al->mType == aiLightSource_AMBIENT) {
            rig.ambient += light.color * light.intensity;
            continue;
        }
        const std::optional<LightType> type = al->mType == aiLightSource_AREA
                                                  ? std::optional(LightType::Rect)
                                                  : lightTypeFromGltf(gltfTypeName(al->mType));
        if (!type) {
            model.warnings << QStringLiteral(
                                  "%1: light %2 of a type LightRig does not model (undefined) skipped")
                                  .arg(displayName, name);
            continue;
        }
        light.type = *type;
        if (light.usesPosition() && !isFinite(light.position)) {
            model.warnings
                << QStringLiteral("%1: light %2 has no finite position; skipped").arg(displayName, name);
            continue;
        }
        if (light.usesFalloff()) setFalloff(*al, gltf, node, light);
        if (light.usesCone()) setCone(*al, gltf, light);
        if (light.isArea())
            setArea(*al, world, QStringLiteral("%1: light %2").arg(displayName, name), light, model.warnings);
        if (int(rig.lights.size()) >= kMaxRigLights) {
            model.warnings << QStringLiteral("%1: more than %2 lights; the rest are skipped")
                                  .arg(displayName)
                                  .arg(kMaxRigLights);
            break;
        }
        if (applyRigLimits(al->mColorDiffuse, QStringLiteral("%1: light %2").arg(displayName, name), light,
                           model.warnings))
            rig.lights.push_back(light);
    }
    const glm::dvec3 ambient = rig.ambient;
    for (int i = 0; i < 3; ++i)
        rig.ambient[i] =
            std::isfinite(rig.ambient[i]) ? std::clamp(rig.ambient[i], 0.0, kMaxRigIntensity) : 0.0;
    if (rig.ambient != ambient)
        model.warnings << QStringLiteral("%1: ambient light [%2, %3, %4] clamped to 0..%5")
                              .arg(displayName, number(ambient.r), number(ambient.g), number(ambient.b),
                                   number(kMaxRigIntensity));

    for (unsigned i = 0; i < scene->mNumCameras && scene->mCameras; ++i) {
        const aiCamera* ac = scene->mCameras[i];
        if (!ac) continue;
        const aiNode* node = findNode(scene, ac->mName);
        const glm::dmat4 world = node ? worldTransform(node) : glm::dmat4(1.0);
        const glm::dmat3 rot(world);
        Camera cam;
        cam.name =
            ac->mName.length ? QString::fromUtf8(ac->mName.C_Str()) : QStringLiteral("Camera %1").arg(i);
        // Assimp 5.2.5's glTF importer copies the node's translation into mPosition as well, which would
        // apply it twice; a glTF camera sits at its node's origin.
        const aiVector3D local = gltf ? aiVector3D(0.0f, 0.0f, 0.0f) : ac->mPosition;
        cam.position = glm::dvec3(world * glm::dvec4(local.x, local.y, local.z, 1.0));
        cam.forward =
            unitOr(rot * glm::dvec3(ac->mLookAt.x, ac->mLookAt.y, ac->mLookAt.z), glm::dvec3(0, 0, -1));
        // Up orthogonal to forward; when the file's up is parallel to forward, any perpendicular.
        const glm::dvec3 up = rot * glm::dvec3(ac->mUp.x, ac->mUp.y, ac->mUp.z);
        const glm::dvec3 side = std::abs(cam.forward.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        cam.up =
            unitOr(up - cam.forward * glm::dot(cam.forward, up), unitOr(glm::cross(cam.forward, side), side));
        if (!isFinite(cam.position)) {
            model.warnings
                << QStringLiteral("%1: camera %2 has no finite position; skipped").arg(displayName, cam.name);
            continue;
        }
        const double aspect = ac->mAspect, hfov = ac->mHorizontalFOV;
        cam.aspect = std::isfinite(aspect) && aspect > 0.0 ? aspect : 0.0;
        if (std::isfinite(hfov) && hfov > 0.0 && (gltf || hfov < std::numbers::pi)) {
            // glTF in 5.2.5: hfov = yfov * aspect (linear, not through the tangent); elsewhere the true
            // full horizontal angle.
            const double yfov = cam.aspect > 0.0 ? (gltf ? hfov / cam.aspect
                                                         : 2.0 * std::atan(std::tan(0.5 * hfov) / cam.aspect))
                                                 : hfov;
            cam.yfovDegrees = std::clamp(yfov * kRadToDeg, 1.0, 170.0);
        } else {
            model.warnings << QStringLiteral("%1: camera %2 is orthographic or has no usable field of view; "
                                             "shown as a 45° perspective")
                                  .arg(displayName, cam.name);
        }
        const double znear = ac->mClipPlaneNear, zfar = ac->mClipPlaneFar;
        // A near plane below float's normal range (glTF znear 1e-45) leaves no depth precision: the model
        // rendered as an empty background. Such a camera is ignored; views of the model remain.
        if (znear > 0.0 && znear < double(std::numeric_limits<float>::min()) * 1e6) {
            model.warnings << QStringLiteral("%1: camera %2 has an unusable near plane (%3); ignored")
                                  .arg(displayName, cam.name, QString::number(znear, 'g', 6));
            continue;
        }
        if (std::isfinite(znear) && znear > 0.0) cam.znear = znear;
        cam.zfar = std::isfinite(zfar) && zfar > cam.znear ? zfar : 0.0;
        model.cameras.push_back(cam);
    }
}

} // namespace lr::detail
