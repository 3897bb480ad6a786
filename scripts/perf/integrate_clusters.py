# Applies the clustered-shading integration (renderer, shader generation, program cache, mesh.frag and
# deferred.frag, the GPU test) to the tree at argv[1]: small, separate hunks; asserts each anchor is unique.
import sys, re
root = sys.argv[1]
def edit(path, pairs):
    p = root + '/' + path; s = open(p).read()
    for old, new in pairs:
        assert s.count(old) == 1, (path, old[:60], s.count(old))
        s = s.replace(old, new)
    open(p, 'w').write(s)

edit('src/render/shadergen.h', [(
'''    bool deferredLighting = false;
''','''    bool deferredLighting = false;
    // Clustered forward shading (cluster.h, shaders/cluster.glsl): each fragment loops over its cluster's
    // lights only. Chosen per frame by the renderer when the rig has many range-bounded lights.
    bool clustered = false;
''')])
edit('src/render/shadergen.cpp', [(
'''    put(deferredLighting, 1);
''','''    put(deferredLighting, 1);
    put(clustered, 1);
'''), (
'''    if (key.deferredLighting) out += "#define LR_DEFERRED_LIGHTING 1\\n";
''','''    if (key.deferredLighting) out += "#define LR_DEFERRED_LIGHTING 1\\n";
    if (key.clustered) out += "#define LR_CLUSTERED 1\\n";
'''), (
'''    if (output == ShaderOutput::GBuffer) parts << QStringLiteral("gbuffer");
''','''    if (output == ShaderOutput::GBuffer) parts << QStringLiteral("gbuffer");
    if (clustered) parts << QStringLiteral("clustered");
''')])
edit('src/render/programcache.cpp', [(
'''                               {QStringLiteral("lighting.glsl"), QStringLiteral("mesh.frag")},''',
'''                               {QStringLiteral("lighting.glsl"), QStringLiteral("cluster.glsl"),
                                QStringLiteral("mesh.frag")},'''), (
'''    p->setUniformValue("uLights", 3);
''','''    p->setUniformValue("uLights", 3);
    p->setUniformValue("uClusterRanges", 8);  // ClusterBuffers::kRangesUnit
    p->setUniformValue("uClusterIndices", 9);  // ClusterBuffers::kIndicesUnit
''')])
edit('shaders/mesh.frag', [(
'''    vec3 radiance = shadeSurface(s, st);''',
'''#ifdef LR_CLUSTERED
    vec3 radiance = shadeSurfaceClustered(s, st, gl_FragCoord.xy);
#else
    vec3 radiance = shadeSurface(s, st);
#endif''')])
edit('src/render/renderer.h', [(
'''    bool hdrFloat32 = false;  // HDR path: RGBA32F instead of RGBA16F
''','''    bool hdrFloat32 = false;  // HDR path: RGBA32F instead of RGBA16F
    // Clustered forward shading (render/cluster.h): -1 automatic (when more than a few lights have a
    // bounded range), 0 never, 1 always. Same pixels either way: it only skips exact zeros.
    int clusteredShading = -1;
'''), (
'''    double lastCpuMs = 0.0;''','''    bool clustered = false;     // the last frame used clustered shading
    qint64 clusterLightRefs = 0;  // its light-index list: global lights + per-cluster entries
    double lastCpuMs = 0.0;'''), (
'''class GpuModel;
''','''class GpuModel;
class ClusterBuffers;
struct LightBounds;
'''), (
'''    std::unique_ptr<render::Targets> m_targets;
''','''    std::unique_ptr<render::Targets> m_targets;
    std::unique_ptr<render::ClusterBuffers> m_clusters;
    std::vector<render::LightBounds> m_lightBounds;  // per uploaded light, view space
    int m_boundedLights = 0;
    bool clusterLights(const glm::dmat4& projection, const RenderSettings& settings);
''')])
edit('src/render/renderer.cpp', [(
'''#include "core/lighting.h"
''','''#include "cluster.h"
#include "clustergl.h"
#include "core/lighting.h"
'''), (
'''      m_targets(std::make_unique<Targets>()) {}''',
'''      m_targets(std::make_unique<Targets>()), m_clusters(std::make_unique<ClusterBuffers>()) {}'''), (
'''    m_targets->release(this);
''','''    m_targets->release(this);
    m_clusters->release(this);
'''), (
'''        const LightTexels t = packLight(castLight<float>(prepareLight(m_rig, frame, view, l)));
''','''        const lighting::ShadeLight<double> prepared = prepareLight(m_rig, frame, view, l);
        m_lightBounds.push_back(lightBounds(prepared, scale));
        m_boundedLights += m_lightBounds.back().bounded ? 1 : 0;
        const LightTexels t = packLight(castLight<float>(prepared));
'''), (
'''    int count = 0;
    for (const Light& l : m_rig.lights) {''','''    int count = 0;
    const double scale = prepareSettings(m_rig, frame).distanceScale;
    m_lightBounds.clear();
    m_boundedLights = 0;
    for (const Light& l : m_rig.lights) {'''), (
'''bool Renderer::drawModel(''','''// Bins the uploaded lights for this frame's projection and target (the viewport's size); false when
// clustering is off for this frame.
bool Renderer::clusterLights(const glm::dmat4& projection, const RenderSettings& settings) {
    m_stats.clustered = false;
    m_stats.clusterLightRefs = 0;
    const bool wanted = settings.clusteredShading > 0 ||
                        (settings.clusteredShading < 0 && m_boundedLights > kClusterMinBoundedLights);
    if (!wanted) return false;
    GLint viewport[4] = {};
    glGetIntegerv(GL_VIEWPORT, viewport);
    ClusterView cv;
    cv.projection = projection;
    cv.width = std::max(1, viewport[2]);
    cv.height = std::max(1, viewport[3]);
    // near and far back from the projection: P22 = -(f+n)/(f-n), P32 = -2fn/(f-n) (f infinite: P22 = -1)
    const double p22 = projection[2][2], p32 = projection[3][2];
    cv.znear = p32 / (p22 - 1.0);
    cv.zfar = p22 > -1.0 ? p32 / (p22 + 1.0) : std::numeric_limits<double>::infinity();
    if (!(cv.znear > 0.0) || !std::isfinite(cv.znear)) return false;
    const ClusterData data = binLights(m_lightBounds, cv);
    m_clusters->upload(this, data);
    m_stats.clustered = true;
    m_stats.clusterLightRefs = qint64(data.indices.size());
    m_clusterUniforms = {float(data.lookup.tileScale.x), float(data.lookup.tileScale.y), float(data.lookup.znear),
                         float(data.lookup.sliceScale)};
    m_clusterGlobal = data.globalCount;
    m_clusterGrid = {data.grid.tilesX, data.grid.tilesY, data.grid.slices};
    return true;
}

bool Renderer::drawModel('''), (
'''    const RigFeatures rig = rigFeatures(m_rig);
    const float exposureScale''','''    const RigFeatures rig = rigFeatures(m_rig);
    const bool clustered = output != int(ShaderOutput::GBuffer) && clusterLights(projection, settings);
    const float exposureScale'''), (
'''        key.output = ShaderOutput(output);
        order.emplace_back(key, &d);''','''        key.output = ShaderOutput(output);
        key.clustered = clustered;
        order.emplace_back(key, &d);'''), (
'''    glBindTexture(GL_TEXTURE_BUFFER, m_lightTexture);
    bool ok = true;''','''    glBindTexture(GL_TEXTURE_BUFFER, m_lightTexture);
    if (clustered) m_clusters->bind(this);
    bool ok = true;'''), (
'''            glUniform1i(p->lightCount, m_stats.lightsUploaded);
            if (p->exposureScale >= 0) glUniform1f(p->exposureScale, exposureScale);''','''            glUniform1i(p->lightCount, m_stats.lightsUploaded);
            if (clustered) setClusterUniforms(p->program.get());
            if (p->exposureScale >= 0) glUniform1f(p->exposureScale, exposureScale);''')])
edit('src/render/renderer.h', [(
'''    bool clusterLights(const glm::dmat4& projection, const RenderSettings& settings);
''','''    bool clusterLights(const glm::dmat4& projection, const RenderSettings& settings);
    void setClusterUniforms(QOpenGLShaderProgram* program);
    glm::vec4 m_clusterUniforms{0.0f};  // tile scale x, y, near, slice scale
    glm::ivec3 m_clusterGrid{0};
    int m_clusterGlobal = 0;
'''), ('''class QOpenGLContext;
''', '''class QOpenGLContext;
class QOpenGLShaderProgram;
''')])
edit('src/render/renderer.cpp', [(
'''bool Renderer::drawModel(''','''void Renderer::setClusterUniforms(QOpenGLShaderProgram* program) {
    const GLuint id = program->programId();
    glUniform1i(glGetUniformLocation(id, "uGlobalLightCount"), m_clusterGlobal);
    glUniform3i(glGetUniformLocation(id, "uClusterGrid"), m_clusterGrid.x, m_clusterGrid.y, m_clusterGrid.z);
    glUniform2f(glGetUniformLocation(id, "uClusterTileScale"), m_clusterUniforms.x, m_clusterUniforms.y);
    glUniform1f(glGetUniformLocation(id, "uClusterNear"), m_clusterUniforms.z);
    glUniform1f(glGetUniformLocation(id, "uClusterSliceScale"), m_clusterUniforms.w);
}

bool Renderer::drawModel(''')])
edit('shaders/deferred.frag', [(
'''    vec3 radiance = shadeSurface(s, st);''',
'''#ifdef LR_CLUSTERED
    vec3 radiance = shadeSurfaceClustered(s, st, gl_FragCoord.xy);
#else
    vec3 radiance = shadeSurface(s, st);
#endif''')])
edit('src/render/programcache.cpp', [(
'''                               {QStringLiteral("lighting.glsl"), QStringLiteral("deferred.frag")},''',
'''                               {QStringLiteral("lighting.glsl"), QStringLiteral("cluster.glsl"),
                                QStringLiteral("deferred.frag")},''')])
edit('src/render/renderer.h', [(
'''    int m_clusterGlobal = 0;
''','''    int m_clusterGlobal = 0;
    glm::dmat4 m_drawProjection{1.0};  // the last drawModel's: the deferred lighting pass bins with it
''')])
edit('src/render/renderer.cpp', [(
'''    const bool clustered = output != int(ShaderOutput::GBuffer) && clusterLights(projection, settings);''',
'''    m_drawProjection = projection;
    const bool clustered = output != int(ShaderOutput::GBuffer) && clusterLights(projection, settings);'''), (
'''    key.deferredLighting = true;
    QString error;''','''    key.deferredLighting = true;
    key.clustered = clusterLights(m_drawProjection, settings);
    QString error;'''), (
'''    if (p->toneMap >= 0) glUniform1i(p->toneMap, int(settings.toneMap));
    glActiveTexture(GL_TEXTURE0 + kLightUnit);
    glBindTexture(GL_TEXTURE_BUFFER, m_lightTexture);
    for (int i = 0;''','''    if (p->toneMap >= 0) glUniform1i(p->toneMap, int(settings.toneMap));
    if (key.clustered) {
        setClusterUniforms(p->program.get());
        m_clusters->bind(this);
    }
    glActiveTexture(GL_TEXTURE0 + kLightUnit);
    glBindTexture(GL_TEXTURE_BUFFER, m_lightTexture);
    for (int i = 0;''')])
cm = root + '/tests/perf/CMakeLists.txt'
if 'tst_clustergl' not in open(cm).read():
    open(cm, 'a').write('lightrig_add_test(tst_clustergl SOURCES tst_clustergl.cpp LIBS lightrig_render NO_APP)\n')
print('ok')
