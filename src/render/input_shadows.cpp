#include "input_shadows.h"

#include "gpumodel.h"
#include "renderplan.h"
#include "scene/scenedescription.h"

namespace lr::render {

bool ShadowInput::prepare(InputFrame& f, QString* error) {
    const SceneDescription& scene = *f.scene;
    m_views =
        scene.model() ? planShadows(scene.rig(), scene.frame(), scene.bounds()) : std::vector<ShadowView>();
    // Shadow linking: the meshes each map leaves out (a changed set re-renders that map:
    // ShadowView::sameMap).
    if (scene.model()) linkShadowCasters(m_views, scene.links(), scene.model()->meshes.size());
    if (const int casting = scene.shadowCasters(); casting > kMaxShadowCasters && !m_warnedCasters) {
        qCWarning(lcRender).noquote()
            << QStringLiteral("%1 lights cast shadows; at most %2 can: the first %2 in "
                              "the rig's order cast, the others light without shadow")
                   .arg(casting)
                   .arg(kMaxShadowCasters);
        m_warnedCasters = true;
    }
    f.shadowViews = &m_views;
    f.plan->set(PlanBit::Shadows, !m_views.empty());
    // No caster: nothing samples a map, and none is kept.
    if (m_views.empty())
        return m_maps.update(f.gl, m_views, *f.model, scene.modelGeneration(), 0, -1, false, f.stats, error);
    return true;
}

bool ShadowInput::render(QOpenGLFunctions_3_3_Core* gl, const GpuModel& model, int modelGeneration,
                         GLuint program, int matrixLocation, bool wait, RenderStats* stats, QString* error) {
    return m_maps.update(gl, m_views, model, modelGeneration, program, matrixLocation, wait, stats, error);
}

} // namespace lr::render
