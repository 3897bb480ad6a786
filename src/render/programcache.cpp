#include "programcache.h"

#include <QFile>
#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcShaders, "lightrig.render.shaders", QtInfoMsg)

namespace lr::render {

QByteArray ProgramCache::source(const QString& name) {
    if (auto it = m_overrides.constFind(name); it != m_overrides.constEnd()) return *it;
    if (auto it = m_sources.constFind(name); it != m_sources.constEnd()) return *it;
    QFile f(QStringLiteral(":/shaders/") + name);
    QByteArray text;
    if (f.open(QIODevice::ReadOnly)) text = f.readAll();
    m_sources.insert(name, text);
    return text;
}

std::unique_ptr<QOpenGLShaderProgram> ProgramCache::build(const QByteArray& prelude,
                                                          const QStringList& vertexFiles,
                                                          const QStringList& fragmentFiles,
                                                          const QString& what, QString* error) {
    // Each file gets a #line with its own source-string number, so a log line "2:14(3)" points at line 14
    // of the second file listed in the message.
    QStringList legend;
    auto assemble = [&](const QStringList& files, QString* missing) {
        QByteArray text = prelude;
        for (const QString& file : files) {
            const QByteArray body = source(file);
            if (body.isEmpty()) *missing = file;
            const int number = int(legend.size()) + 1;
            legend << QStringLiteral("%1 = %2").arg(number).arg(file);
            text += "#line 1 " + QByteArray::number(number) + '\n' + body + '\n';
        }
        return text;
    };
    QString missing;
    const QByteArray vs = assemble(vertexFiles, &missing);
    const QByteArray fs = assemble(fragmentFiles, &missing);
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
    auto program = key.deferredLighting
                       ? build(shaderPrelude(key), {QStringLiteral("fullscreen.vert")},
                               {QStringLiteral("lighting.glsl"), QStringLiteral("cluster.glsl"),
                                QStringLiteral("deferred.frag")},
                               QStringLiteral("variant [%1]").arg(key.describe()), &message)
                       : build(shaderPrelude(key),
                               key.quality == Quality::Fast // the fast tier lights the vertices
                                   ? QStringList{QStringLiteral("lighting.glsl"), QStringLiteral("mesh.vert")}
                                   : QStringList{QStringLiteral("mesh.vert")},
                               {QStringLiteral("lighting.glsl"), QStringLiteral("cluster.glsl"),
                                QStringLiteral("mesh.frag")},
                               QStringLiteral("variant [%1]").arg(key.describe()), &message);
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
    mp->exposureScale = p->uniformLocation("uExposureScale");
    mp->toneMap = p->uniformLocation("uToneMap");
    p->bind();
    p->setUniformValue("uBaseColorTex", 0);
    p->setUniformValue("uNormalTex", 1);
    p->setUniformValue("uEmissiveTex", 2);
    p->setUniformValue("uLights", 3);
    p->setUniformValue("uClusterRanges", 8);  // ClusterBuffers::kRangesUnit
    p->setUniformValue("uClusterIndices", 9); // ClusterBuffers::kIndicesUnit
    for (int i = 0; i < 4; ++i)
        p->setUniformValue(qPrintable(QStringLiteral("uGBuffer%1").arg(i)), 4 + i);
    p->release();
    mp->program = std::move(program);
    return m_mesh.emplace(key, std::move(mp)).first->second.get();
}

QOpenGLShaderProgram* ProgramCache::fixedProgram(const QString& vertex, const QString& fragment,
                                                 QString* error) {
    const QString id = vertex + QLatin1Char('+') + fragment;
    if (auto it = m_fixed.constFind(id); it != m_fixed.constEnd()) return it->get();
    auto program = build(basicPrelude(), {vertex}, {QStringLiteral("lighting.glsl"), fragment}, id, error);
    if (!program) return nullptr;
    QOpenGLShaderProgram* p = program.get();
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
