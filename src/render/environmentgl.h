// The environment on the GPU (issue 15; docs/lighting-models.md "Environment"): the prefiltered
// environment of Renderer::environment() as textures and uniforms for shaders/environment.glsl.
//
// Textures (units in textureunits.h), uploaded only when the LoadedEnvironment pointer changes:
//   - the specular chain: ONE texture whose mip level k is PrefilteredEnvironment::specular[k] (GGX
//     roughness k/5), GL_TEXTURE_MAX_LEVEL 5, trilinear, S repeat (azimuth), T clamp (poles); sampled with
//     textureLod(lod = 5·roughness);
//   - the irradiance map (64×32, bilinear, S repeat, T clamp);
//   - the split-sum table (core/envbrdf.h dfgTable, precomputed), uploaded once (the first environment).
// RGBA16F packed on the CPU, or RGBA32F for an image with radiance above half float's range (a bright sun).
// The SH9 irradiance, the rotation and the intensity are uniforms: rotating or brightening never re-uploads.
#pragma once

#include "core/environment.h"
#include "core/types.h"

#include <QOpenGLFunctions_3_3_Core>
#include <QString>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <memory>

class QOpenGLShaderProgram;

namespace lr {
struct LoadedEnvironment;
struct Rig;
} // namespace lr

namespace lr::render {

// The rotation taking a view-space direction to the environment image's own frame: world from view (the
// inverse of the view's rotation), then R_y(−rotation) (Environment::rotation; the image is looked up at
// R_y(−rotation)·d, core/environment.h).
glm::mat3 environmentFromView(const glm::dmat4& view, double rotationDegrees);

// The classic diffuse model the environment is shaded with (Environment::diffuse; core/environment.h's
// definition).
DiffuseModel environmentDiffuse(const Rig& rig);

// What a frame's lit programs need beyond the textures.
struct EnvironmentUniforms {
    glm::mat3 fromView{1.0f}; // environmentFromView
    float scale = 1.0f;       // 2^Environment::intensity
    DiffuseModel diffuse = DiffuseModel::Lambert;
};

class EnvironmentGl {
  public:
    void initialize(QOpenGLFunctions_3_3_Core* gl); // context current: reads the unit limit
    void release(QOpenGLFunctions_3_3_Core* gl);
    // Uploads `env` when it is not the environment uploaded last (nullptr frees the textures). False with
    // `error` when the textures could not be made; the frame then lights without an environment.
    bool update(QOpenGLFunctions_3_3_Core* gl, const std::shared_ptr<const LoadedEnvironment>& env,
                QString* error);
    // Textures uploaded and enough texture units for them.
    bool ready() const { return m_loaded && m_specular && m_unitsOk; }
    bool unitsAvailable() const { return m_unitsOk; }
    const LoadedEnvironment* loaded() const { return m_loaded.get(); }
    int specularLevels() const { return m_levels; }
    int generation() const { return m_generation; } // changes with every upload
    // Binds the three textures to their units (active texture left at unit 0).
    void bind(QOpenGLFunctions_3_3_Core* gl) const;
    // Sets environment.glsl's uniforms on the bound program `p` (absent ones are skipped).
    void setUniforms(QOpenGLFunctions_3_3_Core* gl, QOpenGLShaderProgram* p,
                     const EnvironmentUniforms& u) const;

  private:
    std::shared_ptr<const LoadedEnvironment> m_loaded;
    GLuint m_specular = 0, m_irradiance = 0, m_dfg = 0;
    int m_levels = 0;
    int m_generation = 0;
    bool m_unitsOk = false;
};

} // namespace lr::render
