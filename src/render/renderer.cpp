#include "renderer.h"

#include "core/colour.h"
#include "environmentgl.h"
#include "framecontext.h"
#include "gpumodel.h"
#include "gputimer.h"
#include "groundmesh.h"
#include "lightset.h"
#include "programcache.h"
#include "readback.h"
#include "renderplan.h"
#include "shadowmaps.h"
#include "targets.h"

#include <QElapsedTimer>
#include <QLoggingCategory>
#include <QOpenGLContext>

#include <algorithm>
#include <cmath>

Q_LOGGING_CATEGORY(lcRender, "lightrig.render", QtInfoMsg)

namespace lr {

using namespace render;

namespace {

glm::dmat4 tileProjection(const ViewCamera& cam, QSize size, const QRect& tile) {
    const double aspect = double(size.width()) / double(std::max(1, size.height()));
    if (!tile.isValid()) return cam.projection(aspect);
    const double w = size.width(), h = size.height();
    const double x0 = 2.0 * tile.left() / w - 1.0, x1 = 2.0 * (tile.left() + tile.width()) / w - 1.0;
    const double y1 = 1.0 - 2.0 * tile.top() / h, y0 = 1.0 - 2.0 * (tile.top() + tile.height()) / h;
    return cam.projection(aspect, x0, y0, x1, y1);
}

} // namespace

Renderer::Renderer()
    : m_programs(std::make_unique<ProgramCache>()), m_model(std::make_unique<GpuModel>()),
      m_lights(std::make_unique<LightSet>()), m_targets(std::make_unique<Targets>()),
      m_plan(std::make_unique<RenderPlan>()), m_timer(std::make_unique<GpuTimer>()),
      m_shadows(std::make_unique<ShadowMaps>()), m_ground(std::make_unique<GpuModel>()),
      m_environmentGl(std::make_unique<EnvironmentGl>()) {}

Renderer::~Renderer() {
    if (!m_initialized) return;
    if (QOpenGLContext::currentContext() == m_context)
        releaseResources();
    else
        qCWarning(lcRender) << "Renderer destroyed without its context current: GL resources leak";
}

bool Renderer::fail(const QString& message, bool log) {
    m_lastError = message;
    if (log) qCWarning(lcRender).noquote() << message;
    return false;
}

bool Renderer::initialize(QString* error) {
    auto bail = [&](const QString& message) {
        fail(message);
        if (error) *error = message;
        return false;
    };
    m_context = QOpenGLContext::currentContext();
    if (!m_context) return bail(QStringLiteral("no current OpenGL context"));
    const QSurfaceFormat format = m_context->format();
    if (m_context->isOpenGLES() || format.version() < qMakePair(3, 3))
        return bail(QStringLiteral("LightRig needs OpenGL 3.3 core profile; this context offers %1 %2.%3")
                        .arg(m_context->isOpenGLES() ? QStringLiteral("OpenGL ES") : QStringLiteral("OpenGL"))
                        .arg(format.majorVersion())
                        .arg(format.minorVersion()));
    if (!initializeOpenGLFunctions())
        return bail(QStringLiteral("cannot resolve the OpenGL 3.3 core functions"));

    GLint maxSamples = 0, maxRenderbuffer = 0, maxTexture = 0, maxViewport[2] = {};
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    m_maxSamples = maxSamples;
    m_maxTargetSize = std::min({maxRenderbuffer, maxTexture, maxViewport[0], maxViewport[1]});

    m_lights->initialize(this);
    m_shadows->initialize(this);
    m_environmentGl->initialize(this);
    // F4 (fast tier): bilinear filtering within the nearest mip level instead of trilinear between two,
    // ~20% of DamagedHelmet's frame on llvmpipe (three 2048² textures); its error is measured with the rest.
    glGenSamplers(1, &m_fastSampler);
    glSamplerParameteri(m_fastSampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glSamplerParameteri(m_fastSampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(m_fastSampler, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glSamplerParameteri(m_fastSampler, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glGenVertexArrays(1, &m_emptyVao);
    glGenTextures(1, &m_slotTexture); // MeshPass::primeSamplerSlots samples it in every slot
    glBindTexture(GL_TEXTURE_2D, m_slotTexture);
    const std::uint32_t white = 0xffffffffu;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, &white);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    m_timer->initialize(this);
    m_initialized = true;

    QString message;
    if (!m_plan->initialize()) {
        releaseResources();
        return bail(QStringLiteral("cannot resolve the OpenGL 3.3 core functions for the render passes"));
    }
    // Compiled now so that a broken shader fails here, not at the first frame (the default tone map's
    // variant; others compile when a frame asks for them).
    if (!m_programs->fixedProgram(kToneMapShader, &message, toneMapDefine(RenderSettings().toneMap)) ||
        !m_programs->fixedProgram(kOverlayShader, &message)) {
        releaseResources();
        return bail(message);
    }
    qCDebug(lcRender) << "initialised:" << reinterpret_cast<const char*>(glGetString(GL_RENDERER))
                      << "max samples" << m_maxSamples << "max target" << m_maxTargetSize;
    return true;
}

void Renderer::releaseResources() {
    if (!m_initialized) return;
    m_programs->clear();
    m_model->release(this);
    m_targets->release(this);
    m_lights->release(this);
    m_shadows->release(this);
    m_environmentGl->release(this);
    m_ground->release(this);
    m_groundGeneration = -1;
    m_plan->release();
    m_timer->release(this);
    glDeleteSamplers(1, &m_fastSampler);
    glDeleteVertexArrays(1, &m_emptyVao);
    glDeleteTextures(1, &m_slotTexture);
    m_fastSampler = m_emptyVao = m_slotTexture = 0;
    m_initialized = false;
}

void Renderer::setShaderSourceOverride(const QString& name, const QByteArray& source) {
    m_programs->setSourceOverride(name, source);
}

bool Renderer::setModel(std::shared_ptr<const Model> model) {
    m_lights->invalidate();
    if (!m_initialized) return fail(QStringLiteral("setModel before initialize"));
    QString error;
    ++m_modelGeneration;
    const bool ok = m_model->upload(this, std::move(model), &error);
    m_stats.triangles = m_model->model() ? qint64(m_model->model()->triangleCount()) : 0;
    return ok || fail(error);
}

const Model* Renderer::model() const {
    return m_model->model();
}

bool Renderer::waitForInteractionProxies() {
    return m_initialized && m_model->updateProxies(this, true);
}

void Renderer::setRig(const Rig& rig) {
    m_lights->setRig(rig);
}

const Rig& Renderer::rig() const {
    return m_lights->rig();
}

void Renderer::setEnvironment(std::shared_ptr<const LoadedEnvironment> environment) {
    m_loadingEnvironment = {};
    m_environment = std::move(environment);
}

void Renderer::setEnvironment(QFuture<EnvironmentLoadResult> loading) {
    m_environment.reset();
    m_loadingEnvironment = std::move(loading);
}

bool Renderer::waitForEnvironment(QString* error) {
    if (!m_loadingEnvironment.isValid()) return true;
    const EnvironmentLoadResult r = m_loadingEnvironment.result();
    m_loadingEnvironment = {};
    m_environment = r.environment;
    if (m_environment) return true;
    if (error) *error = r.error.isEmpty() ? QStringLiteral("the environment did not load") : r.error;
    return false;
}

QString Renderer::renderPlan() const {
    return m_plan->describe();
}

Bounds Renderer::bounds() const {
    if (const Model* m = m_model->model()) return m->bounds;
    Bounds b;
    b.min = glm::dvec3(-1.0 / std::sqrt(3.0));
    b.max = -b.min;
    return b;
}

SceneFrame Renderer::sceneFrame() const {
    const Bounds b = bounds();
    return {b.center(), b.radius()};
}

Bounds Renderer::drawnBounds() const {
    return m_model->model() ? render::drawnBounds(bounds(), rig().ground) : bounds();
}

ViewCamera Renderer::effectiveCamera(const ViewCamera& camera) const {
    const Bounds b = drawnBounds(); // the ground too, when it is drawn
    return camera.withClipPlanes(b.center(), b.radius());
}

bool Renderer::updateGround() {
    const Ground& g = rig().ground;
    const Model* model = m_model->model();
    if (!model || g.mode == GroundMode::Off) {
        if (m_ground->model()) m_ground->release(this);
        m_groundGeneration = -1;
        return true;
    }
    if (m_ground->model() && m_groundGeneration == m_modelGeneration && m_groundUploaded.color == g.color)
        return true;
    QString error;
    auto mesh = std::make_shared<Model>(groundModel(groundPlane(model->bounds), g));
    if (!m_ground->upload(this, std::move(mesh), &error)) return fail(error);
    m_groundUploaded = g;
    m_groundGeneration = m_modelGeneration;
    ++m_groundRevision;
    return true;
}

bool Renderer::updateScene(const glm::dmat4& view) {
    if (!updateGround()) return false;
    m_shadowViews = m_model->model() ? planShadows(rig(), sceneFrame(), bounds()) : std::vector<ShadowView>();
    if (const auto casting = std::count_if(rig().lights.begin(), rig().lights.end(),
                                           [](const Light& l) { return l.hasShadow(); });
        casting > kMaxShadowCasters && !m_warnedCasters) {
        qCWarning(lcRender).noquote()
            << QStringLiteral("%1 lights cast shadows; at most %2 can: the first %2 in "
                              "the rig's order cast, the others light without shadow")
                   .arg(casting)
                   .arg(kMaxShadowCasters);
        m_warnedCasters = true;
    }
    // Lights are culled against everything drawn: the model and its ground.
    const Bounds reach = drawnBounds();
    const SceneFrame reachSphere{reach.center(), reach.radius()};
    m_lights->update(this, sceneFrame(), view, &m_stats, &m_shadowViews, &reachSphere);
    return true;
}

void Renderer::updateEnvironment(FrameContext* frame) {
    const Environment& spec = rig().environment;
    if (m_loadingEnvironment.isValid()) {
        // Planned with the rig's environment; the first pass that samples it waits (passScene).
        frame->environment = !spec.isNone();
    } else {
        QString error;
        if (!m_environmentGl->update(this, m_environment, &error) && !m_warnedEnvironment) {
            qCWarning(lcRender).noquote() << "environment lighting off:" << error;
            m_warnedEnvironment = true;
        }
        frame->environment = m_environment && !spec.isNone() && m_environmentGl->ready();
    }
    if (!frame->environment) return;
    frame->environmentUniforms.fromView = environmentFromView(frame->view, spec.rotation);
    frame->environmentUniforms.scale = float(std::exp2(std::clamp(spec.intensity, -20.0, 20.0)));
    frame->environmentUniforms.diffuse = environmentDiffuse(rig());
    if (!frame->transparent && spec.background != EnvironmentBackground::Color)
        frame->environmentBackgroundLod =
            spec.background == EnvironmentBackground::Blurred
                ? float(std::clamp(std::isfinite(spec.blur) ? spec.blur : 0.0, 0.0, 1.0) *
                        (kSpecularLevels - 1))
                : 0.0f;
}

bool Renderer::ensureTargets(QSize size, int samples, GLenum colorFormat) {
    const int n = std::min(samples > 1 ? samples : 0, m_maxSamples);
    Targets& t = *m_targets;
    if (t.fbo && t.size == size && t.samples == (n > 1 ? n : 0) && t.colorFormat == colorFormat) return true;
    QString error;
    if (t.create(this, size, n, colorFormat, &error)) return true;
    if (n > 1 && t.create(this, size, 0, colorFormat, &error)) {
        qCWarning(lcRender) << "multisampling unavailable for this target, rendering without it";
        return true;
    }
    return fail(error);
}

FrameContext Renderer::frameContext(const ViewCamera& camera, QSize size, const RenderSettings& settings,
                                    const QRect& tile) const {
    FrameContext f;
    f.settings = &settings;
    f.camera = effectiveCamera(camera);
    f.view = f.camera.view();
    f.projection = tileProjection(f.camera, size, tile);
    f.imageSize = size;
    f.targetSize = tile.isValid() ? tile.size() : size;
    f.colourPath = settings.hdrTarget ? ColourPath::Hdr : ColourPath::Display;
    f.exposureScale = float(colour::exposureScale(settings.exposureEV));
    f.toneMap = settings.toneMap;
    const QColor bg = settings.background.toRgb(); // sRGB
    f.backgroundLinear = colour::srgbToLinear(glm::vec3(bg.redF(), bg.greenF(), bg.blueF()));
    f.transparent = settings.transparentBackground;
    // The display path writes sRGB-encoded colours: the background as given.
    if (!settings.hdrTarget && !settings.transparentBackground)
        f.clearColour = glm::vec4(bg.redF(), bg.greenF(), bg.blueF(), 1.0f);
    f.shade = prepareSettings(rig(), sceneFrame());
    f.fast = settings.quality == Quality::Fast; // per vertex, no MSAA, forward only (F1, F3)
    f.overlays = settings.showGizmos || settings.showGrid;
    return f;
}

PassScene Renderer::passScene() {
    PassScene s;
    s.programs = m_programs.get();
    s.model = m_model.get();
    s.mutableModel = m_model.get();
    s.lights = m_lights.get();
    s.targets = m_targets.get();
    s.rig = &rig();
    s.frame = sceneFrame();
    s.bounds = bounds();
    s.drawnBounds = drawnBounds();
    s.stats = &m_stats;
    s.shadowViews = &m_shadowViews;
    s.shadows = m_shadows.get();
    s.modelGeneration = m_modelGeneration;
    s.groundRevision = m_groundRevision;
    s.ground = m_ground->model() ? m_ground.get() : nullptr;
    s.groundMode = rig().ground.mode;
    s.emptyVao = m_emptyVao;
    s.slotTexture = m_slotTexture;
    s.fastSampler = m_fastSampler;
    s.environment = m_environmentGl.get();
    if (m_loadingEnvironment.isValid())
        s.resolveEnvironment = [this](PassScene& scene) {
            if (!waitForEnvironment(&scene.error)) {
                scene.inputError = true; // the caller reports its file
                return false;
            }
            return m_environmentGl->update(this, m_environment, &scene.error);
        };
    return s;
}

bool Renderer::render(const ViewCamera& camera, QSize size, const RenderSettings& settings, GLuint targetFbo,
                      const QRect& tile) {
    if (!m_initialized) return fail(QStringLiteral("render before initialize"));
    if (size.isEmpty()) return fail(QStringLiteral("render: empty size"));
    QElapsedTimer cpu;
    cpu.start();
    FrameContext frame = frameContext(camera, size, settings, tile);
    frame.outputFbo = targetFbo;
    m_stats.lightsInRig = int(rig().lights.size());
    if (!updateScene(frame.view)) return false;
    updateEnvironment(&frame);
    const int samples = frame.fast ? 0 : settings.msaaSamples;
    // Few enough opaque materials: the deferred path samples their textures once per pixel (FrameContext).
    std::vector<AttributeMaterial> materials;
    const bool visibleGround = m_ground->model() && rig().ground.mode == GroundMode::Visible;
    if (settings.deferredTextures && m_model->model() &&
        !(m_model->appendMaterials(materials) && (!visibleGround || m_ground->appendMaterials(materials))))
        materials.clear();
    const int minLights = samples > 1 ? kDeferredMsaaMaxLights : 0;
    const bool wantDeferred =
        !frame.fast && (settings.shadingPath == ShadingPath::Deferred ||
                        (settings.shadingPath == ShadingPath::Auto && m_lights->count() >= minLights));
    const bool hdr = settings.hdrTarget;
    const GLenum colorFormat = !hdr ? GL_RGBA8 : settings.hdrFloat32 ? GL_RGBA32F : GL_RGBA16F;
    if (!ensureTargets(frame.targetSize, wantDeferred ? 0 : samples, colorFormat)) return false;
    frame.deferred = wantDeferred && m_model->model() != nullptr;
    frame.farLights = m_lights->farLights();
    frame.samples = m_targets->samples;
    QString error;
    if (frame.deferred && !m_targets->createGBuffer(this, &error)) return fail(error);
    if (frame.deferred) frame.attributeMaterials = std::move(materials);
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    // Fast lights the vertices, each with every light: clusters (per fragment) do not apply.
    frame.clustered =
        !frame.fast && m_model->model() &&
        m_lights->cluster(this, frame.projection, frame.targetSize, settings.clusteredShading, &m_stats);

    m_timer->begin(this, &m_stats.lastGpuMs);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    const auto& draws = m_model->draws();
    const bool blend = std::any_of(draws.begin(), draws.end(),
                                   [](const render::GpuDraw& d) { return d.features.alphaBlend; });
    const bool shadows = !m_shadowViews.empty();
    const bool catcher = m_ground->model() && rig().ground.mode == GroundMode::Catcher;
    if (!shadows)
        m_shadows->update(this, m_shadowViews, *m_model, m_modelGeneration, 0, -1, false, &m_stats, &error);
    m_plan->select({frame.deferred, hdr, frame.samples > 1, frame.overlays, blend, shadows, catcher,
                    frame.environmentBackgroundLod >= 0.0f});
    m_stats.renderPlanBuilds = m_plan->builds();
    PassScene scene = passScene();
    m_stats.gbufferKept = m_stats.surfacesKept = false; // the passes say otherwise when they run and keep
    const bool ok = m_plan->run(frame, scene) || fail(scene.error, !scene.inputError);
    m_stats.deferred = frame.deferred;
    m_stats.deferredTextures = !frame.attributeMaterials.empty();
    m_lastFrameHdr = hdr;
    m_timer->end(this);
    glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
    m_stats.shaderVariantsCompiled = m_programs->compiledCount();
    m_stats.shaderVariantsCached = m_programs->cachedCount();
    m_stats.lastCpuMs = double(cpu.nsecsElapsed()) * 1e-6;
    return ok;
}

bool Renderer::readRadiance(FloatImage* out) {
    if (!m_initialized || !m_targets->fbo || !m_lastFrameHdr)
        return fail(QStringLiteral("readRadiance: the last frame was not rendered with hdrTarget"));
    return readFloatAttachment(this, m_targets->fbo, GL_COLOR_ATTACHMENT0, m_targets->size, out) ||
           fail(QStringLiteral("reading back a float target failed"));
}

bool Renderer::renderGBuffer(const ViewCamera& camera, QSize size, const RenderSettings& settings,
                             GBuffer* out, const QRect& tile) {
    if (!m_initialized) return fail(QStringLiteral("renderGBuffer before initialize"));
    if (size.isEmpty()) return fail(QStringLiteral("renderGBuffer: empty size"));
    FrameContext frame = frameContext(camera, size, settings, tile);
    frame.gbufferReadBack = true;
    const QSize target = frame.targetSize;
    QString error;
    const GLenum format = m_targets->colorFormat ? m_targets->colorFormat : GLenum(GL_RGBA8);
    if (!ensureTargets(target, 0, format)) return false;
    if (!m_targets->createGBuffer(this, &error)) return fail(error);
    if (!updateScene(frame.view)) return false;
    updateEnvironment(&frame); // the occlusion texture is read when an environment lights the model
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    PassScene scene = passScene();
    bool ok = m_plan->gbufferPass().run(frame, scene) || fail(scene.error);
    FloatImage g[kGBufferTargets];
    for (int i = 0; i < kGBufferTargets; ++i)
        ok = (readFloatAttachment(this, m_targets->gbufferFbo, GLenum(GL_COLOR_ATTACHMENT0 + i), target,
                                  &g[i]) ||
              fail(QStringLiteral("reading back a float target failed"))) &&
             ok;
    decodeGBufferImages(g, readDepth(this, m_targets->gbufferFbo, target), frame.shade.model, out);
    m_stats.shaderVariantsCompiled = m_programs->compiledCount();
    m_stats.shaderVariantsCached = m_programs->cachedCount();
    return ok;
}

} // namespace lr
