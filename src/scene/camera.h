// The interactive view camera: a look-at camera in double precision, world units, right-handed OpenGL
// conventions (view space looks down -Z). No GL here: the renderer, the viewport, the command line and
// the tests share this math.
#pragma once

#include "model/model.h"

#include <QRect>
#include <QSize>
#include <QString>
#include <QStringList>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>

namespace lr {

struct ViewCamera {
    glm::dvec3 eye{0.0, 0.0, 5.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0}; // world up hint; need not be orthogonal to the view direction
    double yfovDeg = 45.0;
    double znear = 0.0; // <= 0: chosen per frame from the scene bounds (clipPlanesFor)
    double zfar = 0.0;  // <= 0 with znear > 0: infinite far plane; with znear <= 0: automatic too

    glm::dvec3 forward() const; // unit, eye -> target (falls back to -Z when eye == target)
    glm::dvec3 right() const;   // unit
    glm::dvec3 trueUp() const;  // unit, orthogonal to forward and right
    double distance() const;    // |target - eye|

    glm::dmat4 view() const;                    // world -> view
    glm::dmat4 projection(double aspect) const; // needs znear > 0 (use withClipPlanes first)
    // Projection of the sub-rectangle [x0,x1]×[y0,y1] (NDC, -1..1) of the full image: for tiled rendering.
    glm::dmat4 projection(double aspect, double x0, double y0, double x1, double y1) const;
    // The projection of a `size`-pixel image, or of its part `tile` (pixels, top-left origin) when valid.
    glm::dmat4 projection(QSize size, const QRect& tile) const;

    // This camera with near/far planes that enclose the sphere (when znear <= 0; explicit planes are kept).
    ViewCamera withClipPlanes(const glm::dvec3& center, double radius) const;
    // For a camera another program uses as written (an exported glTF camera, issue 41): planes that enclose
    // the sphere grown by half its radius again, the near plane no closer than 1/10,000 of the far one (a
    // viewer's depth buffer); planes tight on the sphere clipped the model in three.js. Explicit planes
    // (znear > 0, a file's own camera) are kept.
    ViewCamera withExportClipPlanes(const glm::dvec3& center, double radius) const;

    // Interaction. Angles in degrees; pan offsets in fractions of the viewport height.
    void orbit(double yawDeg, double pitchDeg);
    void pan(double dx, double dy);
    void dolly(double factor); // distance *= factor (factor > 0); the target stays
    // Keep the view direction, look at the bounds and back off until they fit.
    void frameAll(const Bounds& bounds, double aspect);

    bool operator==(const ViewCamera&) const = default;
};

// "front", "back", "left", "right", "top", "three-quarter".
QStringList standardViewNames();
// A standard view framing `bounds`; nullopt for an unknown name.
std::optional<ViewCamera> standardView(const QString& name, const Bounds& bounds, double aspect);
// A camera from a model file. The orbit target lies along the view direction at focusDistance
// (<= 0: 1 unit). Its clip planes are kept.
ViewCamera fromModelCamera(const Camera& camera, double focusDistance = 0.0);

} // namespace lr
