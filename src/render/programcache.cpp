#include "programcache.h"

#include "gbuffer.h"
#include "textureunits.h"

#include <QFile>
#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcShaders, "lightrig.render.shaders", QtInfoMsg)

namespace lr::render {

namespace {

// Every sampler the program declares, to its unit (textureunits.h).
void bindSamplers(QOpenGLShaderProgram* p) {
    p->bind();
    for (const SamplerBinding& b : kSamplerBindings) {
        const int location = p->uniformLocation(b.uniform);
        if (location >= 0) p->setUniformValue(location, GLint(GLuint(b.unit) + GLuint(b.offset)));
    }
    p->release();
}

} // namespace

QByteArray ProgramCache::source(const QString& name) {
    if (auto it = m_overrides.constFind(name); it != m_overrides.constEnd()) return *it;
    if (auto it = m_sources.constFind(name); it != m_sources.constEnd()) return *it;
    QByteArray text;
    if (name == QLatin1String("gbuffer.glsl")) {
        text = gbufferGlsl();
    } else {
        QFile f(QStringLiteral(":/shaders/") + name);
        if (f.open(QIODevice::ReadOnly)) text = f.readAll();
    }
    m_sources.insert(name, text);
    return text;
}

const ShaderConfig& shaderConfig(const FeatureKey& key) {
    if (key.rig.environment) {
        if (key.deferredLighting) return kDeferredLightingEnvironmentShader;
        return key.quality == Quality::Fast ? kVertexLitMeshEnvironmentShader : kMeshEnvironmentShader;
    }
    if (key.deferredLighting) return kDeferredLightingShader;
    return key.quality == Quality::Fast ? kVertexLitMeshShader : kMeshShader;
}

std::unique_ptr<QOpenGLShaderProgram> ProgramCache::build(const QByteArray& prelude,
                                                          const ShaderConfig& config, const QString& what,
                                                          QString* error) {
    // Each file gets a #line with its own source-string number, so a log line "2:14(3)" points at line 14
    // of the second file listed in the message.
    QStringList legend;
    auto assemble = [&](const decltype(ShaderConfig::vertex)& files, QString* missing) {
        QByteArray text = prelude;
        for (const char* name : files) {
            if (!name) break;
            const QString file = QString::fromLatin1(name);
            const QByteArray body = source(file);
            if (body.isEmpty()) *missing = file;
            const int number = int(legend.size()) + 1;
            legend << QStringLiteral("%1 = %2").arg(number).arg(file);
            text += "#line 1 " + QByteArray::number(number) + '\n' + body + '\n';
        }
        return text;
    };
    QString missing;
    const QByteArray vs = assemble(config.vertex, &missing);
    const QByteArray fs = assemble(config.fragment, &missing);
    auto fail = [&](const QString& stage, const QString& log) {
        const QString message = QStringLiteral("shader %1: %2 failed (sources: %3):\n%4")
                                    .arg(what, stage, legend.join(QStringLiteral(", ")), log.trimmed());
        qCWarning(lcShaders).noquote() << message;
        if (error) *error = message;
        return nullptr;
    };
    if (!missing.isEmpty())
        return fail(QStringLiteral("loading"),
                    QStringLiteral(":/shaders/%1 is missing or empty").arg(missing));
    auto program = std::make_unique<QOpenGLShaderProgram>();
    if (!program->addShaderFromSourceCode(QOpenGLShader::Vertex, vs))
        return fail(QStringLiteral("vertex shader compile"), program->log());
    if (!program->addShaderFromSourceCode(QOpenGLShader::Fragment, fs))
        return fail(QStringLiteral("fragment shader compile"), program->log());
    if (!program->link()) return fail(QStringLiteral("link"), program->log());
    ++m_compiled;
    qCDebug(lcShaders).noquote() << "compiled" << what;
    return program;
}

MeshProgram* ProgramCache::meshProgram(const FeatureKey& key, QString* error) {
    if (auto it = m_mesh.find(key); it != m_mesh.end()) return it->second.get();
    if (auto it = m_failed.find(key); it != m_failed.end()) {
        if (error) *error = it->second;
        return nullptr;
    }
    QString message;
    const ShaderConfig& config = shaderConfig(key);
    auto program =
        build(shaderPrelude(key), config,
              QStringLiteral("%1 variant [%2]").arg(QLatin1String(config.name), key.describe()), &message);
    if (!program) {
        m_failed.emplace(key, message);
        if (error) *error = message;
        return nullptr;
    }
    auto mp = std::make_unique<MeshProgram>();
    QOpenGLShaderProgram* p = program.get();
    mp->modelView = p->uniformLocation("uModelView");
    mp->normalMatrix = p->uniformLocation("uNormalMatrix");
    mp->projection = p->uniformLocation("uProjection");
    mp->baseColor = p->uniformLocation("uBaseColor");
    mp->emissive = p->uniformLocation("uEmissive");
    mp->specular = p->uniformLocation("uSpecular");
    mp->shininess = p->uniformLocation("uShininess");
    mp->ambient = p->uniformLocation("uAmbient");
    mp->distanceScale = p->uniformLocation("uDistanceScale");
    mp->lightCount = p->uniformLocation("uLightCount");
    mp->shadowCount = p->uniformLocation("uShadowCount");
    mp->shadowRecords = p->uniformLocation("uShadowRecords");
    mp->exposureScale = p->uniformLocation("uExposureScale");
    mp->normalScale = p->uniformLocation("uNormalScale");
    mp->alphaCutoff = p->uniformLocation("uAlphaCutoff");
    mp->linkClass = p->uniformLocation("uLinkClass");
    for (size_t i = 0; i < mp->textureTransforms.size(); ++i)
        mp->textureTransforms[i] = p->uniformLocation(kTextureTransformUniforms[i]);
    mp->metallic = p->uniformLocation("uMetallic");
    mp->roughness = p->uniformLocation("uRoughness");
    mp->occlusionStrength = p->uniformLocation("uOcclusionStrength");
    bindSamplers(p);
    mp->program = std::move(program);
    return m_mesh.emplace(key, std::move(mp)).first->second.get();
}

QOpenGLShaderProgram* ProgramCache::fixedProgram(const ShaderConfig& config, QString* error,
                                                 const QByteArray& defines) {
    const QString id = QLatin1String(config.name) + QString::fromLatin1(defines);
    if (auto it = m_fixed.constFind(id); it != m_fixed.constEnd()) return it->get();
    auto program = build(basicPrelude() + defines, config, QLatin1String(config.name), error);
    if (!program) return nullptr;
    QOpenGLShaderProgram* p = program.get();
    bindSamplers(p);
    m_fixed.insert(id, std::shared_ptr<QOpenGLShaderProgram>(program.release()));
    return p;
}

void ProgramCache::clear() {
    m_mesh.clear();
    m_failed.clear();
    m_fixed.clear();
}

void ProgramCache::setSourceOverride(const QString& name, const QByteArray& source) {
    if (source.isEmpty())
        m_overrides.remove(name);
    else
        m_overrides.insert(name, source);
    clear();
}

} // namespace lr::render
