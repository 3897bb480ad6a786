// Compiled shader programs, one per distinct FeatureKey, plus the fixed passes (tone map, gizmos).
// Sources are the embedded :/shaders/NAME files (overridable for tests); compile and link errors carry
// the GLSL log. Needs the current context of the owning Renderer.
#pragma once

#include "shadergen.h"

#include <QHash>
#include <QOpenGLShaderProgram>
#include <memory>
#include <unordered_map>

namespace lr::render {

// A mesh program and its uniform locations (looked up once).
struct MeshProgram {
    std::unique_ptr<QOpenGLShaderProgram> program;
    int modelView = -1, normalMatrix = -1, projection = -1;
    int baseColor = -1, emissive = -1, specular = -1, shininess = -1, ambient = -1, distanceScale = -1;
    int lightCount = -1;
    int exposureScale = -1, toneMap = -1; // display output only
};

class ProgramCache {
  public:
    // The program for `key`, compiled on first request; nullptr when it failed (error says why; a failed
    // key is not retried until clear()).
    MeshProgram* meshProgram(const FeatureKey& key, QString* error);
    // A fixed pass: vertex and fragment shader names under :/shaders/, with the basic prelude.
    QOpenGLShaderProgram* fixedProgram(const QString& vertex, const QString& fragment, QString* error);

    int compiledCount() const { return m_compiled; } // variants compiled since construction
    int cachedCount() const { return int(m_mesh.size()); }
    void clear(); // context current

    // Replace a shader file's text (tests, live editing); an empty source restores the embedded one.
    // Clears the cache.
    void setSourceOverride(const QString& name, const QByteArray& source);

  private:
    QByteArray source(const QString& name);
    std::unique_ptr<QOpenGLShaderProgram> build(const QByteArray& prelude, const QStringList& vertexFiles,
                                                const QStringList& fragmentFiles, const QString& what,
                                                QString* error);

    std::unordered_map<FeatureKey, std::unique_ptr<MeshProgram>, FeatureKeyHash> m_mesh;
    std::unordered_map<FeatureKey, QString, FeatureKeyHash> m_failed;
    QHash<QString, std::shared_ptr<QOpenGLShaderProgram>> m_fixed;
    QHash<QString, QByteArray> m_sources, m_overrides;
    int m_compiled = 0;
};

} // namespace lr::render
