#include "lightpack.h"

namespace lr::render {

LightTexels packLight(const lighting::ShadeLight<float>& l) {
    LightTexels t{};
    auto put3 = [&](int texel, const glm::vec3& v, float w) {
        t[size_t(texel * 4 + 0)] = v.x;
        t[size_t(texel * 4 + 1)] = v.y;
        t[size_t(texel * 4 + 2)] = v.z;
        t[size_t(texel * 4 + 3)] = w;
    };
    put3(0, l.position, float(int(l.type)));
    put3(1, l.direction, float(int(l.falloff)));
    put3(2, l.color, float(int(l.cone)));
    put3(3, l.specular, float(int(l.diffuse)));
    put3(4, l.ambient, l.rimExponent);
    put3(5, glm::vec3(l.range, l.falloffExponent, l.constant), l.linear);
    put3(6, glm::vec3(l.quadratic, l.cosInner, l.cosOuter), l.outer);
    put3(7, glm::vec3(l.coneExponent, 0.0f, 0.0f), 0.0f);
    return t;
}

}  // namespace lr::render
