#include "renderplan.h"

#include <QLoggingCategory>
#include <QStringList>
#include <algorithm>
#include <utility>

Q_LOGGING_CATEGORY(lcPlan, "lightrig.render.plan", QtInfoMsg)

namespace lr::render {

QString describeResources(PassResources r) {
    static const char* const names[] = {"lights",   "clusters", "g-buffer",    "scene-color", "scene-depth",
                                        "resolved", "output",   "shadow-maps", "environment"};
    QStringList out;
    for (int i = 0; i < int(std::size(names)); ++i)
        if (r & (1u << i)) out << QLatin1String(names[i]);
    return out.join(QLatin1Char('+'));
}

RenderPlan::RenderPlan() = default;
RenderPlan::~RenderPlan() = default;

bool RenderPlan::initialize() {
    for (RenderPass* p : std::initializer_list<RenderPass*>{&m_shadow, &m_gbuffer, &m_shaded, &m_lighting,
                                                            &m_background, &m_blend, &m_catcher, &m_resolve,
                                                            &m_present, &m_toneMap, &m_overlay})
        if (!p->initialize()) return false;
    return true;
}

void RenderPlan::release() {
    for (RenderPass* p : std::initializer_list<RenderPass*>{&m_shadow, &m_gbuffer, &m_shaded, &m_lighting,
                                                            &m_background, &m_blend, &m_catcher, &m_resolve,
                                                            &m_present, &m_toneMap, &m_overlay})
        p->release();
    m_passes.clear();
    m_hasKey = false;
}

const std::vector<RenderPass*>& RenderPlan::select(const PlanKey& key) {
    if (m_hasKey && key == m_key) return m_passes;
    m_key = key;
    m_hasKey = true;
    ++m_builds;
    m_passes.clear();
    // The shadow pass goes first (it writes shadow maps the geometry or lighting pass reads).
    if (key.shadows) m_passes.push_back(&m_shadow);
    // The environment behind the opaque surfaces, where they left the cleared depth; before the catcher's
    // shadows and the blended meshes, which write no depth and go over it. Deferred, it goes between the
    // G-pass (whose depth it needs) and the lighting, which shades only the covered pixels over it.
    if (key.deferred) {
        m_passes.push_back(&m_gbuffer);
        if (key.background) m_passes.push_back(&m_background);
        m_passes.push_back(&m_lighting);
    } else {
        m_passes.push_back(&m_shaded);
        if (key.background) m_passes.push_back(&m_background);
    }
    // The catcher's shadows over the opaque surfaces and the background, before anything blended.
    if (key.catcher) m_passes.push_back(&m_catcher);
    // Blended meshes after all opaque ones, shaded forward whatever the path.
    if (key.blend) m_passes.push_back(&m_blend);
    if (key.msaa && (key.hdr || key.overlays)) m_passes.push_back(&m_resolve);
    m_passes.push_back(key.hdr ? static_cast<RenderPass*>(&m_toneMap) : &m_present);
    if (key.overlays) m_passes.push_back(&m_overlay);
    const QString problem = check(m_passes, key.msaa);
    if (!problem.isEmpty()) qCWarning(lcPlan).noquote() << "render plan" << describe() << ":" << problem;
    qCDebug(lcPlan).noquote() << "render plan:" << describe();
    return m_passes;
}

bool RenderPlan::run(const FrameContext& frame, PassScene& scene) {
    bool ok = true;
    for (RenderPass* p : m_passes) {
        if (scene.resolveEnvironment && (p->reads() & resource::Environment)) {
            // The frame was planned with an environment still loading: it is needed from here on.
            const auto resolve = std::exchange(scene.resolveEnvironment, nullptr);
            if (!resolve(scene)) return false;
        }
        ok = p->run(frame, scene) && ok;
    }
    return ok;
}

QString RenderPlan::describe() const {
    QStringList names;
    for (const RenderPass* p : m_passes)
        names << QLatin1String(p->name());
    return names.join(QStringLiteral(" > "));
}

QString RenderPlan::check(const std::vector<RenderPass*>& passes, bool msaa) {
    PassResources available = resource::Lights | resource::Clusters | resource::Environment;
    // Without a shadow pass no light casts: the lit passes' shaders sample no map (nothing to wait for).
    if (std::none_of(passes.begin(), passes.end(),
                     [](const RenderPass* p) { return p->writes() & resource::ShadowMaps; }))
        available |= resource::ShadowMaps;
    QStringList problems;
    for (const RenderPass* p : passes) {
        if (const PassResources missing = p->reads() & ~available)
            problems << QStringLiteral("%1 reads %2 before anything writes it")
                            .arg(QLatin1String(p->name()), describeResources(missing));
        available |= p->writes();
        // A single-sample scene target is its own resolve.
        if (!msaa && (available & resource::SceneColor)) available |= resource::Resolved;
    }
    if (!(available & resource::Output)) problems << QStringLiteral("nothing writes the output");
    return problems.join(QStringLiteral("; "));
}

} // namespace lr::render
