#include "editor/placement.h"

#include "core/lighting.h"
#include "core/rigjson.h"
#include "editor/document.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

namespace lr {

namespace {
using lighting::safeNormalize;

// Azimuth offsets (degrees, around the view's up) of successive new lights: right, left, further right...
constexpr double kAzimuths[] = {35.0, -35.0, 70.0, -70.0, 0.0, 105.0, -105.0, 140.0, -140.0};
constexpr double kElevation = 30.0; // degrees above the viewer's horizon
} // namespace

Light placeNewLight(const Rig& rig, LightType type, const QString& name, const PlacementView& view,
                    int index) {
    Light l = makeLight(type, name);
    const SceneFrame& f = view.frame;
    const double radius = f.radius > 0.0 && std::isfinite(f.radius) ? f.radius : 1.0;
    const glm::dvec3 up = safeNormalize(view.up, glm::dvec3(0.0, 1.0, 0.0));
    glm::dvec3 toward = safeNormalize(view.towardViewer, glm::dvec3(0.0, 0.0, 1.0));
    // The viewer's horizon: towardViewer without its up component (looking straight down: any side).
    glm::dvec3 horizon = toward - up * glm::dot(toward, up);
    horizon = safeNormalize(horizon, std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0));
    const int n = int(std::size(kAzimuths));
    const double azimuth = glm::radians(kAzimuths[((index % n) + n) % n]);
    const glm::dvec3 side = glm::angleAxis(azimuth, up) * horizon;
    const double el = glm::radians(kElevation);
    const glm::dvec3 out = safeNormalize(side * std::cos(el) + up * std::sin(el), up); // centre -> light

    const glm::dvec3 world = f.center + out * (kPlacementDistance * radius);
    if (l.usesPosition()) l.position = worldToRig(rig, f, world);
    if (l.usesFalloff() && l.falloff.hasRange())
        l.falloff.range = kPlacementRange * radius * distanceScale(rig, f);
    if (type == LightType::Spot || type == LightType::Directional) l.direction = -out; // towards the centre
    if (rig.shading.model == ShadingModel::Pbr)
        makePhysicallyBased(l, kPlacementDistance * radius * distanceScale(rig, f));
    return l;
}

void makePhysicallyBased(Light& l, double distance) {
    if (l.type == LightType::Rim) return; // a rim light adds its classic term under PBR too
    l.diffuse = DiffuseModel::Lambert;
    if (l.type == LightType::Directional) {
        l.intensity = kPbrPlacementIlluminance;
        return;
    }
    const double d = std::isfinite(distance) && distance > 0.0 ? distance : 1.0;
    l.intensity = std::min(kPbrPlacementIlluminance * d * d, kMaxRigIntensity);
    l.falloff.model = FalloffModel::InverseSquare; // the range window keeps the placement's range
    if (l.usesCone()) {
        l.cone.model = ConeModel::Smooth;
        l.cone.exponent = 2.0;
    }
}

bool addPlacedLight(Document* doc, LightType type, const PlacementView& view, QString* error) {
    QString base = toString(type);
    base[0] = base[0].toUpper();
    const Light light = placeNewLight(doc->rig(), type, doc->uniqueLightName(base), view, doc->lightCount());
    return doc->addLights(
        -1, {light}, QCoreApplication::translate("lr::Document", "Add %1 light").arg(toString(type)), error);
}

} // namespace lr
