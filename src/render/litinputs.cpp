// The registered lit inputs (litinput.h), one line each, in the order they prepare a frame: the ground
// first (the lights are culled against the drawn bounds), the shadow plan and the lights' IES profiles and
// gobos before the lights (the light buffer carries each caster's slot and each profile's and image's
// layer), the environment last.
#include "input_environment.h"
#include "input_ground.h"
#include "input_lights.h"
#include "input_shadows.h"
#include "input_shaping.h"
#include "litinput.h"

namespace lr::render {

LitInputs::LitInputs() {
    m_inputs.push_back(std::make_unique<GroundInput>());
    m_inputs.push_back(std::make_unique<ShadowInput>());
    m_inputs.push_back(std::make_unique<ShapingInput>());
    m_inputs.push_back(std::make_unique<LightInput>());
    m_inputs.push_back(std::make_unique<EnvironmentInput>());
}

LitInputs::~LitInputs() = default;

void LitInputs::initialize(QOpenGLFunctions_3_3_Core* gl) {
    for (const auto& i : m_inputs)
        i->initialize(gl);
}

void LitInputs::release(QOpenGLFunctions_3_3_Core* gl) {
    for (const auto& i : m_inputs)
        i->release(gl);
}

bool LitInputs::prepare(InputFrame& f, QString* error) {
    m_gl = f.gl;
    for (const auto& i : m_inputs)
        if (!i->prepare(f, error)) return false;
    return true;
}

void LitInputs::prepareTargets(InputFrame& f) {
    for (const auto& i : m_inputs)
        i->prepareTargets(f);
}

PassResources LitInputs::provides() const {
    PassResources r = 0;
    for (const auto& i : m_inputs)
        r |= i->provides();
    return r;
}

bool LitInputs::resolve(PassResources reads, QString* error, bool* inputError) const {
    for (const auto& i : m_inputs)
        if (i->pending() && (i->provides() & reads) && !i->resolve(m_gl, error, inputError)) return false;
    return true;
}

void LitInputs::bind(QOpenGLFunctions_3_3_Core* gl, const FrameContext& frame, bool clustered) const {
    for (const auto& i : m_inputs)
        i->bind(gl, frame, clustered);
}

void LitInputs::setUniforms(QOpenGLFunctions_3_3_Core* gl, const MeshProgram& p, const FeatureKey& key,
                            const FrameContext& frame) const {
    for (const auto& i : m_inputs)
        i->setUniforms(gl, p, key, frame);
}

void LitInputs::unbind(QOpenGLFunctions_3_3_Core* gl) const {
    for (const auto& i : m_inputs)
        i->unbind(gl);
}

} // namespace lr::render
