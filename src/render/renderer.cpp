#include "renderer.h"

#include "core/colour.h"
#include "framecontext.h"
#include "gpumodel.h"
#include "gputimer.h"
#include "input_ground.h"
#include "litinput.h"
#include "programcache.h"
#include "readback.h"
#include "renderplan.h"
#include "scaledoutput.h"
#include "targets.h"

#include <QElapsedTimer>
#include <QLoggingCategory>
#include <QOpenGLContext>

#include <algorithm>
#include <cmath>

Q_LOGGING_CATEGORY(lcRender, "lightrig.render", QtInfoMsg)

namespace lr {

using namespace render;

Renderer::Renderer()
    : m_programs(std::make_unique<ProgramCache>()), m_model(std::make_unique<GpuModel>()),
      m_inputs(std::make_unique<LitInputs>()), m_targets(std::make_unique<Targets>()),
      m_scaled(std::make_unique<ScaledOutput>()), m_plan(std::make_unique<RenderPlan>()),
      m_timer(std::make_unique<GpuTimer>()) {}

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

    m_inputs->initialize(this);
    m_targets->createCommon(this);
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
    m_targets->releaseCommon(this);
    m_scaled->release(this);
    m_inputs->release(this);
    m_plan->release();
    m_timer->release(this);
    m_initialized = false;
}

void Renderer::setShaderSourceOverride(const QString& name, const QByteArray& source) {
    m_programs->setSourceOverride(name, source);
}

bool Renderer::setModel(std::shared_ptr<const Model> model) {
    if (!m_initialized) {
        m_scene.setModel(nullptr);
        return fail(QStringLiteral("setModel before initialize"));
    }
    QString error;
    const bool ok = m_model->upload(this, model, &error);
    m_scene.setModel(m_model->model() ? std::move(model) : nullptr); // what is drawn
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
    m_scene.setRig(rig);
}

void Renderer::setEnvironment(std::shared_ptr<const LoadedEnvironment> environment) {
    m_scene.setEnvironment(std::move(environment));
}

void Renderer::setEnvironment(QFuture<EnvironmentLoadResult> loading) {
    m_scene.setEnvironment(std::move(loading));
}

bool Renderer::waitForEnvironment(QString* error) {
    return m_scene.waitForEnvironment(error);
}

QString Renderer::renderPlan() const {
    return m_plan->describe();
}

ViewCamera Renderer::effectiveCamera(const ViewCamera& camera) const {
    const Bounds b = drawnBounds(); // the ground too, when it is drawn
    return camera.withClipPlanes(b.center(), b.radius());
}

bool Renderer::ensureTargets(QSize size, int samples, GLenum colorFormat) {
    QString error;
    return m_targets->ensure(this, size, std::min(samples, m_maxSamples), colorFormat, &error) || fail(error);
}

FrameContext Renderer::frameContext(const ViewCamera& camera, QSize size, const RenderSettings& settings,
                                    const QRect& tile) const {
    FrameContext f;
    f.scene = &m_scene;
    f.settings = &settings;
    f.camera = effectiveCamera(camera);
    f.view = f.camera.view();
    f.projection = f.camera.projection(size, tile);
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
    f.shade = m_scene.shadeSettings();
    f.fast = settings.quality == Quality::Fast; // per vertex, no MSAA, forward only (F1, F3)
    f.overlays = settings.showGizmos || settings.showGrid || !settings.highlightedParts.empty();
    return f;
}

bool Renderer::prepareInputs(FrameContext& frame, PlanKey& plan, InputFrame& inputs) {
    inputs = {this, &m_scene, m_model.get(), &frame, &plan, &m_stats};
    QString error;
    if (!m_inputs->prepare(inputs, &error)) return fail(error);
    frame.features = frameRigFeatures(m_scene.rig(), frame.farLights, frame.settings->forceAllFeatures,
                                      frame.environment, frame.linking);
    return true;
}

std::vector<AttributeMaterial> Renderer::attributeMaterials() const {
    std::vector<AttributeMaterial> materials;
    const GroundInput* input = m_inputs->find<GroundInput>();
    const GpuModel* ground = input ? input->gpu() : nullptr;
    const bool visibleGround = ground && input->mode() == GroundMode::Visible;
    if (!m_model->model() || !m_model->appendMaterials(materials) ||
        (visibleGround && !ground->appendMaterials(materials)))
        materials.clear();
    return materials;
}

PassScene Renderer::passScene() {
    return {m_programs.get(), m_targets.get(), m_model.get(), m_inputs.get(), &m_stats, {}, false};
}

bool Renderer::render(const ViewCamera& camera, QSize size, const RenderSettings& settings, GLuint targetFbo,
                      const QRect& tile) {
    if (!m_initialized) return fail(QStringLiteral("render before initialize"));
    if (size.isEmpty()) return fail(QStringLiteral("render: empty size"));
    const QSize drawSize = scaledDrawSize(size, settings.renderScale);
    if (drawSize != size && !tile.isValid() && !settings.hdrTarget)
        return renderScaled(camera, size, drawSize, settings, targetFbo);
    QElapsedTimer cpu;
    cpu.start();
    FrameContext frame = frameContext(camera, size, settings, tile);
    frame.outputFbo = targetFbo;
    m_stats.lightsInRig = int(rig().lights.size());
    PlanKey plan;
    InputFrame inputs;
    if (!prepareInputs(frame, plan, inputs)) return false;
    const int samples = frame.fast ? 0 : settings.msaaSamples;
    const int minLights = samples > 1 ? kDeferredMsaaMaxLights : 0;
    const bool wantDeferred =
        !frame.fast && (settings.shadingPath == ShadingPath::Deferred ||
                        (settings.shadingPath == ShadingPath::Auto && frame.lightCount >= minLights));
    const bool hdr = settings.hdrTarget;
    const GLenum colorFormat = !hdr ? GL_RGBA8 : settings.hdrFloat32 ? GL_RGBA32F : GL_RGBA16F;
    if (!ensureTargets(frame.targetSize, wantDeferred ? 0 : samples, colorFormat)) return false;
    frame.deferred = wantDeferred && m_model->model() != nullptr;
    frame.samples = m_targets->samples;
    QString error;
    if (frame.deferred && !m_targets->createGBuffer(this, &error)) return fail(error);
    // Few enough opaque materials: the deferred path samples their textures once per pixel (FrameContext).
    if (frame.deferred && settings.deferredTextures) frame.attributeMaterials = attributeMaterials();
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    m_inputs->prepareTargets(inputs);

    m_timer->begin(this, &m_stats.lastGpuMs);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    const auto& draws = m_model->draws();
    plan.set(PlanBit::Deferred, frame.deferred).set(PlanBit::Hdr, hdr).set(PlanBit::Msaa, frame.samples > 1);
    plan.set(PlanBit::Overlays, frame.overlays);
    plan.set(PlanBit::Blend, std::any_of(draws.begin(), draws.end(),
                                         [](const render::GpuDraw& d) { return d.features.alphaBlend; }));
    m_plan->select(plan);
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
    m_stats.drawnSize = frame.targetSize;
    return ok;
}

bool Renderer::renderScaled(const ViewCamera& camera, QSize size, QSize drawSize,
                            const RenderSettings& settings, GLuint targetFbo) {
    QString error;
    if (!m_scaled->ensure(this, drawSize, &error)) return fail(error);
    RenderSettings inner = settings;
    inner.renderScale = 1.0;
    if (!render(camera, drawSize, inner, m_scaled->fbo)) return false;
    m_scaled->present(this, targetFbo, size);
    return true;
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
    // The inputs as for render(): the occlusion texture is read when an environment lights the model.
    PlanKey plan;
    InputFrame inputs;
    if (!prepareInputs(frame, plan, inputs)) return false;
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    PassScene scene = passScene();
    bool ok = RenderPlan::runPass(m_plan->gbufferPass(), frame, scene) || fail(scene.error);
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
