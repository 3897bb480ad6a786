#include "lightpack.h"

#include "core/lighttypes.h"

namespace lr::render {

LightTexels packLight(const lighting::ShadeLight<float>& l) {
    LightTexels t{};
    auto put3 = [&](int texel, const glm::vec3& v, float w) {
        t[size_t(texel * 4 + 0)] = v.x;
        t[size_t(texel * 4 + 1)] = v.y;
        t[size_t(texel * 4 + 2)] = v.z;
        t[size_t(texel * 4 + 3)] = w;
    };
    put3(0, l.position, l.range);
    put3(1, l.color, float(int(l.type)));
    put3(2, l.specular, float(int(l.falloff)));
    put3(3, l.direction, l.falloffExponent);
    put3(4, l.ambient, float(int(l.diffuse)));
    if (traitsOf(l.type).isArea) { // no falloff, no cone: texels 5 and 6 carry the emitter's axes
        put3(5, l.axisX, float(int(l.cone)));
        put3(6, l.axisY, l.coneExponent);
    } else {
        put3(5, glm::vec3(l.constant, l.linear, l.quadratic), float(int(l.cone)));
        put3(6, glm::vec3(l.cosInner, l.cosOuter, l.outer), l.coneExponent);
    }
    put3(7, glm::vec3(l.rimExponent, l.halfWidth, l.halfHeight), l.twoSided ? 1.0f : 0.0f);
    if (l.type ==
        LightType::Rect) { // barn doors (0: none) in slots a rect never reads: rim and falloff exponents
        t[7 * 4 + 0] = l.barnDepth;
        t[3 * 4 + 3] = l.barnExtent;
    }
    return t;
}

std::array<float, 4> packLinkTexel(std::uint32_t litMask) {
    return {float(litMask & 0xffffu), float(litMask >> 16), 0.0f, 0.0f};
}

std::array<float, 4 * kIesTexels> packIesTexels(const lighting::ShadeLight<float>& l, int layer, float norm) {
    if (layer < 0) return {0, 0, 0, -1.0f, 0, 0, 0, 0};
    return {l.iesNadir.x, l.iesNadir.y, l.iesNadir.z, float(layer),
            l.iesX.x,     l.iesX.y,     l.iesX.z,     l.iesScale * norm};
}

std::array<float, 4 * kGoboTexels> packGoboTexels(const lighting::ShadeLight<float>& l, int layer, int width,
                                                  int height, int arrayWidth, int arrayHeight) {
    if (layer < 0 || arrayWidth <= 0 || arrayHeight <= 0) return {0, 0, 0, -1.0f, 0, 0, 0, 0, 0, 0, 0, 0};
    return {l.axisX.x, l.axisX.y,  l.axisX.z,    float(layer),  l.axisY.x,         l.axisY.y,
            l.axisY.z, l.goboHalf, float(width), float(height), 1.0f / arrayWidth, 1.0f / arrayHeight};
}

} // namespace lr::render
