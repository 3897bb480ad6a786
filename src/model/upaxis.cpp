#include "model/upaxis.h"

#include "core/prepare.h"
#include "core/rigjson.h"
#include "importdetail.h"

#include <algorithm>
#include <array>

namespace lr {

namespace {
constexpr std::array<const char*, kModelUpAxisCount> kNames{"+Y", "+Z", "+X", "-Y", "-Z", "-X"};
} // namespace

QString toString(ModelUpAxis axis) {
    const int i = std::clamp(int(axis), 0, kModelUpAxisCount - 1);
    return QString::fromLatin1(kNames[size_t(i)]);
}

ModelUpAxis modelUpAxisFromString(const QString& text, bool* ok) {
    for (int i = 0; i < kModelUpAxisCount; ++i)
        if (text == QLatin1String(kNames[size_t(i)])) {
            if (ok) *ok = true;
            return ModelUpAxis(i);
        }
    if (ok) *ok = false;
    return ModelUpAxis::YUp;
}

QStringList modelUpAxisNames() {
    QStringList names;
    for (int i = 0; i < kModelUpAxisCount; ++i)
        names << toString(ModelUpAxis(i));
    return names;
}

glm::dmat3 upAxisRotation(ModelUpAxis axis) {
    // Columns are the images of the file's x, y and z axes (glm is column-major).
    using V = glm::dvec3;
    switch (axis) {
    case ModelUpAxis::YUp:
        return glm::dmat3(1.0);
    case ModelUpAxis::ZUp: // (x, y, z) -> (x, z, -y): a quarter turn about x
        return glm::dmat3(V(1, 0, 0), V(0, 0, -1), V(0, 1, 0));
    case ModelUpAxis::NegZUp: // (x, y, z) -> (x, -z, y)
        return glm::dmat3(V(1, 0, 0), V(0, 0, 1), V(0, -1, 0));
    case ModelUpAxis::XUp: // (x, y, z) -> (-y, x, z): a quarter turn about z
        return glm::dmat3(V(0, 1, 0), V(-1, 0, 0), V(0, 0, 1));
    case ModelUpAxis::NegXUp: // (x, y, z) -> (y, -x, z)
        return glm::dmat3(V(0, -1, 0), V(1, 0, 0), V(0, 0, 1));
    case ModelUpAxis::NegYUp: // (x, y, z) -> (x, -y, -z): a half turn about x
        return glm::dmat3(V(1, 0, 0), V(0, -1, 0), V(0, 0, -1));
    }
    return glm::dmat3(1.0);
}

Model rotateModelUp(const Model& model, ModelUpAxis axis) {
    if (axis == ModelUpAxis::YUp) return model;
    return rotateModel(model, upAxisRotation(axis));
}

Model rotateModel(const Model& model, const glm::dmat3& r) {
    const glm::mat3 rf(r); // exact: entries are 0 and ±1
    Model m = model;
    m.origin = r * model.origin;
    for (Mesh& mesh : m.meshes)
        for (Vertex& v : mesh.vertices) {
            v.position = rf * v.position;
            v.normal = rf * v.normal;
            v.tangent = glm::vec4(rf * glm::vec3(v.tangent), v.tangent.w); // a rotation keeps handedness
        }
    // A signed axis permutation maps the box's corners onto the rotated box's corners: exact bounds.
    const glm::dvec3 a = r * model.bounds.min, b = r * model.bounds.max;
    m.bounds.min = glm::min(a, b);
    m.bounds.max = glm::max(a, b);
    for (Camera& c : m.cameras) {
        c.position = r * c.position;
        c.forward = r * c.forward;
        c.up = r * c.up;
    }
    for (Light& l : m.lights.lights) {
        const glm::dvec3 d = l.direction;
        l.position = r * l.position;
        l.direction = r * d;
        // Issue 39: an IES profile's or a gobo's rotation is measured about the direction from areaAxes'
        // reference, which does not turn with the model: measured again, so that the profile turns with it.
        const auto turned = [&](double degrees) {
            return detail::rollForUp(r * d, r * areaAxes(d, degrees).y);
        };
        if (l.ies) l.ies->rotation = normalizedEnvironmentRotation(turned(l.ies->rotation));
        if (l.gobo) l.gobo->rotation = turned(l.gobo->rotation);
    }
    return m;
}

} // namespace lr
