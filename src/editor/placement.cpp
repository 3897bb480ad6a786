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
#include <numbers>

namespace lr {

namespace {
using lighting::safeNormalize;

// Azimuth offsets (degrees, around the view's up) of successive new lights: right, left, further right...
constexpr double kAzimuths[] = {35.0, -35.0, 70.0, -70.0, 0.0, 105.0, -105.0, 140.0, -140.0};
constexpr double kElevation = 30.0; // degrees above the viewer's horizon

// Whether the world point p is inside the view's frustum, with a margin of a tenth of it on every side.
bool inView(const PlacementView& v, const glm::dvec3& p) {
    const glm::dvec3 f = safeNormalize(v.forward, glm::dvec3(0.0, 0.0, -1.0));
    const glm::dvec3 right = safeNormalize(glm::cross(f, v.up), glm::dvec3(1.0, 0.0, 0.0));
    const glm::dvec3 up = glm::cross(right, f);
    const glm::dvec3 d = p - v.eye;
    const double z = glm::dot(d, f);
    const double h = 0.9 * z * v.tanHalfFovY;
    return z > 0.0 && std::abs(glm::dot(d, up)) <= h && std::abs(glm::dot(d, right)) <= h * v.aspect;
}

// The level (intensity) an area light needs for `target` at `distance`; kMaxRigIntensity when its emitter is
// empty or too small for the format's limit.
double areaIntensityFor(const Light& l, double distance, double target) {
    const double factor = areaIrradianceFactor(l, distance);
    if (!(factor > 0.0)) return kMaxRigIntensity;
    return std::min(target / factor, kMaxRigIntensity);
}
} // namespace

double areaIrradianceFactor(const Light& l, double distance) {
    if (!l.isArea() || !std::isfinite(distance)) return 0.0;
    const double d = std::max(std::abs(distance), 1e-12);
    if (l.type == LightType::Disk) {
        const double r = std::max(l.area.radius, 0.0);
        return std::numbers::pi * r * r / (r * r + d * d); // π sin² of the half-angle
    }
    // Four corner rectangles of half-sizes a and b: the form factor of a parallel rectangle seen from above
    // one corner, times π each (Howell's catalogue, C-11).
    const double a = std::max(l.area.width, 0.0) / (2.0 * d), b = std::max(l.area.height, 0.0) / (2.0 * d);
    const double sa = std::sqrt(1.0 + a * a), sb = std::sqrt(1.0 + b * b);
    return 2.0 * (a / sa * std::atan(b / sa) + b / sb * std::atan(a / sb));
}

Light placeNewLight(const Rig& rig, LightType type, const QString& name, const PlacementView& view,
                    int index) {
    Light l = makeLight(type, name);
    const SceneFrame& f = view.frame;
    const double radius = f.radius > 0.0 && std::isfinite(f.radius) ? f.radius : 1.0;
    const glm::dvec3 up = safeNormalize(view.up, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dvec3 toward = safeNormalize(view.towardViewer, glm::dvec3(0.0, 0.0, 1.0));
    // The viewer's horizon: towardViewer without its up component (looking straight down: any side).
    glm::dvec3 horizon = toward - up * glm::dot(toward, up);
    horizon = safeNormalize(horizon, std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0));
    const int n = int(std::size(kAzimuths));
    // Centre -> light: the index's azimuth and kElevation around the viewer's horizon (k = 1), turned
    // towards the viewer as k goes to 0 (k = 0: straight at it).
    const double azimuth = glm::radians(kAzimuths[((index % n) + n) % n]);
    const glm::dvec3 side = glm::angleAxis(azimuth, up) * horizon;
    const double el = glm::radians(kElevation);
    const glm::dvec3 usual = safeNormalize(side * std::cos(el) + up * std::sin(el), up);
    const auto direction = [&](double k) { return safeNormalize(toward + k * (usual - toward), usual); };
    // Where the view is known and the usual place is outside it, the nearest place to it that shows: pulled
    // in towards the centre first, then turned towards the viewer.
    glm::dvec3 out = direction(1.0);
    double along = kPlacementDistance; // radii from the centre
    if (view.hasCamera && l.usesPosition() && !inView(view, f.center + out * (along * radius))) {
        bool found = false;
        for (double k = 1.0; k > -0.01 && !found; k -= 0.25)
            for (double t = kPlacementDistance; t >= kMinPlacementDistance - 1e-9 && !found; t -= 0.1)
                if (inView(view, f.center + direction(k) * (t * radius))) {
                    out = direction(k);
                    along = t;
                    found = true;
                }
    }
    const glm::dvec3 world = f.center + out * (along * radius);
    if (l.usesPosition()) l.position = worldToRig(rig, f, world);
    if (l.usesFalloff() && l.falloff.hasRange())
        l.falloff.range = kPlacementRange * radius * distanceScale(rig, f);
    if (l.usesDirection() && l.type != LightType::Rim) l.direction = -out; // towards the centre
    const double distance = along * radius * distanceScale(rig, f);        // rig units
    if (l.isArea()) {
        const double size = kAreaPlacementSize * radius * distanceScale(rig, f);
        l.area.width = l.area.height = std::min(size, kMaxRigLength);
        l.area.radius = std::min(0.5 * size, kMaxRigLength);
        l.area.roll = 0.0; // width level with the view's horizon when the view is upright
        l.intensity = areaIntensityFor(l, distance, std::numbers::pi * kClassicAreaPlacementLevel);
    }
    if (rig.shading.model == ShadingModel::Pbr) makePhysicallyBased(l, distance);
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
    if (l.isArea()) { // its intensity is its face's luminance; no falloff, no cone
        l.intensity = areaIntensityFor(l, d, kPbrPlacementIlluminance);
        return;
    }
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
