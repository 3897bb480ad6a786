#include "picking.h"

#include "model/model.h"

#include <QLineF>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>
#include <limits>

namespace lr {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

glm::dvec3 unproject(const glm::dmat4& inverseViewProj, const glm::dvec3& ndc) {
    const glm::dvec4 p = inverseViewProj * glm::dvec4(ndc, 1.0);
    return glm::dvec3(p) / p.w;
}

double pointSegmentDistance(const QPointF& p, const QPointF& a, const QPointF& b) {
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return QLineF(p, a + t * ab).length();
}
} // namespace

ScreenProjector::ScreenProjector(const glm::dmat4& view, const glm::dmat4& projection, const QSizeF& size)
    : m_view(view), m_proj(projection), m_inverseViewProj(glm::inverse(projection * view)),
      m_inverseView(glm::inverse(view)), m_size(size.width() > 0 && size.height() > 0 ? size : QSizeF(1, 1)) {
}

std::optional<QPointF> ScreenProjector::project(const glm::dvec3& world) const {
    const glm::dvec4 clip = m_proj * m_view * glm::dvec4(world, 1.0);
    if (!(clip.w > 1e-12)) return std::nullopt;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    if (!std::isfinite(ndc.x) || !std::isfinite(ndc.y)) return std::nullopt;
    return QPointF((ndc.x + 1.0) * 0.5 * m_size.width(), (1.0 - ndc.y) * 0.5 * m_size.height());
}

Ray ScreenProjector::ray(const QPointF& screen) const {
    const double x = 2.0 * screen.x() / m_size.width() - 1.0;
    const double y = 1.0 - 2.0 * screen.y() / m_size.height();
    const glm::dvec3 nearP = unproject(m_inverseViewProj, {x, y, -1.0});
    const glm::dvec3 farP = unproject(m_inverseViewProj, {x, y, 0.999});
    glm::dvec3 dir = farP - nearP;
    const double len = glm::length(dir);
    dir = len > 0.0 && std::isfinite(len) ? dir / len : viewDirection();
    // Perspective: from the eye, so points nearer than the near plane (a light close to the camera) are hit
    // too.
    const bool orthographic = m_proj[3][3] == 1.0;
    return {orthographic ? nearP : eye(), dir};
}

glm::dvec3 ScreenProjector::viewDirection() const {
    return glm::normalize(glm::dvec3(m_inverseView * glm::dvec4(0.0, 0.0, -1.0, 0.0)));
}

bool ScreenProjector::isOrthographic() const {
    return m_proj[3][3] == 1.0;
}

glm::dvec3 ScreenProjector::eye() const {
    return glm::dvec3(m_inverseView[3]);
}

double ScreenProjector::depth(const glm::dvec3& world) const {
    return -(m_view * glm::dvec4(world, 1.0)).z;
}

double ScreenProjector::worldPerPixel(double depth) const {
    const double fy = m_proj[1][1]; // 1 / tan(fov / 2) (perspective) or 2 / height (orthographic)
    if (!(std::abs(fy) > 0.0)) return 0.0;
    const bool orthographic = m_proj[3][3] == 1.0;
    return (orthographic ? 2.0 : 2.0 * depth) / (std::abs(fy) * m_size.height());
}

int pickNearest(const ScreenProjector& projector, const std::vector<glm::dvec3>& anchors,
                const QPointF& screen, double maxPixels) {
    int best = -1;
    double bestDist = kInf, bestDepth = kInf;
    for (size_t i = 0; i < anchors.size(); ++i) {
        const auto p = projector.project(anchors[i]);
        if (!p) continue;
        const double dist = QLineF(*p, screen).length();
        if (dist > maxPixels) continue;
        const double depth = projector.depth(anchors[i]);
        // Prefer the nearest on screen; within a pixel, the one closer to the camera.
        if (dist < bestDist - 1.0 || (std::abs(dist - bestDist) <= 1.0 && depth < bestDepth)) {
            best = int(i);
            bestDist = dist;
            bestDepth = depth;
        }
    }
    return best;
}

std::optional<double> intersectPlane(const Ray& ray, const glm::dvec3& point, const glm::dvec3& normal) {
    const double denom = glm::dot(ray.direction, normal);
    if (std::abs(denom) < 1e-12) return std::nullopt;
    const double t = glm::dot(point - ray.origin, normal) / denom;
    if (!(t >= 0.0) || !std::isfinite(t)) return std::nullopt;
    return t;
}

std::optional<ModelHit> intersectModelWithNormal(const Model& model, const Ray& ray) {
    // Möller–Trumbore in double, in the model's local frame (vertices are relative to model.origin).
    const glm::dvec3 o = ray.origin - model.origin;
    const glm::dvec3 d = ray.direction;
    double best = kInf;
    const Mesh* bestMesh = nullptr;
    size_t bestTri = 0;
    double bestU = 0.0, bestW = 0.0;
    for (const Mesh& mesh : model.meshes) {
        const auto& v = mesh.vertices;
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const auto i0 = mesh.indices[i], i1 = mesh.indices[i + 1], i2 = mesh.indices[i + 2];
            if (i0 >= v.size() || i1 >= v.size() || i2 >= v.size()) continue;
            const glm::dvec3 a(v[i0].position), b(v[i1].position), c(v[i2].position);
            const glm::dvec3 e1 = b - a, e2 = c - a;
            const glm::dvec3 p = glm::cross(d, e2);
            const double det = glm::dot(e1, p);
            if (std::abs(det) < 1e-18) continue; // parallel or degenerate (double-sided: both signs)
            const double inv = 1.0 / det;
            const glm::dvec3 s = o - a;
            const double u = glm::dot(s, p) * inv;
            if (u < 0.0 || u > 1.0) continue;
            const glm::dvec3 q = glm::cross(s, e1);
            const double w = glm::dot(d, q) * inv;
            if (w < 0.0 || u + w > 1.0) continue;
            const double t = glm::dot(e2, q) * inv;
            if (t > 1e-9 && t < best) {
                best = t;
                bestMesh = &mesh;
                bestTri = i;
                bestU = u;
                bestW = w;
            }
        }
    }
    if (!std::isfinite(best) || !bestMesh) return std::nullopt;
    const auto& v = bestMesh->vertices;
    const Vertex& va = v[bestMesh->indices[bestTri]];
    const Vertex& vb = v[bestMesh->indices[bestTri + 1]];
    const Vertex& vc = v[bestMesh->indices[bestTri + 2]];
    const glm::dvec3 geometric = glm::cross(glm::dvec3(vb.position) - glm::dvec3(va.position),
                                            glm::dvec3(vc.position) - glm::dvec3(va.position));
    glm::dvec3 n = glm::dvec3(va.normal) * (1.0 - bestU - bestW) + glm::dvec3(vb.normal) * bestU +
                   glm::dvec3(vc.normal) * bestW;
    double len = glm::length(n);
    if (!(len > 1e-12) || !std::isfinite(len)) {
        n = geometric;
        len = glm::length(n);
    }
    n = len > 0.0 && std::isfinite(len) ? n / len : -d;
    if (glm::dot(n, d) > 0.0) n = -n; // the side the ray sees
    return ModelHit{ray.at(best), n, std::size_t(bestMesh - model.meshes.data())};
}

std::optional<glm::dvec3> intersectModel(const Model& model, const Ray& ray) {
    const auto hit = intersectModelWithNormal(model, ray);
    if (!hit) return std::nullopt;
    return hit->point;
}

glm::dvec3 mirrorDirection(const glm::dvec3& incident, const glm::dvec3& normal) {
    return incident - 2.0 * glm::dot(incident, normal) * normal;
}

std::optional<double> closestOnAxis(const Ray& ray, const glm::dvec3& origin, const glm::dvec3& axis) {
    // Lines origin + t a and ray.origin + s d: minimise |w + t a - s d| with w = origin - ray.origin.
    const glm::dvec3 w = origin - ray.origin;
    const double b = glm::dot(axis, ray.direction);
    const double denom = 1.0 - b * b;
    if (!(denom > 1e-9)) return std::nullopt;
    const double t = (b * glm::dot(w, ray.direction) - glm::dot(w, axis)) / denom;
    if (!std::isfinite(t)) return std::nullopt;
    return t;
}

bool hitsPolygon(const ScreenProjector& projector, const std::vector<glm::dvec3>& polygon,
                 const QPointF& screen, double maxPixels) {
    if (polygon.size() < 3) return false;
    std::vector<QPointF> pts;
    pts.reserve(polygon.size());
    for (const glm::dvec3& p : polygon) {
        const auto s = projector.project(p);
        if (!s) return false;
        pts.push_back(*s);
    }
    bool inside = false;
    for (size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
        const QPointF &a = pts[i], &b = pts[j];
        if (pointSegmentDistance(screen, a, b) <= maxPixels) return true;
        if ((a.y() > screen.y()) != (b.y() > screen.y()) &&
            screen.x() < (b.x() - a.x()) * (screen.y() - a.y()) / (b.y() - a.y()) + a.x())
            inside = !inside;
    }
    return inside;
}

glm::dvec3 dragInViewPlane(const ScreenProjector& projector, const glm::dvec3& start, const QPointF& from,
                           const QPointF& to) {
    const glm::dvec3 n = projector.viewDirection();
    const auto t0 = intersectPlane(projector.ray(from), start, n);
    const auto t1 = intersectPlane(projector.ray(to), start, n);
    if (!t0 || !t1) return start;
    const glm::dvec3 moved = start + (projector.ray(to).at(*t1) - projector.ray(from).at(*t0));
    return std::isfinite(moved.x) && std::isfinite(moved.y) && std::isfinite(moved.z) ? moved : start;
}

glm::dvec3 dragAlongViewAxis(const ScreenProjector& projector, const glm::dvec3& start, const QPointF& from,
                             const QPointF& to, double unitsPerPixel) {
    const double pixels = from.y() - to.y(); // up = away from the camera
    // Along the line of sight through the point, so it stays under the cursor (perspective); the view
    // direction for orthographic views (the same thing there).
    const glm::dvec3 sight = start - projector.eye();
    const double len = glm::length(sight);
    const glm::dvec3 dir =
        projector.isOrthographic() || !(len > 0.0) ? projector.viewDirection() : sight / len;
    return start + dir * (pixels * unitsPerPixel);
}

std::vector<glm::dvec3> coneRim(const glm::dvec3& apex, const glm::dvec3& axis, double outerDegrees,
                                double length, int segments) {
    std::vector<glm::dvec3> rim;
    const double axisLen = glm::length(axis);
    if (!(axisLen > 0.0) || segments < 3) return rim;
    const glm::dvec3 a = axis / axisLen;
    const glm::dvec3 helper = std::abs(a.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(a, helper));
    const glm::dvec3 w = glm::cross(a, u);
    const double angle = glm::radians(std::clamp(outerDegrees, 0.0, 90.0));
    // The rim of a cone of slant length `length` (a 90° cone is a disc around the apex).
    const double along = length * std::cos(angle), radius = length * std::sin(angle);
    rim.reserve(size_t(segments));
    for (int i = 0; i < segments; ++i) {
        const double phi = 2.0 * M_PI * i / segments;
        rim.push_back(apex + a * along + radius * (std::cos(phi) * u + std::sin(phi) * w));
    }
    return rim;
}

double distanceToConeRim(const ScreenProjector& projector, const std::vector<glm::dvec3>& rim,
                         const QPointF& screen) {
    double best = kInf;
    for (size_t i = 0; i < rim.size(); ++i) {
        const auto a = projector.project(rim[i]);
        const auto b = projector.project(rim[(i + 1) % rim.size()]);
        if (a && b) best = std::min(best, pointSegmentDistance(screen, *a, *b));
    }
    return best;
}

std::optional<double> coneAngleUnderCursor(const ScreenProjector& projector, const glm::dvec3& apex,
                                           const glm::dvec3& axis, const QPointF& screen,
                                           double rimDistance) {
    const double axisLen = glm::length(axis);
    if (!(axisLen > 0.0)) return std::nullopt;
    const glm::dvec3 a = axis / axisLen;
    const glm::dvec3 v = projector.viewDirection();
    const Ray r = projector.ray(screen);
    if (std::abs(glm::dot(a, v)) > 0.5 && rimDistance > 0.0) {
        const glm::dvec3 centre = apex + a * rimDistance;
        const auto t = intersectPlane(r, centre, a);
        if (!t) return std::nullopt;
        const double radial = glm::length(r.at(*t) - centre);
        return glm::degrees(std::atan2(radial, rimDistance));
    }
    // Plane containing the axis, as perpendicular to the view as possible.
    const glm::dvec3 side = glm::cross(a, v);
    if (glm::length(side) < 1e-6) return std::nullopt;
    const glm::dvec3 normal = glm::normalize(glm::cross(side, a));
    const auto t = intersectPlane(r, apex, normal);
    if (!t) return std::nullopt;
    const glm::dvec3 toHit = r.at(*t) - apex;
    const double len = glm::length(toHit);
    if (!(len > 0.0)) return std::nullopt;
    const double c = std::clamp(glm::dot(toHit / len, a), -1.0, 1.0);
    return std::min(90.0, glm::degrees(std::acos(c)));
}

} // namespace lr
