// Shared by the shadow tests (tst_shadows, tst_shadowshapes): casting lights, rigs with and without their
// shadows, render settings per tier, and a fixture that renders radiance and measures visibility: a
// world point's luminance with the light's shadow on over the same render with it off (so the lighting
// itself cancels), at points projected with the renderer's camera.
#pragma once

#include "glfixture.h"
#include "scenes.h"
#include "shadowscenes.h"

#include "render/offscreen.h"

#include <QSize>
#include <QString>
#include <cmath>
#include <memory>
#include <vector>

namespace lr::test {

inline const QSize kSize(400, 300);
inline Light castingSpot(glm::dvec3 position, glm::dvec3 target, double outer, double size) {
    Light l = makeLight(LightType::Spot, QStringLiteral("spot"));
    l.position = position;
    l.direction = glm::normalize(target - position);
    l.falloff.model = FalloffModel::None;
    l.falloff.range = -1.0;
    l.cone = {ConeModel::Smooth, outer - 2.0, outer, 1.0};
    l.shadow.enabled = true;
    l.shadow.size = size;
    return l;
}

// A rect light at `position` shining straight down, `width` × `width`, one- or two-sided.
inline Light castingRect(glm::dvec3 position, double width, bool twoSided = false) {
    Light l = makeLight(LightType::Rect, QStringLiteral("rect"));
    l.position = position;
    l.direction = {0.0, -1.0, 0.0};
    l.area.width = width;
    l.area.height = width;
    l.area.twoSided = twoSided;
    l.shadow.enabled = true;
    return l;
}

inline Rig withGround(std::vector<Light> lights, GroundMode mode,
                      ShadingModel shading = ShadingModel::Classic) {
    Rig r = rigOf(std::move(lights));
    r.ground.mode = mode;
    r.shading.model = shading;
    return r;
}

inline Rig withoutShadows(Rig r) {
    for (Light& l : r.lights)
        l.shadow.enabled = false;
    return r;
}

inline RenderSettings settingsFor(Quality q, ShadingPath path = ShadingPath::Forward) {
    RenderSettings s;
    s.quality = q;
    s.msaaSamples = 0;
    s.shadingPath = path;
    return s;
}

// Lit ground compared with the same render without shadows: equal up to float rounding (the fast tier's
// program is another one: its reference is the exact tier's, see referenceFor).
inline double litTolerance(Quality q) {
    return q == Quality::Fast ? 1e-3 : 1e-4;
}

// The unshadowed render to compare a tier with: its own, except for the fast tier, whose casting lights are
// shaded per pixel exactly as the exact tier shades them (without its shadow a light would be Gouraud).
inline RenderSettings referenceFor(RenderSettings s) {
    if (s.quality == Quality::Fast) s.quality = Quality::Exact;
    return s;
}

// The radius of the shadow a sphere (centre c, radius a) casts from a point light at height h straight
// above it onto the plane y = 0: the tangent cone's half-angle asin(a / d), d = h − c.y.
inline double sphereShadowRadius(double h, double cy, double a) {
    const double half = std::asin(a / (h - cy));
    return h * std::tan(half);
}

class ShadowFixture {
  protected:
    std::unique_ptr<OffscreenRenderer> m_gl;

    bool startGl() {
        if (!haveDisplay()) return false;
        if (m_gl) return true;
        m_gl = std::make_unique<OffscreenRenderer>();
        QString error;
        if (!m_gl->initialize(&error)) qFatal("%s", qPrintable(error));
        return true;
    }

    FloatImage radiance(const Rig& rig, const ViewCamera& cam, const RenderSettings& s) {
        m_gl->setRig(rig);
        FloatImage out;
        QString error;
        if (!m_gl->renderRadiance(cam, kSize, s, &out, &error)) qWarning("%s", qPrintable(error));
        return out;
    }

    // Shadowed over unshadowed luminance at a world point (-1 where it is off the image or unlit).
    double visibilityAt(const FloatImage& on, const FloatImage& off, const ViewCamera& cam, glm::dvec3 p) {
        const auto px = projectToPixel(m_gl->renderer(), cam, kSize, p);
        if (!px) return -1.0;
        const double lit = luminance(off.at(px->x(), px->y()));
        return lit > 1e-6 ? luminance(on.at(px->x(), px->y())) / lit : -1.0;
    }
};

} // namespace lr::test
