#include "proceduralrig.h"

#include "lighting.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace lr {

namespace {

// HSV (all in [0, 1]) to RGB, as Python's colorsys.hsv_to_rgb.
glm::dvec3 hsvToRgb(double h, double s, double v) {
    const double f6 = h * 6.0;
    const int i = int(std::floor(f6)) % 6;
    const double f = f6 - std::floor(f6);
    const double p = v * (1.0 - s), q = v * (1.0 - s * f), t = v * (1.0 - s * (1.0 - f));
    switch (i) {
    case 0:
        return {v, t, p};
    case 1:
        return {q, v, p};
    case 2:
        return {p, v, t};
    case 3:
        return {p, q, v};
    case 4:
        return {t, p, v};
    default:
        return {v, p, q};
    }
}

// Area lights' size in bounding radii: a rect of 1 × 0.6 and a disk of radius 0.4 (about the same area),
// at the ring's 2.5 radii a softbox subtending about 0.1 sr.
constexpr double kAreaWidth = 1.0, kAreaHeight = 0.6, kAreaRadius = 0.4;

} // namespace

Rig proceduralRig(const ProceduralRigOptions& o) {
    Rig rig;
    rig.name = proceduralRigName(o);
    rig.space = RigSpace::Model;
    rig.ambient = glm::dvec3(0.02);
    const int n = std::max(0, o.count);
    const double total = o.totalIntensity > 0.0 ? o.totalIntensity : traitsOf(o.type).benchIntensity;
    rig.lights.reserve(size_t(n));
    for (int i = 0; i < n; ++i) {
        Light l = makeLight(o.type, QStringLiteral("L%1").arg(i));
        const double a = 2.0 * glm::pi<double>() * i / n;
        const glm::dvec3 p = n > 1 ? glm::dvec3(2.5 * std::sin(a), 1.2 * std::sin(3.1 * i), 2.5 * std::cos(a))
                                   : glm::dvec3(0.0, 1.0, 2.5);
        l.color = hsvToRgb(double(i) / n, 0.35, 1.0);
        l.intensity = total / n;
        l.position = p;
        l.direction = lighting::safeNormalize(-p, glm::dvec3(0.0, -1.0, 0.0)); // towards the centre
        if (l.usesFalloff()) {
            l.falloff = Falloff();
            l.falloff.model = FalloffModel::InverseSquare;
            l.falloff.range = o.range > 0.0 ? o.range : -1.0;
        }
        if (l.usesCone())
            l.cone = {ConeModel::Smooth, 0.3 * 180.0 / glm::pi<double>(), 0.6 * 180.0 / glm::pi<double>(),
                      2.0};
        if (l.usesRimExponent()) l.rimExponent = 1.3;
        if (l.isArea()) { // softboxes facing the centre, sized to the model (kAreaWidth × kAreaHeight radii)
            l.area.width = kAreaWidth, l.area.height = kAreaHeight, l.area.radius = kAreaRadius;
            l.area.roll = 0.0, l.area.twoSided = false;
        }
        rig.lights.push_back(std::move(l));
    }
    return rig;
}

QString proceduralRigName(const ProceduralRigOptions& o) {
    QString name = QStringLiteral("%1 %2").arg(o.count).arg(toString(o.type));
    if (o.range > 0.0) name += QStringLiteral(" r%1").arg(o.range);
    return name;
}

} // namespace lr
