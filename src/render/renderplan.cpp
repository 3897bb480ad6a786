#include "renderplan.h"

#include "litinput.h"
#include "targets.h"

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
    const bool deferred = key.has(PlanBit::Deferred), hdr = key.has(PlanBit::Hdr);
    const bool msaa = key.has(PlanBit::Msaa), overlays = key.has(PlanBit::Overlays);
    const bool background = key.has(PlanBit::Background);
    // The shadow pass goes first (it writes shadow maps the geometry or lighting pass reads).
    if (key.has(PlanBit::Shadows)) m_passes.push_back(&m_shadow);
    // The environment behind the opaque surfaces, where they left the cleared depth; before the catcher's
    // shadows and the blended meshes, which write no depth and go over it. Deferred, it goes between the
    // G-pass (whose depth it needs) and the lighting, which then reads the colour it left and shades only
    // the covered pixels over it.
    m_lighting.setOverBackground(background);
    if (deferred) {
        m_passes.push_back(&m_gbuffer);
        if (background) m_passes.push_back(&m_background);
        m_passes.push_back(&m_lighting);
    } else {
        m_passes.push_back(&m_shaded);
        if (background) m_passes.push_back(&m_background);
    }
    // The catcher's shadows over the opaque surfaces and the background, before anything blended.
    if (key.has(PlanBit::Catcher)) m_passes.push_back(&m_catcher);
    // Blended meshes after all opaque ones, shaded forward whatever the path.
    if (key.has(PlanBit::Blend)) m_passes.push_back(&m_blend);
    if (msaa && (hdr || overlays)) m_passes.push_back(&m_resolve);
    m_passes.push_back(hdr ? static_cast<RenderPass*>(&m_toneMap) : &m_present);
    if (overlays) m_passes.push_back(&m_overlay);
    const QString problem = check(m_passes, msaa);
    if (!problem.isEmpty()) qCWarning(lcPlan).noquote() << "render plan" << describe() << ":" << problem;
    qCDebug(lcPlan).noquote() << "render plan:" << describe();
    return m_passes;
}

bool RenderPlan::runPass(RenderPass& pass, const FrameContext& frame, PassScene& scene) {
    const bool ok = pass.run(frame, scene);
    if ((pass.writes() & resource::kDepthSharing) && !pass.keptOutputs()) scene.targets->wroteDepth(&pass);
    return ok;
}

bool RenderPlan::run(const FrameContext& frame, PassScene& scene) {
    bool ok = true;
    for (RenderPass* p : m_passes) {
        // An input still making what this pass reads (an environment loading) finishes it first.
        if (!scene.inputs->resolve(p->reads(), &scene.error, &scene.inputError)) return false;
        ok = runPass(*p, frame, scene) && ok;
    }
    return ok;
}

QString RenderPlan::describe() const {
    QStringList names;
    for (const RenderPass* p : m_passes)
        names << QLatin1String(p->name());
    return names.join(QStringLiteral(" > "));
}

QString RenderPlan::check(const std::vector<RenderPass*>& passes, bool msaa, PassResources provided) {
    PassResources written = 0;
    for (const RenderPass* p : passes)
        written |= p->writes();
    // A lit input that no input provides and no pass writes is not in this frame: reading it is void.
    PassResources available = provided | (resource::kLitInputs & ~(provided | written));
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
