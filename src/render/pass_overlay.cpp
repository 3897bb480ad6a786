// The overlay pass: highlighted parts, light gizmos and the ground grid (gizmos.h) over the output.
#include "gizmos.h"
#include "gpumodel.h"
#include "input_ground.h"
#include "litinput.h"
#include "passes.h"
#include "programcache.h"
#include "scene/scenedescription.h"
#include "targets.h"
#include "textureunits.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <utility>

namespace lr::render {

bool OverlayPass::initialize() {
    if (!RenderPass::initialize()) return false;
    glGenVertexArrays(1, &m_vao);
    glGenBuffers(1, &m_vbo);
    glBindVertexArray(m_vao);
    glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    const auto attrib = [&](GLuint loc, GLint n, std::size_t offset) {
        glEnableVertexAttribArray(loc);
        glVertexAttribPointer(loc, n, GL_FLOAT, GL_FALSE, GLsizei(sizeof(GizmoVertex)),
                              reinterpret_cast<const void*>(offset));
    };
    attrib(0, 3, offsetof(GizmoVertex, position));
    attrib(1, 4, offsetof(GizmoVertex, color));
    attrib(2, 2, offsetof(GizmoVertex, point));
    glBindVertexArray(0);
    return true;
}

void OverlayPass::release() {
    glDeleteVertexArrays(1, &m_vao);
    glDeleteBuffers(1, &m_vbo);
    m_vao = m_vbo = 0;
}

bool OverlayPass::drawHighlights(const FrameContext& frame, PassScene& scene) {
    const RenderSettings& settings = *frame.settings;
    const std::vector<int>& parts = settings.highlightedParts;
    if (parts.empty() || !scene.model->model()) return true;
    const SceneDescription& described = *frame.scene;
    const auto highlighted = [&](std::size_t part) {
        return std::find(parts.begin(), parts.end(), int(part)) != parts.end();
    };
    const GroundInput* groundInput = scene.inputs->find<GroundInput>();
    const GpuModel* ground =
        groundInput && groundInput->mode() == GroundMode::Visible ? groundInput->gpu() : nullptr;
    QString error;
    QOpenGLShaderProgram* p = scene.programs->fixedProgram(kHighlightShader, &error);
    if (!p) return fail(scene, error);
    glBindFramebuffer(GL_FRAMEBUFFER, frame.outputFbo);
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    p->bind();
    const QColor c = settings.highlightColor.toRgb();
    p->setUniformValue("uColor", float(c.redF()), float(c.greenF()), float(c.blueF()), float(c.alphaF()));
    glUniformMatrix4fv(p->uniformLocation("uProjection"), 1, GL_FALSE,
                       glm::value_ptr(glm::mat4(frame.projection)));
    const int modelViewLocation = p->uniformLocation("uModelView");
    glActiveTexture(textureUnit(TextureUnit::SceneDepth));
    glBindTexture(GL_TEXTURE_2D, scene.targets->depth);
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    // The same vertices the geometry pass drew (its interaction proxy while one is drawn).
    const bool useProxies = settings.interactive && scene.model->updateProxies(this);
    const auto drawOf = [&](const GpuModel& source, bool isGround) {
        const glm::mat4 modelView(frame.view * glm::translate(glm::dmat4(1.0), source.model()->origin));
        glUniformMatrix4fv(modelViewLocation, 1, GL_FALSE, glm::value_ptr(modelView));
        for (const GpuDraw& d : source.draws()) {
            const std::size_t part = isGround ? described.groundPart(std::size_t(d.mesh))
                                              : described.modelPart(std::size_t(d.mesh));
            if (!highlighted(part)) continue;
            if (d.features.doubleSided)
                glDisable(GL_CULL_FACE);
            else
                glEnable(GL_CULL_FACE);
            const bool proxy = !isGround && useProxies && d.lodVao;
            glBindVertexArray(proxy ? d.lodVao : d.vao);
            glDrawElements(GL_TRIANGLES, proxy ? d.lodIndexCount : d.indexCount, GL_UNSIGNED_INT, nullptr);
        }
    };
    drawOf(*scene.model, false);
    if (ground) drawOf(*ground, true);
    glBindVertexArray(0);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    p->release();
    return true;
}

bool OverlayPass::run(const FrameContext& frame, PassScene& scene) {
    if (!drawHighlights(frame, scene)) return false;
    const RenderSettings& settings = *frame.settings;
    GizmoOptions options;
    options.nearClip = frame.camera.znear * 0.5;
    options.lights = settings.showGizmos;
    // A visible ground lies where the grid would (under the model's bounds): it replaces the grid, which
    // would otherwise flicker against it in the depth test. A catcher shows nothing of itself: grid kept.
    const SceneDescription& described = *frame.scene;
    options.grid = settings.showGrid && described.rig().ground.mode != GroundMode::Visible;
    options.selected = settings.selectedLights;
    options.ies = &described.lightAssets().ies;
    const GizmoGeometry g =
        buildGizmos(described.rig(), described.frame(), described.bounds(), frame.view, options);
    if (g.lines.empty() && g.points.empty()) return true;
    QString error;
    QOpenGLShaderProgram* p = scene.programs->fixedProgram(kOverlayShader, &error);
    if (!p) return fail(scene, error);
    // Gizmos are clipped on the CPU at half the near distance and drawn with depth clamping, so lights
    // outside the scene's depth range stay visible; the shader fades the parts behind the model, and
    // drops the grid's.
    glBindFramebuffer(GL_FRAMEBUFFER, frame.outputFbo);
    p->bind();
    p->setUniformValue("uHasDepth", scene.model->model() != nullptr);
    // The grid (gizmos.cpp: under the bounds, 1.5 radii each way) fades from the eye's distance to its
    // centre to one extent beyond: full in front, gone at the far edge of an oblique view.
    const SceneFrame sphere = described.frame();
    const Bounds bounds = described.bounds();
    const double radius = sphere.radius > 0.0 && std::isfinite(sphere.radius) ? sphere.radius : 1.0;
    const glm::dvec3 gridCentre(bounds.center().x, bounds.min.y, bounds.center().z);
    const double fadeStart = glm::length(glm::dvec3(frame.view * glm::dvec4(gridCentre, 1.0)));
    p->setUniformValue("uGridFade", float(fadeStart), float(fadeStart + 1.5 * radius));
    glUniformMatrix4fv(p->uniformLocation("uProjection"), 1, GL_FALSE,
                       glm::value_ptr(glm::mat4(frame.projection)));
    glActiveTexture(textureUnit(TextureUnit::SceneDepth));
    glBindTexture(GL_TEXTURE_2D, scene.targets->depth);
    glActiveTexture(GL_TEXTURE0);
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    glEnable(GL_DEPTH_CLAMP);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_PROGRAM_POINT_SIZE);
    glBindVertexArray(m_vao);
    glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    const auto draw = [&](const std::vector<GizmoVertex>& v, GLenum mode, bool points) {
        if (v.empty()) return;
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(GizmoVertex)), v.data(), GL_STREAM_DRAW);
        p->setUniformValue("uPoints", points);
        glDrawArrays(mode, 0, GLsizei(v.size()));
    };
    // The lines' dark halo first: the same lines a pixel aside in four directions (the grid has none).
    p->setUniformValue("uHalo", true);
    const float px = 2.0f / float(std::max(frame.targetSize.width(), 1)),
                py = 2.0f / float(std::max(frame.targetSize.height(), 1));
    for (const auto& [dx, dy] : {std::pair{px, 0.0f}, {-px, 0.0f}, {0.0f, py}, {0.0f, -py}}) {
        p->setUniformValue("uHaloOffset", dx, dy);
        draw(g.lines, GL_LINES, false);
    }
    p->setUniformValue("uHalo", false);
    p->setUniformValue("uHaloOffset", 0.0f, 0.0f);
    draw(g.lines, GL_LINES, false);
    draw(g.points, GL_POINTS, true);
    glBindVertexArray(0);
    glDisable(GL_PROGRAM_POINT_SIZE);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_CLAMP);
    p->release();
    return true;
}

} // namespace lr::render
