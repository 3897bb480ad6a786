#include "shadowmaps.h"

#include "gpumodel.h"
#include "textureunits.h"

#include <QElapsedTimer>
#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

namespace lr::render {

namespace {

// The cube faces: the axis each looks along and its right and up vectors (lookAt's s and u for the up
// hints +Y, or +Z for the ±Y faces). shaders/shadows.glsl holds the same table (kFaceRight, kFaceUp).
struct Face {
    glm::dvec3 forward, right, up;
};
constexpr Face kFaces[6] = {
    {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},  {{0, -1, 0}, {-1, 0, 0}, {0, 0, 1}},
    {{0, 0, 1}, {-1, 0, 0}, {0, 1, 0}}, {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},
};

glm::dvec3 upFor(const glm::dvec3& axis) {
    return std::abs(axis.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
}

// Near and far planes around a sphere seen from a point at `distance` from its centre; a point inside the
// sphere gets a near plane of far / 1000 (32-bit float depth keeps that ratio well).
void planesAround(double distance, double radius, double* znear, double* zfar) {
    *zfar = distance + radius;
    *znear = std::max(distance - radius, *zfar * 1e-3);
}

// The layers a casting light's map takes at `res` (an area light's kind depends on it, slightly).
int layersOf(const Light& l, const glm::dvec3& position, const glm::dvec3& c, double r, int res) {
    if (l.isArea())
        return areaShadowKind(position, c, r, res) == ShadowKind::Cube ? (l.area.twoSided ? 6 : 5) : 1;
    return shadowKindOf(l.type) == ShadowKind::Cube ? 6 : 1;
}

int arrayResolution(const Rig& rig, const std::vector<int>& casters, const std::vector<glm::dvec3>& positions,
                    const glm::dvec3& c, double r) {
    int res = 256;
    for (int i : casters)
        res = std::max(res, std::clamp(rig.lights[size_t(i)].shadow.resolution, 256, 4096));
    const auto layers = [&](int at) {
        qint64 n = 0;
        for (size_t k = 0; k < casters.size(); ++k)
            n += layersOf(rig.lights[size_t(casters[k])], positions[k], c, r, at);
        return n;
    };
    while (res > 256 && qint64(res) * res * 4 * layers(res) > kMaxShadowBytes)
        res /= 2;
    return res;
}

double finiteSize(double v) {
    return std::isfinite(v) ? std::max(0.0, v) : 0.0;
}

} // namespace

ShadowKind areaShadowKind(const glm::dvec3& position, const glm::dvec3& c, double r, int resolution) {
    const double dist = glm::length(c - position);
    if (!(dist > r)) return ShadowKind::Cube;
    const double tanSphere = r / std::sqrt(dist * dist - r * r);
    return tanSphere <= 1.0 + 2.0 * kAreaFilterTexels / resolution ? ShadowKind::Perspective
                                                                   : ShadowKind::Cube;
}

double areaPenumbraSize(const Light& l) {
    if (l.type == LightType::Disk) return 2.0 * finiteSize(l.area.radius);
    return 2.0 * std::sqrt(finiteSize(l.area.width) * finiteSize(l.area.height) / M_PI);
}

double areaSearchSize(const Light& l) {
    if (l.type == LightType::Disk) return 2.0 * finiteSize(l.area.radius);
    return std::hypot(finiteSize(l.area.width), finiteSize(l.area.height));
}

double ShadowView::texelScale() const {
    return kind == ShadowKind::Orthographic ? 2.0 * halfWidth / resolution : 2.0 * tanHalf / resolution;
}

glm::dmat4 ShadowView::faceViewProj(int face) const {
    if (kind != ShadowKind::Cube) return viewProj;
    const Face& local = kFaces[std::clamp(face, 0, 5)];
    const Face f{axes * local.forward, axes * local.right, axes * local.up}; // the face in world axes
    glm::dmat4 v(1.0); // rows: right, up, -forward (a right-handed view looking down -Z)
    for (int c = 0; c < 3; ++c) {
        v[c][0] = f.right[c];
        v[c][1] = f.up[c];
        v[c][2] = -f.forward[c];
    }
    v[3][0] = -glm::dot(f.right, position);
    v[3][1] = -glm::dot(f.up, position);
    v[3][2] = glm::dot(f.forward, position);
    return glm::perspective(2.0 * std::atan(tanHalf), 1.0, znear, zfar) * v;
}

bool ShadowView::sameMap(const ShadowView& o) const {
    return kind == o.kind && layer == o.layer && resolution == o.resolution && viewProj == o.viewProj &&
           position == o.position && znear == o.znear && zfar == o.zfar && tanHalf == o.tanHalf &&
           halfWidth == o.halfWidth && faces == o.faces && axes == o.axes;
}

namespace {

// An area light's map from its centre (docs/lighting-models.md "Shadows", "Area lights"): blockers behind
// its plane cannot shadow its front from there (every segment from the emitter to a point in front stays
// in front), so one centre serves the whole emitter; its extent only widens the PCSS filter.
void planAreaShadow(const Light& l, const glm::dvec3& position, const glm::dvec3& c, double r, double toWorld,
                    ShadowView* v) {
    v->position = position;
    v->emitter = areaPenumbraSize(l) * toWorld;
    v->searchEmitter = areaSearchSize(l) * toWorld;
    v->maxFilterTexels = kAreaFilterTexels;
    v->kind = areaShadowKind(position, c, r, v->resolution);
    const double dist = glm::length(c - position);
    planesAround(dist, r, &v->znear, &v->zfar);
    if (v->kind == ShadowKind::Cube) {
        const glm::dvec3 n = lighting::safeNormalize(l.direction, glm::dvec3(0, -1, 0));
        const AreaAxes a = areaAxes(n, l.area.roll);
        v->axes = glm::dmat3(a.y, a.x, n); // a.y × a.x = n: right-handed, face 4 (+Z) along n
        v->faces = l.area.twoSided ? 6 : 5;
        v->tanHalf = 1.0 + 2.0 * kAreaFilterTexels / v->resolution;
        return;
    }
    v->maxFilterTexels = kAreaMapFilterTexels;
    const double half = std::asin(r / dist);
    const glm::dvec3 look = (c - position) / dist;
    v->tanHalf = std::tan(half);
    v->viewProj = glm::perspective(2.0 * half, 1.0, v->znear, v->zfar) *
                  glm::lookAt(position, position + look, upFor(look));
}

} // namespace

std::vector<ShadowView> planShadows(const Rig& rig, const SceneFrame& frame, const Bounds& bounds) {
    std::vector<int> casters;
    std::vector<glm::dvec3> positions; // world
    for (size_t i = 0; i < rig.lights.size() && int(casters.size()) < kMaxShadowCasters; ++i) {
        if (!rig.lights[i].hasShadow()) continue;
        casters.push_back(int(i));
        positions.push_back(rig.lights[i].usesPosition() ? rigToWorld(rig, frame, rig.lights[i].position)
                                                         : glm::dvec3(0.0));
    }
    std::vector<ShadowView> views;
    if (casters.empty()) return views;
    const glm::dvec3 c = bounds.center();
    const double r = bounds.radius() * 1.02; // a margin for float rounding at the sphere's rim
    const int res = arrayResolution(rig, casters, positions, c, r);
    const double toWorld = 1.0 / distanceScale(rig, frame);
    int layer = 0;
    for (int i : casters) {
        const Light& l = rig.lights[size_t(i)];
        ShadowView v;
        v.rigIndex = i;
        v.layer = layer;
        v.resolution = res;
        v.bias = std::clamp(l.shadow.bias, 0.0, 16.0);
        v.normalOffset = std::clamp(l.shadow.normalOffset, 0.0, 16.0);
        v.kind = shadowKindOf(l.type);
        v.searchEmitter = 0.0;
        if (l.isArea()) {
            planAreaShadow(l, rigToWorld(rig, frame, l.position), c, r, toWorld, &v);
        } else if (v.kind == ShadowKind::Orthographic) {
            const glm::dvec3 d = lighting::safeNormalize(l.direction, glm::dvec3(0, -1, 0));
            v.position = c - d * (2.0 * r);
            v.znear = r;
            v.zfar = 3.0 * r;
            v.halfWidth = r;
            v.viewProj = glm::ortho(-r, r, -r, r, v.znear, v.zfar) * glm::lookAt(v.position, c, upFor(d));
            const double angle = std::clamp(l.shadow.angle, 0.0, 10.0);
            v.emitter = 2.0 * std::tan(0.5 * angle * M_PI / 180.0);
            v.searchEmitter = v.emitter;
        } else {
            v.position = rigToWorld(rig, frame, l.position);
            v.emitter = std::max(0.0, l.shadow.size) * toWorld;
            v.searchEmitter = v.emitter;
            const double dist = glm::length(c - v.position);
            planesAround(dist, r, &v.znear, &v.zfar);
            if (v.kind == ShadowKind::Cube) {
                v.tanHalf = 1.0 + 2.0 * kCubeMarginTexels / res;
            } else {
                // The cone, or only the part of it that can hold the model: the sphere's cone seen from
                // the light when that is narrower (a 179° spot keeps its texels on the model).
                const double outer = std::clamp(l.cone.outer, 0.01, 89.9) * M_PI / 180.0;
                const glm::dvec3 axis = lighting::safeNormalize(l.direction, glm::dvec3(0, -1, 0));
                const bool outside = dist > r;
                const double sphereHalf = outside ? std::asin(r / dist) : M_PI;
                double half = std::min(outer, sphereHalf);
                const glm::dvec3 look = half < outer ? (c - v.position) / dist : axis;
                half = std::min(half, 85.0 * M_PI / 180.0); // a light inside the model: at most 170°
                v.tanHalf = std::tan(half);
                v.viewProj = glm::perspective(2.0 * half, 1.0, v.znear, v.zfar) *
                             glm::lookAt(v.position, v.position + look, upFor(look));
            }
        }
        layer += v.layers();
        views.push_back(v);
    }
    return views;
}

qint64 shadowMapBytes(const std::vector<ShadowView>& views) {
    qint64 layers = 0;
    for (const ShadowView& v : views)
        layers += v.layers();
    return views.empty() ? 0 : layers * views.front().resolution * views.front().resolution * 4;
}

std::array<float, 4 * kShadowTexels> packShadow(const ShadowView& v, const glm::dmat4& view, int lightIndex) {
    const glm::dmat4 toWorld = glm::inverse(view);
    const glm::dmat4 m =
        v.kind == ShadowKind::Cube
            ? glm::dmat4(glm::transpose(v.axes)) * glm::translate(glm::dmat4(1.0), -v.position) * toWorld
            : v.viewProj * toWorld;
    std::array<float, 4 * kShadowTexels> t{};
    const glm::mat4 mf(m);
    std::copy_n(glm::value_ptr(mf), 16, t.begin());
    const float rest[] = {float(v.layer),         float(int(v.kind)),
                          float(v.znear),         float(v.zfar),
                          float(v.texelScale()),  float(v.bias),
                          float(v.normalOffset),  float(v.emitter),
                          float(lightIndex),      float(v.tanHalf),
                          float(v.resolution),    0.0f,
                          float(v.searchEmitter), float(v.maxFilterTexels),
                          float(v.layers()),      0.0f};
    std::copy(std::begin(rest), std::end(rest), t.begin() + 16);
    return t;
}

bool ShadowMaps::initialize(QOpenGLFunctions_3_3_Core* gl) {
    gl->glGenFramebuffers(1, &m_fbo);
    gl->glGenSamplers(1, &m_compare);
    gl->glGenSamplers(1, &m_raw);
    const GLfloat border[4] = {1.0f, 1.0f, 1.0f, 1.0f}; // outside a map: nothing in the way
    for (GLuint s : {m_compare, m_raw}) {
        const GLint filter = s == m_compare ? GL_LINEAR : GL_NEAREST;
        gl->glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, filter);
        gl->glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, filter);
        gl->glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
        gl->glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
        gl->glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
        gl->glSamplerParameteri(s, GL_TEXTURE_COMPARE_MODE,
                                s == m_compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
        gl->glSamplerParameteri(s, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    }
    return true;
}

void ShadowMaps::freeArray(QOpenGLFunctions_3_3_Core* gl) {
    gl->glDeleteTextures(1, &m_texture);
    m_texture = 0;
    m_resolution = m_layers = 0;
    m_bytes = 0;
    m_rendered.clear();
}

void ShadowMaps::release(QOpenGLFunctions_3_3_Core* gl) {
    freeArray(gl);
    gl->glDeleteFramebuffers(1, &m_fbo);
    gl->glDeleteSamplers(1, &m_compare);
    gl->glDeleteSamplers(1, &m_raw);
    m_fbo = m_compare = m_raw = 0;
    m_modelGeneration = -1;
}

bool ShadowMaps::update(QOpenGLFunctions_3_3_Core* gl, const std::vector<ShadowView>& views,
                        const GpuModel& model, int modelGeneration, GLuint depthProgram, int matrixLocation,
                        bool wait, RenderStats* stats, QString* error) {
    stats->shadowMapsRendered = 0;
    stats->shadowLayersRendered = 0;
    stats->shadowMapMs = 0.0;
    stats->shadowCasters = int(views.size());
    if (views.empty() || !model.model()) {
        if (m_texture) freeArray(gl);
        stats->shadowMapBytes = 0;
        return true;
    }
    int layers = 0;
    for (const ShadowView& v : views)
        layers += v.layers();
    const int res = views.front().resolution;
    if (res != m_resolution || layers != m_layers) {
        freeArray(gl);
        while (gl->glGetError() != GL_NO_ERROR) {
        }
        gl->glGenTextures(1, &m_texture);
        gl->glBindTexture(GL_TEXTURE_2D_ARRAY, m_texture);
        gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
        gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl->glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, res, res, layers, 0,
                         GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
        gl->glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
        if (const GLenum e = gl->glGetError(); e != GL_NO_ERROR) {
            freeArray(gl);
            *error = QStringLiteral("cannot allocate the shadow maps (%1 layers of %2², GL error 0x%3)")
                         .arg(layers)
                         .arg(res)
                         .arg(e, 0, 16);
            return false;
        }
        m_resolution = res;
        m_layers = layers;
        m_bytes = qint64(res) * res * 4 * layers;
    }
    stats->shadowMapBytes = m_bytes;
    const bool newModel = modelGeneration != m_modelGeneration;
    m_rendered.resize(views.size());
    const Model* m = model.model();
    const glm::dmat4 toOrigin = glm::translate(glm::dmat4(1.0), m->origin);
    bool bound = false;
    QElapsedTimer timer;
    for (size_t i = 0; i < views.size(); ++i) {
        const ShadowView& v = views[i];
        if (!newModel && m_rendered[i].resolution > 0 && m_rendered[i].sameMap(v)) continue;
        if (!bound) {
            timer.start();
            gl->glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
            gl->glDrawBuffer(GL_NONE);
            gl->glReadBuffer(GL_NONE);
            gl->glViewport(0, 0, res, res);
            gl->glEnable(GL_DEPTH_TEST);
            gl->glDepthFunc(GL_LESS);
            gl->glDepthMask(GL_TRUE);
            gl->glDisable(GL_CULL_FACE); // open meshes cast from both sides
            gl->glDisable(GL_BLEND);
            // Slope-scaled depth offset: the receiver-side bias (shadows.glsl) handles the rest.
            gl->glEnable(GL_POLYGON_OFFSET_FILL);
            gl->glPolygonOffset(1.5f, 2.0f);
            gl->glUseProgram(depthProgram);
            bound = true;
        }
        for (int face = 0; face < v.layers(); ++face) {
            gl->glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, m_texture, 0, v.layer + face);
            gl->glClear(GL_DEPTH_BUFFER_BIT);
            const glm::mat4 mvp(v.faceViewProj(face) * toOrigin);
            gl->glUniformMatrix4fv(matrixLocation, 1, GL_FALSE, glm::value_ptr(mvp));
            // Opaque and MASK meshes cast (MASK without its cutout); BLEND meshes do not.
            for (const GpuDraw& d : model.draws()) {
                if (d.features.alphaBlend) continue;
                gl->glBindVertexArray(d.vao);
                gl->glDrawElements(GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT, nullptr);
            }
            ++stats->shadowLayersRendered;
        }
        m_rendered[i] = v;
        ++stats->shadowMapsRendered;
    }
    m_modelGeneration = modelGeneration;
    if (bound) {
        if (wait) gl->glFinish(); // then the time is the maps' own
        stats->shadowMapMs = double(timer.nsecsElapsed()) * 1e-6;
        gl->glBindVertexArray(0);
        gl->glDisable(GL_POLYGON_OFFSET_FILL);
        gl->glUseProgram(0);
        gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    return true;
}

void ShadowMaps::bind(QOpenGLFunctions_3_3_Core* gl) const {
    if (!m_texture) return;
    gl->glActiveTexture(textureUnit(TextureUnit::ShadowMaps));
    gl->glBindTexture(GL_TEXTURE_2D_ARRAY, m_texture);
    gl->glBindSampler(GLuint(TextureUnit::ShadowMaps), m_compare);
    gl->glActiveTexture(textureUnit(TextureUnit::ShadowDepths));
    gl->glBindTexture(GL_TEXTURE_2D_ARRAY, m_texture);
    gl->glBindSampler(GLuint(TextureUnit::ShadowDepths), m_raw);
    gl->glActiveTexture(GL_TEXTURE0);
}

void ShadowMaps::unbind(QOpenGLFunctions_3_3_Core* gl) const {
    if (!m_texture) return;
    gl->glBindSampler(GLuint(TextureUnit::ShadowMaps), 0);
    gl->glBindSampler(GLuint(TextureUnit::ShadowDepths), 0);
}

} // namespace lr::render
