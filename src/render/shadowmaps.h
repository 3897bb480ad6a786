// The shadow maps on the GPU (issue 14; docs/architecture.md "Shadow maps"): the maps of the shadow plan
// (shadowplan.h, no GL), as cluster.h's plan is clustergl.h's.
//
// ShadowMaps owns one GL_TEXTURE_2D_ARRAY of GL_DEPTH_COMPONENT32F layers (one per spot or directional
// light, six per point light), all of one resolution (the largest a caster asks for, halved until the
// array fits kMaxShadowBytes), and two sampler objects over it: a compare sampler (sampler2DArrayShadow,
// LEQUAL, bilinear: 2×2 PCF per tap) and a raw one (PCSS's blocker search). A layer re-renders only when
// its light's map (matrix, resolution, layer) or the model changed: dragging one light re-renders that
// light's layers, orbiting none. No casters: no texture at all.
#pragma once

#include "rendersettings.h"
#include "shadowplan.h"

#include <QOpenGLFunctions_3_3_Core>
#include <QString>
#include <vector>

namespace lr::render {

class GpuModel;

class ShadowMaps {
  public:
    bool initialize(QOpenGLFunctions_3_3_Core* gl);
    void release(QOpenGLFunctions_3_3_Core* gl);
    // Re-renders the layers whose map changed; `modelGeneration` changes with every new model. `wait`:
    // finish them before returning (RenderSettings::waitForShadowMaps). False (with error) when the array
    // could not be made.
    bool update(QOpenGLFunctions_3_3_Core* gl, const std::vector<ShadowView>& views, const GpuModel& model,
                int modelGeneration, GLuint depthProgram, int matrixLocation, bool wait, RenderStats* stats,
                QString* error);
    // Binds the array to TextureUnit::ShadowMaps (compare) and ShadowDepths (raw); nothing without maps.
    void bind(QOpenGLFunctions_3_3_Core* gl) const;
    void unbind(QOpenGLFunctions_3_3_Core* gl) const;
    qint64 bytes() const { return m_bytes; }

  private:
    void freeArray(QOpenGLFunctions_3_3_Core* gl);
    GLuint m_texture = 0, m_fbo = 0, m_compare = 0, m_raw = 0;
    int m_resolution = 0, m_layers = 0;
    qint64 m_bytes = 0;
    std::vector<ShadowView> m_rendered; // what each view's layers hold
    int m_modelGeneration = -1;
};

} // namespace lr::render
