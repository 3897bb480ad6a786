#include "environmentgl.h"

#include "core/envbrdf.h"
#include "core/rig.h"
#include "scene/environmentloader.h"
#include "textureunits.h"

#include <QOpenGLShaderProgram>
#include <algorithm>
#include <glm/gtc/packing.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <vector>

namespace lr::render {

namespace {

// Largest value a half float holds (65504) with a margin: above it the texture is RGBA32F.
constexpr float kHalfMax = 60000.0f;

float maxValue(const EnvironmentImage& image) {
    float m = 0.0f;
    for (const glm::vec3& t : image.texels)
        m = std::max({m, t.r, t.g, t.b});
    return m;
}

void setEquirectParameters(QOpenGLFunctions_3_3_Core* gl, int maxLevel) {
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, maxLevel);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                        maxLevel > 0 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);        // azimuth wraps
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE); // the poles do not
}

// RGBA half floats packed here (or RGBA floats above half's range), in the layout the driver keeps: Mesa
// stored GL_RGB16F from GL_FLOAT by converting texel by texel through its generic path (0.65 s of the first
// frame for the chain and the irradiance map on llvmpipe at load 6-8); a matching format is a copy.
void upload(QOpenGLFunctions_3_3_Core* gl, int level, const EnvironmentImage& image, bool half) {
    // Row 0 of the image is the top (+Y): uploaded first, it is t = 0, so t = v of core's mapping.
    const size_t n = image.texels.size();
    if (half) {
        std::vector<glm::uint64> texels(n);
        for (size_t i = 0; i < n; ++i)
            texels[i] = glm::packHalf4x16(glm::vec4(image.texels[i], 1.0f));
        gl->glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA16F, image.width, image.height, 0, GL_RGBA,
                         GL_HALF_FLOAT, texels.data());
    } else {
        std::vector<glm::vec4> texels(n);
        for (size_t i = 0; i < n; ++i)
            texels[i] = glm::vec4(image.texels[i], 1.0f);
        gl->glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA32F, image.width, image.height, 0, GL_RGBA, GL_FLOAT,
                         texels.data());
    }
}

} // namespace

glm::mat3 environmentFromView(const glm::dmat4& view, double rotationDegrees) {
    const glm::dmat3 worldFromView = glm::transpose(glm::dmat3(view));
    glm::dmat3 envFromWorld;
    for (int i = 0; i < 3; ++i) {
        glm::dvec3 e(0.0);
        e[i] = 1.0;
        envFromWorld[i] = environment::rotateAboutUp(e, -rotationDegrees);
    }
    return glm::mat3(envFromWorld * worldFromView);
}

DiffuseModel environmentDiffuse(const Rig& rig) {
    return rig.environment.diffuse;
}

void EnvironmentGl::initialize(QOpenGLFunctions_3_3_Core* gl) {
    GLint units = 0;
    gl->glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
    m_unitsOk = units >= kEnvironmentUnitsNeeded;
}

void EnvironmentGl::release(QOpenGLFunctions_3_3_Core* gl) {
    const GLuint textures[] = {m_specular, m_irradiance, m_dfg};
    gl->glDeleteTextures(3, textures);
    m_specular = m_irradiance = m_dfg = 0;
    m_loaded.reset();
    m_levels = 0;
}

bool EnvironmentGl::update(QOpenGLFunctions_3_3_Core* gl, const std::shared_ptr<const LoadedEnvironment>& env,
                           QString* error) {
    if (env == m_loaded && (m_specular || !env)) return true;
    if (!env || !m_unitsOk) {
        const GLuint textures[] = {m_specular, m_irradiance};
        gl->glDeleteTextures(2, textures);
        m_specular = m_irradiance = 0;
        m_loaded = env;
        m_levels = 0;
        ++m_generation;
        if (env && error)
            *error = QStringLiteral("environment lighting needs %1 texture units; this OpenGL offers fewer")
                         .arg(kEnvironmentUnitsNeeded);
        return !env;
    }
    const PrefilteredEnvironment& p = env->prefiltered;
    // The chain: as many levels as were prefiltered, each half the previous one (a level of another size
    // would make the texture incomplete).
    int levels = 0;
    float peak = 0.0f;
    for (const EnvironmentImage& level : p.specular) {
        const int w = p.specular.empty() ? 0 : std::max(1, p.specular.front().width >> levels);
        const int h = std::max(1, p.specular.front().height >> levels);
        if (level.isNull() || level.width != w || level.height != h ||
            level.texels.size() != size_t(w) * size_t(h))
            break;
        peak = std::max(peak, maxValue(level));
        ++levels;
    }
    if (levels == 0 || p.irradiance.isNull() ||
        p.irradiance.texels.size() != size_t(p.irradiance.width) * size_t(p.irradiance.height)) {
        if (error)
            *error =
                QStringLiteral("the environment %1 has no prefiltered form to shade with").arg(env->source);
        return false;
    }
    const bool half = !(peak > kHalfMax);
    if (!m_specular) gl->glGenTextures(1, &m_specular);
    if (!m_irradiance) gl->glGenTextures(1, &m_irradiance);
    gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->glBindTexture(GL_TEXTURE_2D, m_specular);
    for (int k = 0; k < levels; ++k)
        upload(gl, k, p.specular[size_t(k)], half);
    setEquirectParameters(gl, levels - 1);
    gl->glBindTexture(GL_TEXTURE_2D, m_irradiance);
    upload(gl, 0, p.irradiance, !(maxValue(p.irradiance) > kHalfMax));
    setEquirectParameters(gl, 0);
    if (!m_dfg) {
        gl->glGenTextures(1, &m_dfg);
        gl->glBindTexture(GL_TEXTURE_2D, m_dfg);
        gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16F, envbrdf::kDfgTableSize, envbrdf::kDfgTableSize, 0,
                         GL_RGB, GL_FLOAT, envbrdf::dfgTable());
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_loaded = env;
    m_levels = levels;
    ++m_generation;
    return true;
}

void EnvironmentGl::bind(QOpenGLFunctions_3_3_Core* gl) const {
    const std::pair<TextureUnit, GLuint> textures[] = {{TextureUnit::EnvSpecular, m_specular},
                                                       {TextureUnit::EnvIrradiance, m_irradiance},
                                                       {TextureUnit::EnvDfg, m_dfg}};
    for (const auto& [unit, texture] : textures) {
        gl->glActiveTexture(textureUnit(unit));
        gl->glBindTexture(GL_TEXTURE_2D, texture);
    }
    gl->glActiveTexture(GL_TEXTURE0);
}

void EnvironmentGl::setUniforms(QOpenGLFunctions_3_3_Core* gl, QOpenGLShaderProgram* p,
                                const EnvironmentUniforms& u) const {
    if (!m_loaded) return;
    const GLuint id = p->programId();
    const auto at = [&](const char* name) { return gl->glGetUniformLocation(id, name); };
    if (const GLint l = at("uEnvFromView"); l >= 0)
        gl->glUniformMatrix3fv(l, 1, GL_FALSE, glm::value_ptr(u.fromView));
    if (const GLint l = at("uEnvScale"); l >= 0) gl->glUniform1f(l, u.scale);
    if (const GLint l = at("uEnvMaxLod"); l >= 0) gl->glUniform1f(l, float(m_levels - 1));
    if (const GLint l = at("uEnvSh"); l >= 0)
        gl->glUniform3fv(l, 9, glm::value_ptr(m_loaded->prefiltered.sh[0]));
    // Classic diffuse: Lambert from E(n) (the irradiance map where the tier reads it), half-Lambert from the
    // SH9 with its own band weights (docs/lighting-models.md: the zonal coefficients of ((1 + cos θ)/2)²
    // over the cosine lobe's: 4/3, 1, 8/15).
    const bool half = u.diffuse == DiffuseModel::HalfLambert;
    if (const GLint l = at("uEnvBands"); l >= 0)
        gl->glUniform3f(l, half ? 4.0f / 3.0f : 1.0f, 1.0f, half ? 8.0f / 15.0f : 1.0f);
    if (const GLint l = at("uEnvMapWeight"); l >= 0) gl->glUniform1f(l, half ? 0.0f : 1.0f);
}

} // namespace lr::render
