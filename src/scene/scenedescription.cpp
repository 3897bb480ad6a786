#include "scenedescription.h"

#include "core/shapinglights.h"

#include "groundmesh.h"
#include "linkparts.h"

#include <algorithm>
#include <cmath>

namespace lr {

void SceneDescription::setModel(std::shared_ptr<const Model> model) {
    m_model = std::move(model);
    ++m_modelGeneration;
    m_links.reset();
    updateGround();
}

void SceneDescription::setRig(const Rig& rig) {
    const bool reload = !sameLightFiles(m_rig, rig) || m_assets.ies.size() != rig.lights.size();
    m_rig = rig;
    if (reload) m_assets = loadLightAssets(m_rig);
    ++m_rigRevision;
    m_links.reset();
    updateGround();
}

void SceneDescription::setEnvironment(std::shared_ptr<const LoadedEnvironment> environment) {
    m_loading = {};
    m_environment = std::move(environment);
}

void SceneDescription::setEnvironment(QFuture<EnvironmentLoadResult> loading) {
    m_environment.reset();
    m_loading = std::move(loading);
}

bool SceneDescription::waitForEnvironment(QString* error) {
    if (!m_loading.isValid()) return true;
    const EnvironmentLoadResult r = m_loading.result();
    m_loading = {};
    m_environment = r.environment;
    if (m_environment) return true;
    if (error) *error = r.error.isEmpty() ? QStringLiteral("the environment did not load") : r.error;
    return false;
}

void SceneDescription::updateGround() {
    const Ground& g = m_rig.ground;
    if (!m_model || g.mode == GroundMode::Off) {
        m_ground.reset();
        m_groundGeneration = -1;
        return;
    }
    if (m_ground && m_groundGeneration == m_modelGeneration && m_groundBuilt.color == g.color) return;
    m_ground = std::make_shared<const Model>(render::groundModel(groundPlane(m_model->bounds), g));
    m_groundBuilt = g;
    m_groundGeneration = m_modelGeneration;
    ++m_groundRevision;
}

Bounds SceneDescription::bounds() const {
    if (m_model) return m_model->bounds;
    Bounds b;
    b.min = glm::dvec3(-1.0 / std::sqrt(3.0));
    b.max = -b.min;
    return b;
}

Bounds SceneDescription::drawnBounds() const {
    return m_model ? render::drawnBounds(bounds(), m_rig.ground) : bounds();
}

SceneFrame SceneDescription::frame() const {
    const Bounds b = bounds();
    return {b.center(), b.radius()};
}

SceneFrame SceneDescription::reach() const {
    const Bounds b = drawnBounds();
    return {b.center(), b.radius()};
}

const LinkResolution& SceneDescription::links() const {
    if (!m_links) m_links = resolveLinks(m_rig.lights, linkParts(m_model.get(), m_ground.get()));
    return *m_links;
}

std::size_t SceneDescription::groundPart(std::size_t mesh) const {
    return linkPartOfGround(m_model.get(), mesh);
}

std::vector<lighting::ShadeLight<double>> SceneDescription::lights(const glm::dmat4& view) const {
    std::vector<lighting::ShadeLight<double>> lights = prepareLights(m_rig, frame(), view);
    applyLightShaping(lights, m_rig, m_assets.ies, m_assets.gobos, view); // issue 39: into this description
    return lights;
}

lighting::ShadeSettings<double> SceneDescription::shadeSettings() const {
    return prepareSettings(m_rig, frame());
}

bool SceneDescription::environmentLights() const {
    return m_environment && !m_rig.environment.isNone();
}

int SceneDescription::shadowCasters() const {
    return int(std::count_if(m_rig.lights.begin(), m_rig.lights.end(),
                             [](const Light& l) { return l.hasShadow(); }));
}

} // namespace lr
