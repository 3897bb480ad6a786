// The shadow maps as a lit input (litinput.h): the frame's shadow plan (shadowplan.h, no GL) from the
// scene description, the maps themselves (shadowmaps.h), which the shadow pass renders where they changed
// (pass_shadow.cpp, in the plan when some light casts: PlanBit::Shadows) and which this input frees when no
// light casts, and their binding for the lit programs.
#pragma once

#include "litinput.h"
#include "shadowmaps.h"

#include <vector>

namespace lr::render {

class ShadowInput final : public LitInput {
  public:
    const char* name() const override { return "shadows"; }
    void initialize(QOpenGLFunctions_3_3_Core* gl) override { m_maps.initialize(gl); }
    void release(QOpenGLFunctions_3_3_Core* gl) override { m_maps.release(gl); }
    bool prepare(InputFrame& f, QString* error) override;
    void bind(QOpenGLFunctions_3_3_Core* gl, const FrameContext&, bool) const override { m_maps.bind(gl); }
    void unbind(QOpenGLFunctions_3_3_Core* gl) const override { m_maps.unbind(gl); }

    // The shadow pass: re-renders the maps of this frame's plan that changed, with the depth program.
    bool render(QOpenGLFunctions_3_3_Core* gl, const GpuModel& model, int modelGeneration, GLuint program,
                int matrixLocation, bool wait, RenderStats* stats, QString* error);

  private:
    ShadowMaps m_maps;
    std::vector<ShadowView> m_views; // this frame's plan
    bool m_warnedCasters = false;    // more than kMaxShadowCasters casting lights was logged once
};

} // namespace lr::render
