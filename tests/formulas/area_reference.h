// The area-light definition (core/lighting_area.h) integrated numerically in double for the formula
// tests: a midpoint quadrature over the emitter's surface (K × K cells of the rect, or K rings × 4K sectors
// of the disk), each cell a direction ω with solid angle dA·cos θe / d². Independent of the LTC code.
#pragma once

#include "core/shade.h"

namespace lr::test {

using AreaLight = lighting::ShadeLight<double>;
using lighting::Vec3;

// A rect (or disk: halfHeight ignored) centred at `centre`, emitting along `direction` (unit).
inline AreaLight makeArea(lr::LightType type, Vec3<double> centre, Vec3<double> direction, double hw,
                          double hh, bool twoSided = false) {
    AreaLight l;
    l.type = type;
    l.position = centre;
    l.direction = glm::normalize(direction);
    const Vec3<double> up = std::abs(l.direction.y) < 0.9 ? Vec3<double>(0, 1, 0) : Vec3<double>(1, 0, 0);
    l.axisX = glm::normalize(glm::cross(up, l.direction));
    l.axisY = glm::cross(l.direction, l.axisX); // x × y = -direction
    l.axisY = -l.axisY;
    l.halfWidth = hw;
    l.halfHeight = type == lr::LightType::Disk ? hw : hh;
    l.twoSided = twoSided;
    l.color = Vec3<double>(1);
    l.specular = Vec3<double>(1);
    return l;
}

// ∫Ω directionalResponse dω (× 1/π when classic), without the ambient.
inline Vec3<double> areaQuadrature(const AreaLight& l, const lighting::Surface<double>& s,
                                   const lighting::ShadeSettings<double>& st, int K) {
    using namespace lighting;
    const Vec3<double> V = viewVector(st, s.position);
    const Vec3<double> cDiff =
        st.model == ShadingModel::Pbr ? pbrDiffuseColor(s.albedo, s.metallic) : s.albedo;
    const Vec3<double> f0 = st.model == ShadingModel::Pbr ? pbrF0(s.albedo, s.metallic) : s.specular;
    const double alpha = pbrAlpha(s.roughness);
    Vec3<double> sum(0);
    const auto add = [&](const Vec3<double>& q, double dA) {
        const Vec3<double> d = q - s.position;
        const double d2 = glm::dot(d, d);
        const Vec3<double> w = d / std::sqrt(d2);
        double cosE = -glm::dot(w, l.direction);
        if (l.twoSided) cosE = std::abs(cosE);
        if (!(cosE > 0)) return;
        sum += directionalResponse(l, s, st, V, w, cDiff, f0, alpha) * (dA * cosE / d2);
    };
    if (l.type == lr::LightType::Disk) {
        const int rings = K, sectors = 4 * K;
        for (int i = 0; i < rings; ++i)
            for (int j = 0; j < sectors; ++j) {
                const double r0 = l.halfWidth * i / rings, r1 = l.halfWidth * (i + 1) / rings;
                const double r = (r0 + r1) / 2, a = 2 * kPi * (j + 0.5) / sectors;
                add(l.position + l.axisX * (r * std::cos(a)) + l.axisY * (r * std::sin(a)),
                    kPi * (r1 * r1 - r0 * r0) / sectors);
            }
    } else {
        const double dA = 4 * l.halfWidth * l.halfHeight / (double(K) * K);
        for (int i = 0; i < K; ++i)
            for (int j = 0; j < K; ++j) {
                const double u = -1 + (2 * i + 1.0) / K, v = -1 + (2 * j + 1.0) / K;
                add(l.position + l.axisX * (u * l.halfWidth) + l.axisY * (v * l.halfHeight), dA);
            }
    }
    return st.model == ShadingModel::Pbr ? sum : sum * (1 / kPi);
}

} // namespace lr::test
