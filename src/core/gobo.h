// A gobo: an image projected through a spot light's cone (issue 39, core/lightshaping.h GoboSpec;
// docs/light-shaping.md "Gobos"). The one definition every renderer follows (shaders/gobo.glsl mirrors it).
//
// Projection, as a slide projector seen from behind the light: a direction w leaving the spot (unit,
// world or view space) is cut by the plane one unit along the spot's axis d, at
//     (x, y) = (w·X, w·Y) / (w·d),   X, Y = areaAxes(d, rotation) (prepare.h: X horizontal, Y up at 0°)
// and the image covers the square |x|, |y| <= h, h = tan(cone.outer) × scale: at scale 1 the square's
// inscribed circle is the cone's edge. Image column u runs along +X (left to right), row v along −Y (row 0
// at the top):  u = (x / h + 1) / 2,  v = (1 − y / h) / 2. Outside the square and behind the light (w·d <= 0)
// the gobo is black. Inside it is the image's transmission, bilinear between texel centres ((i + ½)/width)
// and clamped to the edge texels, as a GL_LINEAR / CLAMP_TO_EDGE texture without mipmaps samples it. The
// light's colour is multiplied by it (its falloff and cone still apply).
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace lr {

// Linear RGB transmission in [0, 1], row 0 at the image's top, as decoded from the file (model/gobodecode.h).
struct GoboImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb; // width * height * 3
    bool isNull() const { return width <= 0 || height <= 0; }
};

// Limits on a gobo image (model/gobodecode.h refuses larger ones): a gobo is a pattern, not a photograph.
inline constexpr int kMaxGoboSide = 4096;

namespace gobo {

// The image's (u, v) for direction w (unit) leaving a spot with axis d and gobo axes X, Y (unit, the
// spot's frame) and half extent h = tan(outer) × scale; false (no uv) behind the light or outside the
// square.
template <typename T>
bool project(const glm::vec<3, T>& w, const glm::vec<3, T>& d, const glm::vec<3, T>& X,
             const glm::vec<3, T>& Y, T h, glm::vec<2, T>* uv) {
    const T c = glm::dot(w, d);
    if (!(c > T(0)) || !(h > T(0))) return false;
    const T x = glm::dot(w, X) / (c * h), y = glm::dot(w, Y) / (c * h);
    if (!(std::abs(x) <= T(1) && std::abs(y) <= T(1))) return false;
    *uv = glm::vec<2, T>((x + T(1)) * T(0.5), (T(1) - y) * T(0.5));
    return true;
}

// The image's transmission at (u, v) in [0, 1]²: bilinear between texel centres, clamped to the edge.
inline glm::dvec3 sample(const GoboImage& img, double u, double v) {
    if (img.isNull()) return glm::dvec3(0.0);
    const double fx = std::clamp(u * img.width - 0.5, 0.0, double(img.width - 1));
    const double fy = std::clamp(v * img.height - 0.5, 0.0, double(img.height - 1));
    const int x0 = int(fx), y0 = int(fy);
    const int x1 = std::min(x0 + 1, img.width - 1), y1 = std::min(y0 + 1, img.height - 1);
    const double tx = fx - x0, ty = fy - y0;
    const auto at = [&](int x, int y) {
        const float* p = img.rgb.data() + (size_t(y) * size_t(img.width) + size_t(x)) * 3;
        return glm::dvec3(p[0], p[1], p[2]);
    };
    const glm::dvec3 top = at(x0, y0) * (1.0 - tx) + at(x1, y0) * tx;
    const glm::dvec3 bottom = at(x0, y1) * (1.0 - tx) + at(x1, y1) * tx;
    return top * (1.0 - ty) + bottom * ty;
}

// The gobo's tint for direction w (unit) leaving the light: the sampled transmission, or black.
template <typename T>
glm::vec<3, T> tint(const GoboImage& img, const glm::vec<3, T>& w, const glm::vec<3, T>& d,
                    const glm::vec<3, T>& X, const glm::vec<3, T>& Y, T h) {
    glm::vec<2, T> uv;
    if (!project(w, d, X, Y, h, &uv)) return glm::vec<3, T>(T(0));
    return glm::vec<3, T>(sample(img, double(uv.x), double(uv.y)));
}

// h for a cone's outer half-angle (radians) and the gobo's scale.
inline double halfExtent(double outerRadians, double scale) {
    return std::tan(outerRadians) * scale;
}

} // namespace gobo
} // namespace lr
