#include "tracescene.h"

#include "core/shapinglights.h"

#include "core/envintegrate.h"
#include "core/prepare.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lr::trace {

namespace {

TextureSampler samplerOf(const Model& model, int index, bool srgb, const TextureSampling& sampling) {
    if (index < 0 || size_t(index) >= model.textures.size()) return {};
    return TextureSampler(model.textures[size_t(index)].image, srgb, sampling);
}

} // namespace

std::shared_ptr<const TraceScene> TraceScene::build(const SceneDescription& scene, QString* error) {
    const auto fail = [&](const QString& message) {
        if (error) *error = message;
        return std::shared_ptr<const TraceScene>();
    };
    const Rig& rig = scene.rig();
    if (!scene.model()) return fail(QStringLiteral("the path tracer needs a model"));
    if (rig.shading.model != ShadingModel::Pbr)
        return fail(QStringLiteral("the path-traced quality renders physically based rigs only, and the "
                                   "rig%1 uses classic shading "
                                   "(its Phong, Blinn-Phong and half-Lambert models are not reflectance "
                                   "functions a path can follow); "
                                   "render it with --shading pbr, or with a raster quality")
                        .arg(rig.name.isEmpty() ? QString() : QStringLiteral(" \"%1\"").arg(rig.name)));
    std::shared_ptr<TraceScene> t(new TraceScene);
    t->m_model = scene.sharedModel();
    const Model& model = *t->m_model;
    const SceneFrame frame = scene.frame();
    t->m_radius = model.bounds.radius();
    t->m_epsilon = 1e-4 * t->m_radius;
    if (rig.ground.mode == GroundMode::Visible) t->m_ground = scene.ground();
    if (rig.ground.mode == GroundMode::Catcher) t->m_catcher = groundPlane(model.bounds);

    std::vector<const Model*> models{&model};
    if (t->m_ground) models.push_back(t->m_ground.get());
    // Linking: the Embree scene's parts are the linking parts (model meshes, then a visible ground's).
    const LinkResolution& links = scene.links();
    t->m_linked = links.active;
    if (t->m_linked) {
        t->m_litClass = links.litClass;
        t->m_catcherPart = std::uint32_t(scene.groundPart(0));
        if (t->m_litClass.size() <= t->m_catcherPart) t->m_litClass.resize(t->m_catcherPart + 1, 0);
    }
    t->m_embree =
        std::make_unique<EmbreeScene>(models, model.bounds.center(), EmbreeScene::shadowClassMasks(links));
    if (!t->m_embree->ok()) return fail(t->m_embree->error());
    for (const Model* m : models) {
        const int first = int(t->m_materials.size());
        for (const Material& material : m->materials) {
            MaterialTextures mt;
            mt.material = &material;
            mt.base = samplerOf(*m, material.baseColorTexture, true, material.baseColorSampling);
            mt.normal = samplerOf(*m, material.normalTexture, false, material.normalSampling);
            mt.emissive = samplerOf(*m, material.emissiveTexture, true, material.emissiveSampling);
            mt.metalRough =
                samplerOf(*m, material.metallicRoughnessTexture, false, material.metallicRoughnessSampling);
            mt.occlusion = samplerOf(*m, material.occlusionTexture, false, material.occlusionSampling);
            t->m_allOpaque = t->m_allOpaque && material.alphaMode == AlphaMode::Opaque;
            t->m_materials.push_back(std::move(mt));
        }
        for (const EmbreeScene::Part& part : t->m_embree->parts()) {
            if (part.model != m) continue;
            const Mesh& mesh = m->meshes[size_t(part.mesh)];
            const int material = std::clamp(mesh.material, 0, std::max(0, int(m->materials.size()) - 1));
            t->m_parts.push_back({m, &mesh, m->materials.empty() ? -1 : first + material});
        }
    }
    // Emissive triangles, in part order (EmissiveTriangles::probability finds them by part and index).
    for (size_t p = 0; p < t->m_parts.size(); ++p) {
        const PartInfo& part = t->m_parts[p];
        if (part.material < 0) continue;
        const double weight =
            envintegrate::luminance(glm::dvec3(t->m_materials[size_t(part.material)].material->emissive));
        if (!(weight > 0.0) || !std::isfinite(weight)) continue;
        std::vector<EmissiveTriangles::Triangle> tris;
        const Mesh& mesh = *part.mesh;
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            EmissiveTriangles::Triangle tri;
            const auto at = [&](size_t k) {
                return part.model->origin + glm::dvec3(mesh.vertices[mesh.indices[i + k]].position);
            };
            tri.p0 = at(0), tri.p1 = at(1), tri.p2 = at(2);
            tri.part = std::uint32_t(p), tri.triangle = std::uint32_t(i / 3);
            tri.area = 0.5 * glm::length(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
            tris.push_back(tri);
        }
        t->m_emissive.add(std::uint32_t(p), std::move(tris), weight);
    }
    t->m_emissive.finish(t->m_parts.size());

    t->m_settings = scene.shadeSettings();
    t->m_ambient = rig.ambient;
    t->m_groups = lightGroups(rig, {.hasEmissive = !t->m_emissive.empty(), .includeRims = false});
    const std::vector<int> groupOf = groupOfLights(rig, t->m_groups);
    const auto groupOfKind = [&](LightGroupKind kind) {
        for (size_t g = 0; g < t->m_groups.size(); ++g)
            if (t->m_groups[g].kind == kind) return int(g);
        return -1;
    };
    t->m_backgroundGroup = groupOfKind(LightGroupKind::Background); // always listed (alwaysBackground)
    const auto orBackground = [&](int g) { return g >= 0 ? g : t->m_backgroundGroup; };
    t->m_environmentGroup = orBackground(groupOfKind(LightGroupKind::Environment));
    t->m_emissiveGroup = orBackground(groupOfKind(LightGroupKind::Emissive));
    t->m_ambientGroup = orBackground(groupOfKind(LightGroupKind::Ambient));
    t->m_iesProfiles = scene.lightAssets().ies; // what the lights' ShadeLight::ies point to
    for (const QString& e : scene.lightAssets().errors)
        if (e.contains(QLatin1String(".ies.file: ")))
            t->m_warnings << QStringLiteral("%1 (the light is traced without its profile)").arg(e);
    for (size_t i = 0; i < rig.lights.size(); ++i) {
        const Light& light = rig.lights[i];
        if (!light.enabled) continue;
        if (light.type == LightType::Rim) {
            t->m_warnings << QStringLiteral(
                                 "the rim light \"%1\" is left out of the path-traced image (a rim "
                                 "light is not a physical emitter)")
                                 .arg(light.name);
            continue;
        }
        TraceLight l;
        l.group = orBackground(groupOf[i]);
        l.shade = prepareLight(rig, frame, glm::dmat4(1.0), light);
        if (const LightAssets& a = scene.lightAssets(); i < a.ies.size() && i < a.gobos.size()) {
            applyLightShaping(l.shade, light, a.ies[i].get(), a.gobos[i].get(), glm::dmat4(1.0)); // issue 39
            if (l.shade.gobo) t->m_gobos.push_back(a.gobos[i]); // kept alive with the traced scene
        }
        l.emitter = shadowEmitter(rig, frame, light);
        l.emitter.casts = true; // every light is occluded in the traced image, as the environment is
        if (links.active) l.litMask = links.litMask[i], l.emitter.shadowMask = links.shadowMask[i];
        if (light.isArea())
            l.area = light.type == LightType::Disk ? std::numbers::pi * l.shade.halfWidth * l.shade.halfWidth
                                                   : 4.0 * l.shade.halfWidth * l.shade.halfHeight;
        t->m_lights.push_back(l);
    }
    if (scene.environmentLights()) {
        const Environment& e = rig.environment;
        t->m_environment = EnvironmentMap(scene.environment()->image, e.intensity, e.rotation);
        t->m_environmentVisible = e.background != EnvironmentBackground::Color;
    }
    return t;
}

glm::vec2 TraceScene::uvAt(const PartInfo& part, const EmbreeHit& hit) const {
    const Mesh& m = *part.mesh;
    const size_t i = size_t(hit.triangle) * 3;
    const float u = float(hit.u), v = float(hit.v);
    return m.vertices[m.indices[i]].uv * (1.0f - u - v) + m.vertices[m.indices[i + 1]].uv * u +
           m.vertices[m.indices[i + 2]].uv * v;
}

double TraceScene::alphaAt(const EmbreeHit& hit, Sampler& sampler, bool* pass) const {
    *pass = false;
    const PartInfo& part = m_parts[hit.part];
    if (part.material < 0) return 1.0;
    const MaterialTextures& mt = m_materials[size_t(part.material)];
    const Material& mat = *mt.material;
    if (mat.alphaMode == AlphaMode::Opaque) return 1.0;
    double a = mat.baseColor.a;
    if (!mt.base.isNull()) a *= mt.base.sample(transformUv(mat.baseColorTransform, uvAt(part, hit))).a;
    if (part.mesh->hasVertexColors) {
        const Mesh& m = *part.mesh;
        const size_t i = size_t(hit.triangle) * 3;
        a *= m.vertices[m.indices[i]].color.a * (1.0 - hit.u - hit.v) +
             m.vertices[m.indices[i + 1]].color.a * hit.u + m.vertices[m.indices[i + 2]].color.a * hit.v;
    }
    if (mat.alphaMode == AlphaMode::Mask)
        *pass = !(a >= mat.alphaCutoff); // glTF: opaque where alpha >= cutoff (NaN passes)
    else
        *pass = !(sampler.next() < lighting::saturate(a));
    return a;
}

EmbreeHit TraceScene::intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tfar,
                                Sampler& sampler, std::uint32_t mask) const {
    double tnear = 0.0;
    for (int i = 0; i < 64; ++i) {
        const EmbreeHit h = m_embree->intersect(origin, dir, tnear, tfar, mask);
        if (!h.hit || m_allOpaque) return h;
        bool pass = false;
        alphaAt(h, sampler, &pass);
        if (!pass) return h;
        tnear = h.t + std::max(1e-3 * m_epsilon, 1e-6 * h.t);
    }
    return {};
}

bool TraceScene::unoccluded(const glm::dvec3& origin, const glm::dvec3& dir, double distance,
                            Sampler& sampler, std::uint32_t mask) const {
    if (m_allOpaque) return !m_embree->occluded(origin, dir, distance, 0.0, mask);
    return !intersect(origin, dir, distance, sampler, mask).hit;
}

SurfacePoint TraceScene::surface(const EmbreeHit& hit, const glm::dvec3& origin,
                                 const glm::dvec3& dir) const {
    SurfacePoint s;
    s.part = hit.part;
    const PartInfo& part = m_parts[hit.part];
    const Mesh& m = *part.mesh;
    const size_t i = size_t(hit.triangle) * 3;
    const Vertex& a = m.vertices[m.indices[i]];
    const Vertex& b = m.vertices[m.indices[i + 1]];
    const Vertex& c = m.vertices[m.indices[i + 2]];
    const double w0 = 1.0 - hit.u - hit.v, w1 = hit.u, w2 = hit.v;
    s.position = part.model->origin +
                 (w0 * glm::dvec3(a.position) + w1 * glm::dvec3(b.position) + w2 * glm::dvec3(c.position));
    if (!std::isfinite(s.position.x + s.position.y + s.position.z)) s.position = origin + hit.t * dir;
    const bool back = glm::dot(hit.normal, dir) > 0.0;
    s.geometric = back ? -hit.normal : hit.normal;
    const glm::dvec3 interpolated =
        w0 * glm::dvec3(a.normal) + w1 * glm::dvec3(b.normal) + w2 * glm::dvec3(c.normal);
    glm::dvec3 n = lighting::safeNormalize(interpolated, hit.normal);
    const glm::vec2 uv = a.uv * float(w0) + b.uv * float(w1) + c.uv * float(w2);
    const MaterialTextures* mt = part.material >= 0 ? &m_materials[size_t(part.material)] : nullptr;
    if (mt && !mt->normal.isNull()) {
        const Material& mat = *mt->material;
        const glm::dvec4 tan =
            w0 * glm::dvec4(a.tangent) + w1 * glm::dvec4(b.tangent) + w2 * glm::dvec4(c.tangent);
        const glm::dvec3 t =
            lighting::safeNormalize(glm::dvec3(tan) - n * glm::dot(n, glm::dvec3(tan)), glm::dvec3(0.0));
        const glm::dvec3 bt = glm::cross(n, t) * (tan.w < 0.0 ? -1.0 : 1.0);
        glm::dvec3 mp = glm::dvec3(mt->normal.sample(transformUv(mat.normalTransform, uv))) * 2.0 - 1.0;
        mp *= glm::dvec3(mat.normalScale, mat.normalScale, 1.0);
        n = lighting::safeNormalize(t * mp.x + bt * mp.y + n * mp.z, n);
    }
    if (glm::dot(n, s.geometric) < 0.0) n = -n;
    // A shading normal facing away from the viewer (normal maps, coarse meshes at the silhouette): the
    // geometric one, so no path leaves through the surface.
    s.normal = glm::dot(n, -dir) > 1e-4 ? n : s.geometric;
    if (!mt) return s;
    const Material& mat = *mt->material;
    glm::dvec4 base(mat.baseColor);
    if (!mt->base.isNull()) base *= glm::dvec4(mt->base.sample(transformUv(mat.baseColorTransform, uv)));
    if (m.hasVertexColors)
        base *= w0 * glm::dvec4(a.color) + w1 * glm::dvec4(b.color) + w2 * glm::dvec4(c.color);
    s.baseColor = glm::dvec3(base);
    s.metallic = mat.metallic;
    s.roughness = mat.roughness;
    if (!mt->metalRough.isNull()) {
        const glm::vec4 mr = mt->metalRough.sample(transformUv(mat.metallicRoughnessTransform, uv));
        s.metallic *= mr.b;
        s.roughness *= mr.g;
    }
    if (!mt->occlusion.isNull())
        s.occlusion = 1.0 + mat.occlusionStrength *
                                (mt->occlusion.sample(transformUv(mat.occlusionTransform, uv)).r - 1.0);
    s.emissive = glm::dvec3(mat.emissive);
    if (!mt->emissive.isNull())
        s.emissive *= glm::dvec3(mt->emissive.sample(transformUv(mat.emissiveTransform, uv)));
    return s;
}

glm::dvec3 TraceScene::offset(const SurfacePoint& s, const glm::dvec3& dir) const {
    return s.position + s.geometric * (glm::dot(dir, s.geometric) >= 0.0 ? m_epsilon : -m_epsilon);
}

double TraceScene::hitCatcher(const glm::dvec3& origin, const glm::dvec3& dir) const {
    if (!m_catcher || dir.y == 0.0) return -1.0;
    const double t = (m_catcher->height - origin.y) / dir.y;
    if (!(t > 0.0) || !std::isfinite(t)) return -1.0;
    const glm::dvec3 p = origin + t * dir;
    double minX = m_catcher->corners[0].x, maxX = minX, minZ = m_catcher->corners[0].z, maxZ = minZ;
    for (const glm::dvec3& c : m_catcher->corners) {
        minX = std::min(minX, c.x), maxX = std::max(maxX, c.x);
        minZ = std::min(minZ, c.z), maxZ = std::max(maxZ, c.z);
    }
    return p.x >= minX && p.x <= maxX && p.z >= minZ && p.z <= maxZ ? t : -1.0;
}

std::size_t TraceScene::bytes() const {
    return m_environment.bytes() + m_emissive.size() * sizeof(EmissiveTriangles::Triangle) +
           m_materials.size() * sizeof(MaterialTextures) + m_parts.size() * sizeof(PartInfo);
}

} // namespace lr::trace
