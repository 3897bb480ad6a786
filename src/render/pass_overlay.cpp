// The overlay pass: light gizmos and the ground grid (gizmos.h) over the output.
#include "gizmos.h"
#include "gpumodel.h"
#include "passes.h"
#include "programcache.h"
#include "scene/scenedescription.h"
#include "targets.h"
#include "textureunits.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
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

bool OverlayPass::run(const FrameContext& frame, PassScene& scene) {
    const RenderSettings& settings = *frame.settings;
    GizmoOptions options;
    options.nearClip = frame.camera.znear * 0.5;
    options.lights = settings.showGizmos;
    // A visible ground lies where the grid would (under the model's bounds): it replaces the grid, which
    // would otherwise flicker against it in the depth test. A catcher shows nothing of itself: grid kept.
    const SceneDescription& described = *frame.scene;
    options.grid = settings.showGrid && described.rig().ground.mode != GroundMode::Visible;
    options.selected = settings.selectedLights;
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
