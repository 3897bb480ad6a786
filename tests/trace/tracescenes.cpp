#include "tracescenes.h"

#include "trace/sampler.h"
#include "trace/tracescene.h"

#include <cmath>

using namespace lr;

namespace tracetest {

Material pbrMaterial(const glm::vec3& base, float metallic, float roughness) {
    Material m;
    m.name = QStringLiteral("test");
    m.pbr = true;
    m.baseColor = glm::vec4(base, 1.0f);
    m.metallic = metallic;
    m.roughness = roughness;
    m.doubleSided = true;
    return m;
}

namespace {

void growBounds(Model& m) {
    bool first = true;
    for (const Mesh& mesh : m.meshes)
        for (const Vertex& v : mesh.vertices) {
            const glm::dvec3 p = m.origin + glm::dvec3(v.position);
            m.bounds.min = first ? p : glm::min(m.bounds.min, p);
            m.bounds.max = first ? p : glm::max(m.bounds.max, p);
            first = false;
        }
}

} // namespace

Model quadsModel(const std::vector<std::array<glm::dvec3, 4>>& quads, const Material& material) {
    Model m;
    m.path = QStringLiteral("quads");
    m.materials.push_back(material);
    Mesh mesh;
    mesh.name = QStringLiteral("quads");
    for (const auto& q : quads) {
        const auto base = std::uint32_t(mesh.vertices.size());
        const glm::dvec3 n = glm::normalize(glm::cross(q[1] - q[0], q[2] - q[0]));
        const glm::vec2 uvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        for (int i = 0; i < 4; ++i) {
            Vertex v;
            v.position = glm::vec3(q[size_t(i)]);
            v.normal = glm::vec3(n);
            v.uv = uvs[i];
            v.tangent = glm::vec4(glm::vec3(glm::normalize(q[1] - q[0])), 1.0f);
            mesh.vertices.push_back(v);
        }
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    m.meshes.push_back(std::move(mesh));
    growBounds(m);
    return m;
}

Model openBox(const Material& material) {
    using V = glm::dvec3;
    return quadsModel({{V(-1, -1, 1), V(1, -1, 1), V(1, -1, -1), V(-1, -1, -1)}, // floor, up
                       {V(-1, -1, -1), V(1, -1, -1), V(1, 1, -1), V(-1, 1, -1)}, // back wall, +Z
                       {V(1, -1, 1), V(-1, -1, 1), V(-1, 1, 1), V(1, 1, 1)},     // front wall, -Z
                       {V(-1, -1, 1), V(-1, -1, -1), V(-1, 1, -1), V(-1, 1, 1)}, // left wall, +X
                       {V(1, -1, -1), V(1, -1, 1), V(1, 1, 1), V(1, 1, -1)}},    // right wall, -X
                      material);
}

void merge(Model& a, const Model& b) {
    const int offset = int(a.materials.size());
    a.materials.insert(a.materials.end(), b.materials.begin(), b.materials.end());
    for (Mesh mesh : b.meshes) {
        for (Vertex& v : mesh.vertices)
            v.position = glm::vec3(b.origin - a.origin + glm::dvec3(v.position));
        mesh.material += offset;
        a.meshes.push_back(std::move(mesh));
    }
    growBounds(a);
}

std::shared_ptr<const LoadedEnvironment> uniformEnvironment(const glm::vec3& radiance, int width) {
    auto env = std::make_shared<LoadedEnvironment>();
    env->spec.source = EnvironmentSource::Image;
    env->spec.file = QStringLiteral("uniform");
    env->source = QStringLiteral("uniform");
    env->image.width = width;
    env->image.height = width / 2;
    env->image.texels.assign(size_t(width) * size_t(width / 2), radiance);
    return env;
}

Rig pbrRig(bool environment) {
    Rig rig;
    rig.name = QStringLiteral("test");
    rig.space = RigSpace::World;
    rig.shading.model = ShadingModel::Pbr;
    if (environment) {
        rig.environment.source = EnvironmentSource::Image;
        rig.environment.file = QStringLiteral("uniform");
    }
    return rig;
}

std::unique_ptr<SceneDescription> describe(const Model& model, const Rig& rig,
                                           std::shared_ptr<const LoadedEnvironment> environment) {
    auto d = std::make_unique<SceneDescription>();
    d->setModel(std::make_shared<const Model>(model));
    d->setRig(rig);
    d->setEnvironment(std::move(environment));
    return d;
}

double meanChannel(const FloatImage& image, int c) {
    double sum = 0.0;
    for (const glm::vec4& p : image.pixels)
        sum += p[c];
    return image.pixels.empty() ? 0.0 : sum / double(image.pixels.size());
}

bool allFinite(const FloatImage& image) {
    for (const glm::vec4& p : image.pixels)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w))
            return false;
    return true;
}

ViewCamera lookAt(const glm::dvec3& eye, const glm::dvec3& target, double fovDeg, const glm::dvec3& up) {
    ViewCamera c;
    c.eye = eye;
    c.target = target;
    c.up = up;
    c.yfovDeg = fovDeg;
    return c;
}

std::optional<lr::lighting::Surface<double>> viewSurfaceAt(const lr::trace::TraceScene& traced,
                                                           const lr::trace::CameraRays& rays,
                                                           const glm::dmat4& view, int x, int y) {
    const glm::dvec3 dir = rays.direction(x + 0.5, y + 0.5);
    lr::trace::Sampler sampler(0, 0);
    const lr::EmbreeHit hit = traced.intersect(rays.origin(), dir, 1e30, sampler);
    if (!hit.hit) return std::nullopt;
    const lr::trace::SurfacePoint p = traced.surface(hit, rays.origin(), dir);
    lr::lighting::Surface<double> s;
    s.position = glm::dvec3(view * glm::dvec4(p.position, 1.0));
    s.normal = glm::normalize(glm::dvec3(view * glm::dvec4(p.normal, 0.0)));
    s.albedo = p.baseColor;
    s.metallic = p.metallic;
    s.roughness = p.roughness;
    return s;
}

} // namespace tracetest
