#include "renderer.h"

#include "cluster.h"
#include "clustergl.h"
#include "core/lighting.h"
#include "gizmos.h"
#include "gpumodel.h"
#include "lightpack.h"
#include "programcache.h"
#include "shadergen.h"
#include "targets.h"

#include <QElapsedTimer>
#include <QLoggingCategory>
#include <QOpenGLContext>

#include <algorithm>
#include <bit>
#include <cmath>
#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

Q_LOGGING_CATEGORY(lcRender, "lightrig.render", QtInfoMsg)

namespace lr {

using namespace render;

namespace {

constexpr GLuint kLightUnit = 3;

glm::dmat4 tileProjection(const ViewCamera& cam, QSize size, const QRect& tile) {
    const double aspect = double(size.width()) / double(std::max(1, size.height()));
    if (!tile.isValid()) return cam.projection(aspect);
    const double w = size.width(), h = size.height();
    const double x0 = 2.0 * tile.left() / w - 1.0, x1 = 2.0 * (tile.left() + tile.width()) / w - 1.0;
    const double y1 = 1.0 - 2.0 * tile.top() / h, y0 = 1.0 - 2.0 * (tile.top() + tile.height()) / h;
    return cam.projection(aspect, x0, y0, x1, y1);
}

QSize targetSize(QSize size, const QRect& tile) {
    return tile.isValid() ? tile.size() : size;
}

} // namespace

Renderer::Renderer()
    : m_programs(std::make_unique<ProgramCache>()), m_model(std::make_unique<GpuModel>()),
      m_targets(std::make_unique<Targets>()), m_clusters(std::make_unique<ClusterBuffers>()) {}

Renderer::~Renderer() {
    if (!m_initialized) return;
    if (QOpenGLContext::currentContext() == m_context)
        releaseResources();
    else
        qCWarning(lcRender) << "Renderer destroyed without its context current: GL resources leak";
}

bool Renderer::fail(const QString& message) {
    m_lastError = message;
    qCWarning(lcRender).noquote() << message;
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

    glGenBuffers(1, &m_lightBuffer);
    glGenTextures(1, &m_lightTexture);
    m_lightCapacity = 0;
    // F4 (fast tier): bilinear filtering within the nearest mip level instead of trilinear between two,
    // ~20% of DamagedHelmet's frame on llvmpipe (three 2048² textures); its error is measured with the rest.
    glGenSamplers(1, &m_fastSampler);
    glSamplerParameteri(m_fastSampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glSamplerParameteri(m_fastSampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(m_fastSampler, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glSamplerParameteri(m_fastSampler, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glGenVertexArrays(1, &m_emptyVao);
    glGenVertexArrays(1, &m_gizmoVao);
    glGenBuffers(1, &m_gizmoVbo);
    glBindVertexArray(m_gizmoVao);
    glBindBuffer(GL_ARRAY_BUFFER, m_gizmoVbo);
    const auto attrib = [&](GLuint loc, GLint n, std::size_t offset) {
        glEnableVertexAttribArray(loc);
        glVertexAttribPointer(loc, n, GL_FLOAT, GL_FALSE, GLsizei(sizeof(GizmoVertex)),
                              reinterpret_cast<const void*>(offset));
    };
    attrib(0, 3, offsetof(GizmoVertex, position));
    attrib(1, 4, offsetof(GizmoVertex, color));
    attrib(2, 2, offsetof(GizmoVertex, point));
    glBindVertexArray(0);
    glGenQueries(4, m_queries);
    m_queryNext = m_queriesPending = 0;
    m_initialized = true;

    QString message;
    if (!m_programs->fixedProgram(QStringLiteral("fullscreen.vert"), QStringLiteral("tonemap.frag"),
                                  &message) ||
        !m_programs->fixedProgram(QStringLiteral("gizmo.vert"), QStringLiteral("gizmo.frag"), &message)) {
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
    m_clusters->release(this);
    glDeleteBuffers(1, &m_lightBuffer);
    glDeleteTextures(1, &m_lightTexture);
    glDeleteSamplers(1, &m_fastSampler);
    m_fastSampler = 0;
    glDeleteVertexArrays(1, &m_emptyVao);
    glDeleteVertexArrays(1, &m_gizmoVao);
    glDeleteBuffers(1, &m_gizmoVbo);
    glDeleteQueries(4, m_queries);
    m_lightBuffer = m_lightTexture = m_emptyVao = m_gizmoVao = m_gizmoVbo = 0;
    m_lightCapacity = 0;
    m_packedLights.clear();
    m_initialized = false;
    m_lightsDirty = true;
}

void Renderer::setShaderSourceOverride(const QString& name, const QByteArray& source) {
    m_programs->setSourceOverride(name, source);
}

bool Renderer::setModel(std::shared_ptr<const Model> model) {
    m_lightsDirty = true;
    if (!m_initialized) return fail(QStringLiteral("setModel before initialize"));
    QString error;
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
    m_rig = rig;
    m_lightsDirty = true;
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

ViewCamera Renderer::effectiveCamera(const ViewCamera& camera) const {
    const SceneFrame f = sceneFrame();
    return camera.withClipPlanes(f.center, f.radius);
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

void Renderer::uploadLights(const glm::dmat4& view) {
    const SceneFrame frame = sceneFrame();
    std::vector<float> data;
    data.reserve(m_rig.lights.size() * 4 * kLightTexels);
    int count = 0;
    const double scale = prepareSettings(m_rig, frame).distanceScale;
    m_lightBounds.clear();
    m_boundedLights = 0;
    for (const Light& l : m_rig.lights) {
        if (!lightReaches(m_rig, frame, l, frame.center, frame.radius)) continue;
        const lighting::ShadeLight<double> prepared = prepareLight(m_rig, frame, view, l);
        m_lightBounds.push_back(lightBounds(prepared, scale));
        m_boundedLights += m_lightBounds.back().bounded ? 1 : 0;
        const LightTexels t = packLight(castLight<float>(prepared));
        data.insert(data.end(), t.begin(), t.end());
        ++count;
    }
    glBindBuffer(GL_TEXTURE_BUFFER, m_lightBuffer);
    if (count > m_lightCapacity || m_lightCapacity == 0) {
        m_lightCapacity = std::max({count, 2 * m_lightCapacity, 16});
        glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(m_lightCapacity) * kLightTexels * 16, nullptr,
                     GL_DYNAMIC_DRAW);
        glBindTexture(GL_TEXTURE_BUFFER, m_lightTexture);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, m_lightBuffer);
        m_packedLights.clear(); // the new store holds nothing yet
    }
    // Only the texels that changed go up: dragging one light of many sends that light's 128 bytes (a view
    // change moves every view-space light, and then everything differs).
    const auto same = [](float a, float b) {
        return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
    };
    size_t first = 0, last = data.size();
    if (m_packedLights.size() == data.size()) {
        first = size_t(std::mismatch(data.begin(), data.end(), m_packedLights.begin(), same).first -
                       data.begin());
        while (last > first && same(data[last - 1], m_packedLights[last - 1]))
            --last;
    }
    if (last > first)
        glBufferSubData(GL_TEXTURE_BUFFER, GLintptr(first * sizeof(float)),
                        GLsizeiptr((last - first) * sizeof(float)), data.data() + first);
    m_stats.lightBytesUploaded = qint64((last - first) * sizeof(float));
    m_packedLights = std::move(data);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    m_stats.lightsUploaded = count;
    m_uploadedView = view;
    m_lightsDirty = false;
}

// Bins the uploaded lights for this frame's projection and target (the viewport's size); false when
// clustering is off for this frame.
bool Renderer::clusterLights(const glm::dmat4& projection, const RenderSettings& settings) {
    m_stats.clustered = false;
    m_stats.clusterLightRefs = 0;
    const bool wanted = settings.clusteredShading > 0 ||
                        (settings.clusteredShading < 0 && m_boundedLights > kClusterMinBoundedLights);
    if (!wanted) return false;
    GLint viewport[4] = {};
    glGetIntegerv(GL_VIEWPORT, viewport);
    ClusterView cv;
    cv.projection = projection;
    cv.width = std::max(1, viewport[2]);
    cv.height = std::max(1, viewport[3]);
    // near and far back from the projection: P22 = -(f+n)/(f-n), P32 = -2fn/(f-n) (f infinite: P22 = -1)
    const double p22 = projection[2][2], p32 = projection[3][2];
    cv.znear = p32 / (p22 - 1.0);
    cv.zfar = p22 > -1.0 ? p32 / (p22 + 1.0) : std::numeric_limits<double>::infinity();
    if (!(cv.znear > 0.0) || !std::isfinite(cv.znear)) return false;
    const ClusterData data = binLights(m_lightBounds, cv);
    m_clusters->upload(this, data);
    m_stats.clustered = true;
    m_stats.clusterLightRefs = qint64(data.indices.size());
    m_clusterUniforms = {float(data.lookup.tileScale.x), float(data.lookup.tileScale.y),
                         float(data.lookup.znear), float(data.lookup.sliceScale)};
    m_clusterGlobal = data.globalCount;
    m_clusterGrid = {data.grid.tilesX, data.grid.tilesY, data.grid.slices};
    return true;
}

void Renderer::setClusterUniforms(QOpenGLShaderProgram* program) {
    const GLuint id = program->programId();
    glUniform1i(glGetUniformLocation(id, "uGlobalLightCount"), m_clusterGlobal);
    glUniform3i(glGetUniformLocation(id, "uClusterGrid"), m_clusterGrid.x, m_clusterGrid.y, m_clusterGrid.z);
    glUniform2f(glGetUniformLocation(id, "uClusterTileScale"), m_clusterUniforms.x, m_clusterUniforms.y);
    glUniform1f(glGetUniformLocation(id, "uClusterNear"), m_clusterUniforms.z);
    glUniform1f(glGetUniformLocation(id, "uClusterSliceScale"), m_clusterUniforms.w);
}

bool Renderer::drawModel(const glm::dmat4& view, const glm::dmat4& projection, const RenderSettings& settings,
                         int output) {
    const Model* model = m_model->model();
    m_stats.drawCalls = 0;
    m_stats.trianglesDrawn = 0;
    if (!model || m_model->draws().empty()) return true;
    const glm::dmat4 modelView = view * glm::translate(glm::dmat4(1.0), model->origin);
    const glm::mat4 mv(modelView), proj(projection);
    const glm::mat3 normalMatrix(glm::transpose(glm::inverse(glm::dmat3(modelView))));
    const lighting::ShadeSettings<double> shade = prepareSettings(m_rig, sceneFrame());
    const glm::vec3 ambient(shade.ambient);
    const RigFeatures rig = rigFeatures(m_rig);
    m_drawProjection = projection;
    const bool gpass = ShaderOutput(output) == ShaderOutput::GBuffer;
    // Fast lights the vertices, each with every light: clusters (per fragment) do not apply.
    const bool clustered = !gpass && settings.quality != Quality::Fast && clusterLights(projection, settings);
    const bool useProxies = settings.interactive && m_model->updateProxies(this);
    const RigFeatures shaded = settings.forceAllFeatures ? allRigFeatures(rig) : rig;
    const float exposureScale = float(std::exp2(std::clamp(settings.exposureEV, -60.0, 60.0)));

    // Group the draws by program so each variant is bound once per frame.
    std::vector<std::pair<FeatureKey, const GpuDraw*>> order;
    order.reserve(m_model->draws().size());
    for (const GpuDraw& d : m_model->draws()) {
        FeatureKey key;
        if (!gpass) key.rig = shaded; // the G-pass does no lighting
        key.material = d.features;
        key.quality = gpass ? Quality::Exact : settings.quality; // the G-buffer is the exact surface
        if (key.quality == Quality::Balanced) { // B2: an integer shininess becomes a chain of products
            const Material& m = d.material >= 0 ? model->materials[size_t(d.material)] : Material();
            const double n = m.shininess >= 0.0f ? double(m.shininess) : m_rig.shading.shininess;
            if (n >= 1.0 && n <= kMaxShininessInt && n == std::floor(n)) key.shininessInt = std::uint16_t(n);
        }
        key.output = ShaderOutput(output);
        key.clustered = clustered;
        order.emplace_back(key, &d);
    }
    std::stable_sort(order.begin(), order.end(),
                     [](const auto& a, const auto& b) { return a.first.bits() < b.first.bits(); });

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    glActiveTexture(GL_TEXTURE0 + kLightUnit);
    glBindTexture(GL_TEXTURE_BUFFER, m_lightTexture);
    if (clustered) m_clusters->bind(this);
    bool ok = true;
    MeshProgram* current = nullptr;
    const Material defaultMaterial;
    for (const auto& [key, d] : order) {
        QString error;
        MeshProgram* p = m_programs->meshProgram(key, &error);
        if (!p) {
            ok = fail(error);
            continue;
        }
        if (p != current) {
            current = p;
            p->program->bind();
            glUniformMatrix4fv(p->modelView, 1, GL_FALSE, glm::value_ptr(mv));
            glUniformMatrix3fv(p->normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
            glUniformMatrix4fv(p->projection, 1, GL_FALSE, glm::value_ptr(proj));
            glUniform3fv(p->ambient, 1, glm::value_ptr(ambient));
            glUniform1f(p->distanceScale, float(shade.distanceScale));
            glUniform1i(p->lightCount, m_stats.lightsUploaded);
            if (clustered) setClusterUniforms(p->program.get());
            if (p->exposureScale >= 0) glUniform1f(p->exposureScale, exposureScale);
            if (p->toneMap >= 0) glUniform1i(p->toneMap, int(settings.toneMap));
        }
        const Material& m = d->material >= 0 ? model->materials[size_t(d->material)] : defaultMaterial;
        glUniform4fv(p->baseColor, 1, glm::value_ptr(m.baseColor));
        glUniform3fv(p->emissive, 1, glm::value_ptr(m.emissive));
        glUniform3fv(p->specular, 1, glm::value_ptr(m.specular));
        glUniform1f(p->shininess, m.shininess >= 0.0f ? m.shininess : float(m_rig.shading.shininess));
        const GLuint textures[3] = {d->baseColorTexture, d->normalTexture, d->emissiveTexture};
        const GLuint sampler = key.quality == Quality::Fast ? m_fastSampler : 0;
        for (GLuint unit = 0; unit < 3; ++unit) {
            if (!textures[unit]) continue;
            glActiveTexture(GL_TEXTURE0 + unit);
            glBindTexture(GL_TEXTURE_2D, textures[unit]);
            glBindSampler(unit, sampler);
        }
        if (settings.cullBackFaces && !d->features.doubleSided)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
        const bool proxy = useProxies && d->lodVao;
        glBindVertexArray(proxy ? d->lodVao : d->vao);
        const GLsizei indices = proxy ? d->lodIndexCount : d->indexCount;
        glDrawElements(GL_TRIANGLES, indices, GL_UNSIGNED_INT, nullptr);
        m_stats.trianglesDrawn += indices / 3;
        ++m_stats.drawCalls;
    }
    glBindVertexArray(0);
    for (GLuint unit = 0; unit < 3; ++unit)
        glBindSampler(unit, 0);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glActiveTexture(GL_TEXTURE0);
    return ok;
}

bool Renderer::toneMapPass(QSize size, const RenderSettings& settings, GLuint targetFbo) {
    QString error;
    QOpenGLShaderProgram* p =
        m_programs->fixedProgram(QStringLiteral("fullscreen.vert"), QStringLiteral("tonemap.frag"), &error);
    if (!p) return fail(error);
    glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
    glViewport(0, 0, size.width(), size.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_FRAMEBUFFER_SRGB);
    p->bind();
    const QColor bg = settings.background.toRgb();
    p->setUniformValue("uHdr", 0);
    p->setUniformValue("uExposureScale", float(std::exp2(std::clamp(settings.exposureEV, -60.0, 60.0))));
    p->setUniformValue("uToneMap", int(settings.toneMap));
    p->setUniformValue("uBackground", float(lighting::srgbToLinear(bg.redF())),
                       float(lighting::srgbToLinear(bg.greenF())), float(lighting::srgbToLinear(bg.blueF())));
    p->setUniformValue("uTransparent", settings.transparentBackground);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m_targets->color);
    glBindVertexArray(m_emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    p->release();
    return true;
}

bool Renderer::gizmoPass(const glm::dmat4& view, const glm::dmat4& projection, double znear,
                         const RenderSettings& settings, QSize size) {
    GizmoOptions options;
    options.nearClip = znear * 0.5;
    options.lights = settings.showGizmos;
    options.grid = settings.showGrid;
    options.selected = settings.selectedLights;
    const GizmoGeometry g = buildGizmos(m_rig, sceneFrame(), bounds(), view, options);
    if (g.lines.empty() && g.points.empty()) return true;
    QString error;
    QOpenGLShaderProgram* p =
        m_programs->fixedProgram(QStringLiteral("gizmo.vert"), QStringLiteral("gizmo.frag"), &error);
    if (!p) return fail(error);
    // Gizmos are clipped on the CPU at half the near distance and drawn with depth clamping, so lights
    // outside the scene's depth range stay visible; the shader fades the parts behind the model.
    p->bind();
    p->setUniformValue("uSceneDepth", 0);
    p->setUniformValue("uHasDepth", m_model->model() != nullptr);
    glUniformMatrix4fv(p->uniformLocation("uProjection"), 1, GL_FALSE, glm::value_ptr(glm::mat4(projection)));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m_targets->depth);
    glViewport(0, 0, size.width(), size.height());
    glEnable(GL_DEPTH_CLAMP);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_PROGRAM_POINT_SIZE);
    glBindVertexArray(m_gizmoVao);
    glBindBuffer(GL_ARRAY_BUFFER, m_gizmoVbo);
    const auto draw = [&](const std::vector<GizmoVertex>& v, GLenum mode, bool points) {
        if (v.empty()) return;
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(GizmoVertex)), v.data(), GL_STREAM_DRAW);
        p->setUniformValue("uPoints", points);
        glDrawArrays(mode, 0, GLsizei(v.size()));
    };
    draw(g.lines, GL_LINES, false);
    draw(g.points, GL_POINTS, true);
    glBindVertexArray(0);
    glDisable(GL_PROGRAM_POINT_SIZE);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_CLAMP);
    p->release();
    return true;
}

void Renderer::beginTimer() {
    // Harvest finished queries (oldest first) without waiting for any.
    while (m_queriesPending > 0) {
        const int oldest = (m_queryNext - m_queriesPending + 4) % 4;
        GLint available = 0;
        glGetQueryObjectiv(m_queries[oldest], GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) break;
        GLuint64 ns = 0;
        glGetQueryObjectui64v(m_queries[oldest], GL_QUERY_RESULT, &ns);
        m_stats.lastGpuMs = double(ns) * 1e-6;
        --m_queriesPending;
    }
    if (m_queriesPending >= 4) return; // all in flight: skip timing this frame
    glBeginQuery(GL_TIME_ELAPSED, m_queries[m_queryNext]);
}

void Renderer::endTimer() {
    if (m_queriesPending >= 4) return;
    glEndQuery(GL_TIME_ELAPSED);
    m_queryNext = (m_queryNext + 1) % 4;
    ++m_queriesPending;
}

// The pixels of a `size` target that the box can cover under `viewProjection` (conservative; the whole
// target when a corner is behind the eye).
static QRect screenBounds(const Bounds& box, const glm::dmat4& viewProjection, QSize size) {
    double x0 = 1, y0 = 1, x1 = -1, y1 = -1;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 c((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                           (i & 4) ? box.max.z : box.min.z);
        const glm::dvec4 p = viewProjection * glm::dvec4(c, 1.0);
        if (!(p.w > 1e-12)) return QRect(QPoint(0, 0), size);
        x0 = std::min(x0, p.x / p.w), x1 = std::max(x1, p.x / p.w);
        y0 = std::min(y0, p.y / p.w), y1 = std::max(y1, p.y / p.w);
    }
    const auto px = [&](double ndc, int extent) {
        return std::clamp((ndc * 0.5 + 0.5) * extent, 0.0, double(extent));
    };
    const int left = int(std::floor(px(x0, size.width()))) - 1,
              right = int(std::ceil(px(x1, size.width()))) + 1;
    const int bottom = int(std::floor(px(y0, size.height()))) - 1,
              top = int(std::ceil(px(y1, size.height()))) + 1;
    return QRect(QPoint(0, 0), size).intersected(QRect(left, bottom, right - left, top - bottom)); // GL rows
}

bool Renderer::lightingPass(const RenderSettings& settings, bool hdr, const QRect& scissor) {
    FeatureKey key;
    key.rig = settings.forceAllFeatures ? allRigFeatures(rigFeatures(m_rig)) : rigFeatures(m_rig);
    key.quality = settings.quality; // never Fast: render() keeps the fast tier forward
    key.output = hdr ? ShaderOutput::Radiance : ShaderOutput::Display;
    key.deferredLighting = true;
    key.clustered = clusterLights(m_drawProjection, settings);
    QString error;
    MeshProgram* p = m_programs->meshProgram(key, &error);
    if (!p) return fail(error);
    const lighting::ShadeSettings<double> shade = prepareSettings(m_rig, sceneFrame());
    p->program->bind();
    glUniform3fv(p->ambient, 1, glm::value_ptr(glm::vec3(shade.ambient)));
    glUniform1f(p->distanceScale, float(shade.distanceScale));
    glUniform1i(p->lightCount, m_stats.lightsUploaded);
    if (p->exposureScale >= 0)
        glUniform1f(p->exposureScale, float(std::exp2(std::clamp(settings.exposureEV, -60.0, 60.0))));
    if (p->toneMap >= 0) glUniform1i(p->toneMap, int(settings.toneMap));
    if (key.clustered) {
        setClusterUniforms(p->program.get());
        m_clusters->bind(this);
    }
    glActiveTexture(GL_TEXTURE0 + kLightUnit);
    glBindTexture(GL_TEXTURE_BUFFER, m_lightTexture);
    for (int i = 0; i < kGBufferTargets; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE4 + i));
        glBindTexture(GL_TEXTURE_2D, m_targets->gbuffer[i]);
    }
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER); // the triangle lies on the far plane: passes where a surface was drawn
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    // Only the model's screen rectangle: a software rasteriser runs the shader for background blocks too,
    // even where the depth test rejects every pixel.
    glEnable(GL_SCISSOR_TEST);
    glScissor(scissor.x(), scissor.y(), scissor.width(), scissor.height());
    glBindVertexArray(m_emptyVao);
    if (!scissor.isEmpty()) glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_SCISSOR_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    p->program->release();
    return true;
}

bool Renderer::render(const ViewCamera& camera, QSize size, const RenderSettings& settings, GLuint targetFbo,
                      const QRect& tile) {
    if (!m_initialized) return fail(QStringLiteral("render before initialize"));
    if (size.isEmpty()) return fail(QStringLiteral("render: empty size"));
    QElapsedTimer cpu;
    cpu.start();
    const QSize target = targetSize(size, tile);
    const ViewCamera cam = effectiveCamera(camera);
    const glm::dmat4 view = cam.view();
    const glm::dmat4 projection = tileProjection(cam, size, tile);
    m_stats.lightsInRig = int(m_rig.lights.size());
    const bool hdr = settings.hdrTarget;
    if (m_lightsDirty || view != m_uploadedView) uploadLights(view);
    const bool fast = settings.quality == Quality::Fast; // per vertex, no MSAA, forward only (F1, F3)
    const int samples = fast ? 0 : settings.msaaSamples;
    const bool wantDeferred =
        !fast && (settings.shadingPath == ShadingPath::Deferred ||
                  (settings.shadingPath == ShadingPath::Auto &&
                   m_stats.lightsUploaded >= (samples <= 1 ? kDeferredMinLights : kDeferredMsaaMaxLights)));
    const GLenum colorFormat = !hdr ? GL_RGBA8 : settings.hdrFloat32 ? GL_RGBA32F : GL_RGBA16F;
    if (!ensureTargets(target, wantDeferred ? 0 : samples, colorFormat)) return false;
    const bool deferred = wantDeferred && m_model->model() != nullptr;
    QString error;
    if (deferred && !m_targets->createGBuffer(this, &error)) return fail(error);

    beginTimer();
    const bool overlays = settings.showGizmos || settings.showGrid;
    glViewport(0, 0, target.width(), target.height());
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    if (hdr || settings.transparentBackground) {
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    } else { // the display path writes sRGB-encoded colours: the background as given
        const QColor bg = settings.background.toRgb();
        glClearColor(float(bg.redF()), float(bg.greenF()), float(bg.blueF()), 1.0f);
    }
    bool ok = true;
    if (deferred) {
        // G-pass (depth and surfaces; the G-buffer's colour needs no clear: the lighting pass reads only
        // pixels a surface was drawn on), then the lighting pass into the scene target.
        glBindFramebuffer(GL_FRAMEBUFFER, m_targets->gbufferFbo);
        glClear(GL_DEPTH_BUFFER_BIT);
        ok = drawModel(view, projection, settings, int(ShaderOutput::GBuffer));
        glBindFramebuffer(GL_FRAMEBUFFER, m_targets->fbo);
        glClear(GL_COLOR_BUFFER_BIT);
        const glm::dmat4 toModel = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0));
        ok = lightingPass(settings, hdr,
                          screenBounds(m_model->model()->bounds, projection * view * toModel, target)) &&
             ok;
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, m_targets->drawFbo());
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        ok = drawModel(view, projection, settings, int(hdr ? ShaderOutput::Radiance : ShaderOutput::Display));
    }
    m_stats.deferred = deferred;
    const int w = target.width(), h = target.height();
    if (hdr) {
        if (m_targets->samples > 1) {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, m_targets->msaaFbo);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_targets->fbo);
            glBlitFramebuffer(0, 0, w, h, 0, 0, w, h,
                              GL_COLOR_BUFFER_BIT | (overlays ? GL_DEPTH_BUFFER_BIT : 0), GL_NEAREST);
        }
        ok = toneMapPass(target, settings, targetFbo) && ok;
    } else {
        if (m_targets->samples > 1 && overlays) { // the gizmos' occlusion test reads resolved depth
            glBindFramebuffer(GL_READ_FRAMEBUFFER, m_targets->msaaFbo);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_targets->fbo);
            glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        }
        glBindFramebuffer(GL_READ_FRAMEBUFFER, m_targets->drawFbo());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targetFbo);
        glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST); // resolves MSAA
        glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
    }
    m_lastFrameHdr = hdr;
    if (overlays) ok = gizmoPass(view, projection, cam.znear, settings, target) && ok;
    endTimer();
    glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
    m_stats.shaderVariantsCompiled = m_programs->compiledCount();
    m_stats.shaderVariantsCached = m_programs->cachedCount();
    m_stats.lastCpuMs = double(cpu.nsecsElapsed()) * 1e-6;
    return ok;
}

bool Renderer::readAttachment(GLuint fbo, GLenum attachment, QSize size, FloatImage* out) {
    out->width = size.width();
    out->height = size.height();
    out->pixels.assign(size_t(size.width()) * size_t(size.height()), glm::vec4(0.0f));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glReadBuffer(attachment);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    std::vector<glm::vec4> rows(out->pixels.size());
    glReadPixels(0, 0, size.width(), size.height(), GL_RGBA, GL_FLOAT, rows.data());
    for (int y = 0; y < size.height(); ++y) // GL's first row is the bottom one
        std::copy_n(rows.begin() + std::ptrdiff_t(y) * size.width(), size.width(),
                    out->pixels.begin() + std::ptrdiff_t(size.height() - 1 - y) * size.width());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return glGetError() == GL_NO_ERROR || fail(QStringLiteral("reading back a float target failed"));
}

bool Renderer::readRadiance(FloatImage* out) {
    if (!m_initialized || !m_targets->fbo || !m_lastFrameHdr)
        return fail(QStringLiteral("readRadiance: the last frame was not rendered with hdrTarget"));
    return readAttachment(m_targets->fbo, GL_COLOR_ATTACHMENT0, m_targets->size, out);
}

bool Renderer::renderGBuffer(const ViewCamera& camera, QSize size, const RenderSettings& settings,
                             GBuffer* out, const QRect& tile) {
    if (!m_initialized) return fail(QStringLiteral("renderGBuffer before initialize"));
    if (size.isEmpty()) return fail(QStringLiteral("renderGBuffer: empty size"));
    const QSize target = targetSize(size, tile);
    const ViewCamera cam = effectiveCamera(camera);
    const glm::dmat4 view = cam.view();
    QString error;
    const GLenum format = m_targets->colorFormat ? m_targets->colorFormat : GLenum(GL_RGBA8);
    if (!ensureTargets(target, 0, format)) return false;
    if (!m_targets->createGBuffer(this, &error)) return fail(error);
    if (m_lightsDirty || view != m_uploadedView) uploadLights(view);
    glBindFramebuffer(GL_FRAMEBUFFER, m_targets->gbufferFbo);
    glViewport(0, 0, target.width(), target.height());
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    bool ok = drawModel(view, tileProjection(cam, size, tile), settings, int(ShaderOutput::GBuffer));
    FloatImage g[kGBufferTargets];
    for (int i = 0; i < kGBufferTargets; ++i)
        ok = readAttachment(m_targets->gbufferFbo, GLenum(GL_COLOR_ATTACHMENT0 + i), target, &g[i]) && ok;
    // Coverage from depth (a surface wrote depth < 1).
    std::vector<float> depth(size_t(target.width()) * size_t(target.height()));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_targets->gbufferFbo);
    glReadPixels(0, 0, target.width(), target.height(), GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    for (FloatImage* f : {&out->position, &out->normal, &out->albedo, &out->specular, &out->emissive})
        *f = g[0];
    for (int y = 0; y < target.height(); ++y) {
        for (int x = 0; x < target.width(); ++x) {
            const float covered =
                depth[size_t(target.height() - 1 - y) * size_t(target.width()) + size_t(x)] < 1.0f;
            const glm::vec4 a = g[0].at(x, y), b = g[1].at(x, y), c = g[2].at(x, y), d = g[3].at(x, y);
            out->position.at(x, y) = glm::vec4(glm::vec3(a), covered);
            out->normal.at(x, y) = glm::vec4(glm::vec3(b), covered);
            out->albedo.at(x, y) = glm::vec4(glm::vec3(c), covered);
            out->specular.at(x, y) = glm::vec4(glm::vec3(d), a.w);
            out->emissive.at(x, y) = glm::vec4(b.w, c.w, d.w, covered);
        }
    }
    m_stats.shaderVariantsCompiled = m_programs->compiledCount();
    m_stats.shaderVariantsCached = m_programs->cachedCount();
    return ok;
}

} // namespace lr
