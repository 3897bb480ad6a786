// The lights' IES profiles and gobo images as a lit input (litinput.h; issue 39): their texture arrays
// (lightshapinggl.h), remade when the rig names other files, and each rig light's layers, which the light
// input packs into the light buffer (so it prepares first). Nothing at all for a rig without either: no
// texture, no texel, no program text (RigFeatures::ies, ::gobo).
#pragma once

#include "lightshapinggl.h"
#include "litinput.h"

namespace lr::render {

class ShapingInput final : public LitInput {
  public:
    const char* name() const override { return "light shaping"; }
    void initialize(QOpenGLFunctions_3_3_Core* gl) override;
    void release(QOpenGLFunctions_3_3_Core* gl) override;
    bool prepare(InputFrame& f, QString* error) override;
    void bind(QOpenGLFunctions_3_3_Core* gl, const FrameContext& frame, bool clustered) const override;

  private:
    LightShapingGl m_gl;
    ShapingLayers m_layers;
    int m_rigRevision = -1;
    const void* m_scene = nullptr; // the description m_rigRevision counts in
    // TextureUnit::Ies and ::Gobos lie beyond the 16 units GL 3.3 guarantees: with fewer units than they
    // need, lights render unshaped (every layer -1), with a warning once.
    bool m_unitsOk = true;
};

} // namespace lr::render
