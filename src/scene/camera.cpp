#include "camera.h"

#include "core/lighting.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace lr {

namespace {
using lighting::safeNormalize;

double finiteOr(double v, double fallback) {
    return std::isfinite(v) ? v : fallback;
}
double clampedFov(double deg) {
    return std::clamp(finiteOr(deg, 45.0), 1e-3, 179.0);
}
} // namespace

glm::dvec3 ViewCamera::forward() const {
    return safeNormalize(target - eye, glm::dvec3(0, 0, -1));
}

glm::dvec3 ViewCamera::right() const {
    const glm::dvec3 f = forward();
    glm::dvec3 r = glm::cross(f, safeNormalize(up, glm::dvec3(0, 1, 0)));
    if (!(glm::dot(r, r) > 1e-20)) // looking along up: pick any perpendicular
        r = glm::cross(f, std::abs(f.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0));
    return safeNormalize(r, glm::dvec3(1, 0, 0));
}

glm::dvec3 ViewCamera::trueUp() const {
    return glm::cross(right(), forward());
}

double ViewCamera::distance() const {
    return glm::length(target - eye);
}

glm::dmat4 ViewCamera::view() const {
    const glm::dvec3 f = forward(), r = right(), u = glm::cross(r, f);
    glm::dmat4 m(1.0);
    for (int i = 0; i < 3; ++i) {
        m[i][0] = r[i];
        m[i][1] = u[i];
        m[i][2] = -f[i];
    }
    m[3][0] = -glm::dot(r, eye);
    m[3][1] = -glm::dot(u, eye);
    m[3][2] = glm::dot(f, eye);
    return m;
}

glm::dmat4 ViewCamera::projection(double aspect) const {
    const double fovy = glm::radians(clampedFov(yfovDeg));
    const double a = aspect > 0.0 && std::isfinite(aspect) ? aspect : 1.0;
    const double n = znear > 0.0 ? znear : 0.01;
    if (zfar <= n) return glm::infinitePerspective(fovy, a, n);
    return glm::perspective(fovy, a, n, zfar);
}

glm::dmat4 ViewCamera::projection(QSize size, const QRect& tile) const {
    const double aspect = double(size.width()) / double(std::max(1, size.height()));
    if (!tile.isValid()) return projection(aspect);
    const double w = size.width(), h = size.height();
    const double x0 = 2.0 * tile.left() / w - 1.0, x1 = 2.0 * (tile.left() + tile.width()) / w - 1.0;
    const double y1 = 1.0 - 2.0 * tile.top() / h, y0 = 1.0 - 2.0 * (tile.top() + tile.height()) / h;
    return projection(aspect, x0, y0, x1, y1);
}

glm::dmat4 ViewCamera::projection(double aspect, double x0, double y0, double x1, double y1) const {
    glm::dmat4 crop(1.0);
    crop[0][0] = 2.0 / (x1 - x0);
    crop[1][1] = 2.0 / (y1 - y0);
    crop[3][0] = -(x0 + x1) / (x1 - x0);
    crop[3][1] = -(y0 + y1) / (y1 - y0);
    return crop * projection(aspect);
}

ViewCamera ViewCamera::withClipPlanes(const glm::dvec3& center, double radius) const {
    ViewCamera c = *this;
    if (znear > 0.0) return c;
    const double r = radius > 0.0 && std::isfinite(radius) ? radius * 1.02 : 1.0;
    const double depth = glm::dot(center - eye, forward());
    double farPlane = depth + r;
    if (!(farPlane > 0.0)) farPlane = r; // the scene is behind the camera: anything sane
    c.zfar = farPlane;
    c.znear = std::max(depth - r, farPlane * 1e-5);
    return c;
}

ViewCamera ViewCamera::withExportClipPlanes(const glm::dvec3& center, double radius) const {
    ViewCamera c = *this;
    if (znear > 0.0) return c;
    const double r = radius > 0.0 && std::isfinite(radius) ? radius * 1.5 : 1.5;
    const double depth = glm::dot(center - eye, forward());
    c.zfar = depth + r > 0.0 ? depth + r : r;
    c.znear = std::max(depth - r, c.zfar * 1e-4);
    return c;
}

void ViewCamera::orbit(double yawDeg, double pitchDeg) {
    const glm::dvec3 worldUp = safeNormalize(up, glm::dvec3(0, 1, 0));
    glm::dvec3 offset = eye - target;
    if (!(glm::dot(offset, offset) > 0.0)) offset = glm::dvec3(0, 0, 1);
    const double yaw = glm::radians(finiteOr(yawDeg, 0.0));
    offset = glm::angleAxis(yaw, worldUp) * offset;
    // Keep the pitch strictly between straight down and straight up so `up` stays usable.
    const double len = glm::length(offset);
    const double current = std::acos(std::clamp(glm::dot(offset / len, worldUp), -1.0, 1.0)); // from up
    const double minAngle = glm::radians(0.5), maxAngle = glm::radians(179.5);
    const double wanted = std::clamp(current - glm::radians(finiteOr(pitchDeg, 0.0)), minAngle, maxAngle);
    glm::dvec3 axis = glm::cross(worldUp, offset);
    if (glm::dot(axis, axis) > 0.0)
        offset = glm::angleAxis(wanted - current, safeNormalize(axis, worldUp)) * offset;
    eye = target + offset;
}

void ViewCamera::pan(double dx, double dy) {
    const double scale = distance() * 2.0 * std::tan(glm::radians(clampedFov(yfovDeg)) * 0.5);
    const glm::dvec3 delta = (finiteOr(dx, 0.0) * right() + finiteOr(dy, 0.0) * trueUp()) * scale;
    eye += delta;
    target += delta;
}

void ViewCamera::dolly(double factor) {
    if (!(factor > 0.0) || !std::isfinite(factor)) return;
    const glm::dvec3 offset = eye - target;
    const double d = glm::length(offset) * factor;
    if (!(d > 1e-9) || !std::isfinite(d)) return;
    eye = target + offset * factor;
}

void ViewCamera::frameAll(const Bounds& bounds, double aspect) {
    const double a = aspect > 0.0 && std::isfinite(aspect) ? aspect : 1.0;
    const double halfV = glm::radians(clampedFov(yfovDeg)) * 0.5;
    const double halfH = std::atan(std::tan(halfV) * a);
    const double half = std::min(halfV, halfH);
    const double dist = bounds.radius() / std::sin(half) * 1.05;
    const glm::dvec3 f = forward();
    target = bounds.center();
    eye = target - f * dist;
}

QStringList standardViewNames() {
    return {QStringLiteral("front"), QStringLiteral("back"), QStringLiteral("left"),
            QStringLiteral("right"), QStringLiteral("top"),  QStringLiteral("three-quarter")};
}

std::optional<ViewCamera> standardView(const QString& name, const Bounds& bounds, double aspect) {
    glm::dvec3 toEye, up(0, 1, 0);
    if (name == QLatin1String("front"))
        toEye = {0, 0, 1};
    else if (name == QLatin1String("back"))
        toEye = {0, 0, -1};
    else if (name == QLatin1String("left"))
        toEye = {-1, 0, 0};
    else if (name == QLatin1String("right"))
        toEye = {1, 0, 0};
    else if (name == QLatin1String("top"))
        toEye = {0, 1, 0}, up = {0, 0, -1};
    else if (name == QLatin1String("three-quarter")) {
        const double az = glm::radians(45.0), el = glm::radians(30.0);
        toEye = {std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el)};
    } else
        return std::nullopt;
    ViewCamera c;
    c.up = up;
    c.target = bounds.center();
    c.eye = c.target + toEye;
    c.frameAll(bounds, aspect);
    return c;
}

ViewCamera fromModelCamera(const Camera& camera, double focusDistance) {
    ViewCamera c;
    c.eye = camera.position;
    const glm::dvec3 f = safeNormalize(camera.forward, glm::dvec3(0, 0, -1));
    c.target = camera.position + f * (focusDistance > 0.0 ? focusDistance : 1.0);
    c.up = safeNormalize(camera.up, glm::dvec3(0, 1, 0));
    c.yfovDeg = clampedFov(camera.yfovDegrees);
    c.znear = camera.znear > 0.0 ? camera.znear : 0.0;
    c.zfar = camera.znear > 0.0 ? camera.zfar : 0.0;
    return c;
}

} // namespace lr
