// The lights as a lit input (litinput.h): the light set (lightset.h: the packed light buffer, the area
// lights' LTC table, the clusters), rebuilt from the scene description's rig when it or the model changes,
// and the lit programs' feature bits of the rig (shadergen.h rigFeatures).
#pragma once

#include "lightset.h"
#include "litinput.h"

namespace lr::render {

class LightInput final : public LitInput {
  public:
    const char* name() const override { return "lights"; }
    void initialize(QOpenGLFunctions_3_3_Core* gl) override { m_set.initialize(gl); }
    void release(QOpenGLFunctions_3_3_Core* gl) override;
    bool prepare(InputFrame& f, QString* error) override;
    void prepareTargets(InputFrame& f) override;
    PassResources provides() const override { return resource::Lights | resource::Clusters; }
    void bind(QOpenGLFunctions_3_3_Core* gl, const FrameContext& frame, bool clustered) const override;
    void setUniforms(QOpenGLFunctions_3_3_Core* gl, const MeshProgram& p, const FeatureKey& key,
                     const FrameContext& frame) const override;

  private:
    LightSet m_set;
    const Rig* m_rig = nullptr; // the rig the set holds (SceneDescription::rig(), by address and revision)
    int m_rigRevision = -1, m_modelGeneration = -1;
};

} // namespace lr::render
