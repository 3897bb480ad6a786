// The ground as a lit input (litinput.h): the scene description's ground mesh (scene/groundmesh.h) on the
// GPU, uploaded when it was rebuilt. A visible ground is one more opaque surface of the geometry pass; a
// shadow catcher puts the catcher pass in the plan (PlanBit::Catcher).
#pragma once

#include "gpumodel.h"
#include "litinput.h"

namespace lr::render {

class GroundInput final : public LitInput {
  public:
    const char* name() const override { return "ground"; }
    void release(QOpenGLFunctions_3_3_Core* gl) override;
    bool prepare(InputFrame& f, QString* error) override;

    // The ground's draws this frame: nullptr when the ground is off or there is no model.
    const GpuModel* gpu() const { return m_gpu.model() ? &m_gpu : nullptr; }
    GroundMode mode() const { return m_mode; }
    int revision() const { return m_revision; } // the description's, of the mesh uploaded

  private:
    GpuModel m_gpu;
    int m_revision = -1;
    GroundMode m_mode = GroundMode::Off;
};

} // namespace lr::render
