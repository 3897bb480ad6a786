// The scene description (Cycles' and pbrt's idea): what is drawn, without GL. The model, the rig (its
// lights, shading, ground and environment settings), the loaded environment and the ground's mesh, with
// what every renderer derives from them in one place: the scene frame a model-space rig is anchored to, the
// bounds, the lights prepared for a view. The OpenGL raster builds its lit inputs from it
// (render/litinput.h), the double-precision reference reads it (render/reference.h makeReferenceScene), and
// so does any traced renderer: a feature is defined once (here and in src/core) and rendered three ways.
// The camera is scene/camera.h's ViewCamera; how a renderer samples or tone-maps is its own settings.
#pragma once

#include "core/lightlink.h"
#include "core/prepare.h"
#include "core/rig.h"
#include "environmentloader.h"
#include "lightassets.h"
#include "model/model.h"

#include <QFuture>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

namespace lr {

class SceneDescription {
  public:
    // A new model (nullptr: none). Its generation changes, and the ground is rebuilt over it.
    void setModel(std::shared_ptr<const Model> model);
    // Cheap: the ground's mesh is rebuilt only when the ground is switched on or its colour changed.
    void setRig(const Rig& rig);
    // The rig's environment decoded and prefiltered (scene/environmentloader.h), or nullptr: none.
    void setEnvironment(std::shared_ptr<const LoadedEnvironment> environment);
    // One still loading (loadEnvironment on a worker thread): environment() is null until
    // waitForEnvironment() takes its result; a renderer plans with the rig's environment meanwhile.
    void setEnvironment(QFuture<EnvironmentLoadResult> loading);
    bool environmentLoading() const { return m_loading.isValid(); }
    // Waits for an environment still loading; false with its error when it did not load (then none).
    bool waitForEnvironment(QString* error = nullptr);

    const Model* model() const { return m_model.get(); }
    const std::shared_ptr<const Model>& sharedModel() const { return m_model; }
    const Rig& rig() const { return m_rig; }
    const std::shared_ptr<const LoadedEnvironment>& environment() const { return m_environment; }
    // Changes with every setModel (what was made from the model, such as shadow maps, is stale).
    int modelGeneration() const { return m_modelGeneration; }
    // Changes with every setRig.
    int rigRevision() const { return m_rigRevision; }

    // The ground's mesh (scene/groundmesh.h) in world units over the model, or nullptr when the rig's
    // ground is off or there is no model. groundRevision() changes with every rebuild.
    const std::shared_ptr<const Model>& ground() const { return m_ground; }
    int groundRevision() const { return m_groundRevision; }

    // The model's bounds (a unit-radius box about the origin without a model), and grown by the ground's
    // square when it is drawn: what the camera's clip planes, light culling and the raster's scissor
    // enclose.
    Bounds bounds() const;
    Bounds drawnBounds() const;
    // The frame a model-space rig is anchored to: the model's bounding sphere (core/prepare.h).
    SceneFrame frame() const;
    // The sphere lights are culled against: the drawn bounds' (the model and its ground).
    SceneFrame reach() const;

    // The enabled lights prepared in double for a view (world -> view), in rig order, with their IES
    // profiles and gobo images (core/shapinglights.h; they point into lightAssets()), and the rig's
    // scene-wide shading settings
    // (core/prepare.h).
    std::vector<lighting::ShadeLight<double>> lights(const glm::dmat4& view) const;
    lighting::ShadeSettings<double> shadeSettings() const;
    // Whether the environment lights the scene: the rig's source is not None and one is loaded.
    bool environmentLights() const;
    // Lights that cast (Light::hasShadow(): enabled, with a shadow, of a type that casts).
    int shadowCasters() const;
    // Light and shadow linking (issue 38, core/lightlink.h) resolved over the model's parts and the ground's
    // (scene/linkparts.h), per rig light (Rig::lights order, disabled lights included). Inactive when no
    // light links: a renderer then compiles and tests nothing. Recomputed after setModel or setRig.
    const LinkResolution& links() const;
    // Part index (scene/linkparts.h) of a model mesh and of a ground mesh.
    std::size_t modelPart(std::size_t mesh) const { return mesh; }
    std::size_t groundPart(std::size_t mesh) const;
    // The IES profiles and gobo images the rig's lights name (scene/lightassets.h), per rig light; loaded by
    // setRig when the files it names change (a light whose file fails renders unshaped; errors says why).
    const LightAssets& lightAssets() const { return m_assets; }

  private:
    void updateGround();

    std::shared_ptr<const Model> m_model;
    Rig m_rig;
    std::shared_ptr<const LoadedEnvironment> m_environment;
    QFuture<EnvironmentLoadResult> m_loading; // valid while one is loading
    int m_modelGeneration = 0;
    int m_rigRevision = 0;
    std::shared_ptr<const Model> m_ground;
    Ground m_groundBuilt;        // what m_ground was built for
    int m_groundGeneration = -1; // ... over which model generation
    int m_groundRevision = 0;
    mutable std::optional<LinkResolution> m_links; // reset by setModel and setRig
    LightAssets m_assets;
};

} // namespace lr
