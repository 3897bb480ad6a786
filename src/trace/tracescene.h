// The scene as the path tracer reads it, built once from the scene description (scene/scenedescription.h)
// and read-only afterwards: the Embree scene of the model's triangles and a visible ground's
// (scene/embreescene.h, the one builder the traced shadow reference shares), the materials with their
// texture samplers, the rig's lights in world units, the emissive triangles, the environment map, and the
// shadow catcher's plane. Shading: physically based only. A classic-shading rig is refused (build() fails
// naming the rig and the way out, --shading pbr): its Phong and half-Lambert models are not reflectance
// functions, so there is no path they could be traced along.
//
// Light and shadow linking (issue 38, core/lightlink.h; SceneDescription::links()): the Embree scene's
// parts are the linking parts (the model's meshes, then a visible ground's), so a hit's part is its part.
// A light lights a surface point only when lights(light, point.part) — the integrator skips it there in
// next-event estimation and in what a BSDF ray that meets its emitter adds, so the estimator stays
// unbiased for the linked set — and its shadow rays carry its shadowMask (ShadowEmitter), so parts
// outside its shadow set let them through (Embree ray masks, embreescene.h). Without links nothing of it
// is set: every mask is all ones and linked() is false.
#pragma once

#include "environmentmap.h"
#include "lights.h"
#include "sampler.h"
#include "texture.h"

#include "core/lightgroups.h"
#include "model/ground.h"
#include "scene/embreescene.h"
#include "scene/scenedescription.h"

#include <QStringList>
#include <memory>
#include <optional>
#include <vector>

namespace lr::trace {

// A surface point as shaded: world position, the triangle's geometric normal and the shading normal (both
// unit, turned to the side the ray came from: every surface is two-sided to rays), and the material's
// values there (factor × texel × vertex colour, shaders/surface.glsl's order).
struct SurfacePoint {
    glm::dvec3 position{0.0};
    glm::dvec3 geometric{0.0, 0.0, 1.0};
    glm::dvec3 normal{0.0, 0.0, 1.0};
    glm::dvec3 baseColor{1.0};
    double metallic = 0.0, roughness = 1.0, occlusion = 1.0;
    glm::dvec3 emissive{0.0};
    std::uint32_t part = 0; // the hit's part (EmbreeHit::part): its linking part
};

class TraceScene {
  public:
    // The scene for `scene`'s model, rig and loaded environment; nullopt with *error on a classic rig, no
    // model, or Embree failing.
    static std::shared_ptr<const TraceScene> build(const SceneDescription& scene, QString* error);
    TraceScene(const TraceScene&) = delete;
    TraceScene& operator=(const TraceScene&) = delete;

    // The closest surface the ray reaches before tfar, skipping alpha-masked texels and BLEND texels
    // with probability 1 − alpha (stochastic transparency, `sampler`).
    // `mask`: a light's shadowMask for its shadow rays (only the parts that cast its shadow stop them).
    EmbreeHit intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tfar, Sampler& sampler,
                        std::uint32_t mask = kAllLinkClasses) const;
    // Whether nothing opaque lies on the segment (the same transparency as intersect()).
    bool unoccluded(const glm::dvec3& origin, const glm::dvec3& dir, double distance, Sampler& sampler,
                    std::uint32_t mask = kAllLinkClasses) const;
    SurfacePoint surface(const EmbreeHit& hit, const glm::dvec3& origin, const glm::dvec3& dir) const;
    // Where a ray leaving a surface starts: the point lifted off along its geometric normal (world units).
    glm::dvec3 offset(const SurfacePoint& s, const glm::dvec3& dir) const;

    const std::vector<TraceLight>& lights() const { return m_lights; }
    // Whether some light links (SceneDescription::links().active); false: lights() is true everywhere and
    // need not be asked.
    bool linked() const { return m_linked; }
    // Whether `light` lights the points of `part` (only meaningful when linked()).
    bool lights(const TraceLight& light, std::uint32_t part) const {
        return (light.litMask >> m_litClass[part]) & 1u;
    }
    // The shadow catcher's part: the ground's (SceneDescription::groundPart(0)).
    std::uint32_t catcherPart() const { return m_catcherPart; }
    const EmissiveTriangles& emissive() const { return m_emissive; }
    const EnvironmentMap& environment() const { return m_environment; }
    bool hasEnvironment() const { return !m_environment.isBlack(); }
    // What a camera ray that escapes shows: the environment (visible or blurred background; blurred is
    // shown sharp) or the background colour.
    bool environmentVisible() const { return m_environmentVisible; }
    // The rig's scene ambient and the lights' own ambient terms, added at every surface as the raster
    // does: irradiance × c_diff / π × occlusion (not traced: no path reaches them).
    const glm::dvec3& ambient() const { return m_ambient; }
    const lighting::ShadeSettings<double>& settings() const { return m_settings; }
    // The shadow catcher (rig ground mode catcher): a plane camera rays may stop at; nullopt otherwise.
    const std::optional<GroundPlane>& catcher() const { return m_catcher; }
    // Its distance along a camera ray, or a negative value.
    double hitCatcher(const glm::dvec3& origin, const glm::dvec3& dir) const;
    double epsilon() const { return m_epsilon; }
    double sceneRadius() const { return m_radius; }
    std::int64_t triangles() const { return m_embree->triangles(); }
    // Memory the traced scene holds besides the model (Embree's own is not counted).
    std::size_t bytes() const;
    // The light groups the traced image splits into (core/lightgroups.h, rims left out: the tracer leaves
    // them out; "emissive" when emissive() is not empty): each light's is TraceLight::group, the other
    // emitters' below. A kind the list lacks (no environment, no ambient) falls back to "background",
    // which is always there, so every contribution has a group; nothing falls back in practice, since a
    // kind is listed whenever the scene holds it.
    const std::vector<LightGroup>& groups() const { return m_groups; }
    int environmentGroup() const { return m_environmentGroup; } // its light and the visible background
    int emissiveGroup() const { return m_emissiveGroup; }       // emissive surfaces, hit or sampled
    int ambientGroup() const { return m_ambientGroup; }         // the rig's scene ambient
    int backgroundGroup() const { return m_backgroundGroup; }   // background colour, the catcher
    // What the traced image leaves out of the rig (rim lights), one line each.
    const QStringList& warnings() const { return m_warnings; }

  private:
    TraceScene() = default;
    struct MaterialTextures {
        const Material* material = nullptr;
        TextureSampler base, normal, emissive, metalRough, occlusion;
    };
    struct PartInfo {
        const Model* model = nullptr;
        const Mesh* mesh = nullptr;
        int material = -1; // index into m_materials
    };
    double alphaAt(const EmbreeHit& hit, Sampler& sampler, bool* pass) const;
    glm::vec2 uvAt(const PartInfo& part, const EmbreeHit& hit) const;

    std::shared_ptr<const Model> m_model, m_ground;
    std::unique_ptr<EmbreeScene> m_embree;
    std::vector<PartInfo> m_parts;
    std::vector<MaterialTextures> m_materials;
    bool m_allOpaque = true;
    std::vector<TraceLight> m_lights;
    std::vector<std::shared_ptr<const GoboImage>> m_gobos;        // what m_lights' shade.gobo point into
    std::vector<std::shared_ptr<const IesProfile>> m_iesProfiles; // kept alive for m_lights (issue 39)
    bool m_linked = false;
    std::vector<std::uint8_t> m_litClass; // per part, when linked
    std::uint32_t m_catcherPart = 0;
    EmissiveTriangles m_emissive;
    EnvironmentMap m_environment;
    bool m_environmentVisible = false;
    glm::dvec3 m_ambient{0.0};
    lighting::ShadeSettings<double> m_settings;
    std::optional<GroundPlane> m_catcher;
    double m_epsilon = 1e-4, m_radius = 1.0;
    QStringList m_warnings;
    std::vector<LightGroup> m_groups;
    int m_environmentGroup = 0, m_emissiveGroup = 0, m_ambientGroup = 0, m_backgroundGroup = 0;
};

} // namespace lr::trace
