#include "reference.h"

#include "core/colour.h"
#include "core/lighting.h"
#include "gbuffer.h"

#include <QtConcurrent/QtConcurrentMap>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace lr {

ReferenceScene makeReferenceScene(const Rig& rig, const SceneFrame& frame, const glm::dmat4& view,
                                  const RenderSettings& settings) {
    ReferenceScene s;
    s.lights = prepareLights(rig, frame, view);
    s.settings = prepareSettings(rig, frame);
    s.exposureEV = settings.exposureEV;
    s.toneMap = settings.toneMap;
    const QColor bg = settings.background.toRgb();
    s.background = colour::srgbToLinear(glm::dvec3(bg.redF(), bg.greenF(), bg.blueF()));
    return s;
}

glm::dvec3 encodeSrgb(const glm::dvec3& radiance, double exposureEV, ToneMap op) {
    return colour::displayColour(radiance, colour::exposureScale(exposureEV), op);
}

std::uint8_t toLevel(double srgb01) {
    return std::uint8_t(std::lround(lighting::saturate(srgb01) * 255.0));
}

ReferenceJob::ReferenceJob(GBuffer gbuffer, ReferenceScene scene)
    : m_gbuffer(std::move(gbuffer)), m_scene(std::move(scene)) {
    const int w = m_gbuffer.position.width, h = m_gbuffer.position.height;
    m_out.width = w;
    m_out.height = h;
    m_out.radiance.assign(size_t(w) * size_t(h), glm::dvec3(0.0));
    m_out.covered.assign(size_t(w) * size_t(h), 0);
    m_out.srgb = QImage(w, h, QImage::Format_RGBA8888);
    m_rowIndices.resize(size_t(h));
    std::iota(m_rowIndices.begin(), m_rowIndices.end(), 0);
}

QFuture<void> ReferenceJob::start() {
    return QtConcurrent::map(m_rowIndices, [this](int y) { evaluateRow(y); });
}

void ReferenceJob::evaluateRow(int y) {
    using V = glm::dvec3;
    const GBuffer& g = m_gbuffer;
    const ReferenceScene& sc = m_scene;
    const glm::dvec3 bg = encodeSrgb(sc.background, 0.0, ToneMap::Clamp);
    std::uint8_t* row = m_out.srgb.scanLine(y);
    for (int x = 0; x < m_out.width; ++x) {
        const size_t i = size_t(y) * size_t(m_out.width) + size_t(x);
        std::uint8_t* px = row + 4 * x;
        px[3] = 255;
        if (!(g.position.at(x, y).w >= 0.5f)) {
            for (int c = 0; c < 3; ++c)
                px[c] = toLevel(bg[c]);
            continue;
        }
        const lighting::Surface<double> s = render::surfaceAt(g, x, y);
        const V radiance = lighting::shadeSurface<double>(s, sc.lights, sc.settings);
        m_out.radiance[i] = radiance;
        m_out.covered[i] = 1;
        const V encoded = encodeSrgb(radiance, sc.exposureEV, sc.toneMap);
        for (int c = 0; c < 3; ++c)
            px[c] = toLevel(encoded[c]);
    }
}

ReferenceImage computeReference(const GBuffer& gbuffer, const ReferenceScene& scene) {
    ReferenceJob job(gbuffer, scene);
    job.start().waitForFinished();
    return job.result();
}

ErrorFigures compareWithReference(const QImage& frame, const ReferenceImage& reference) {
    ErrorFigures f;
    if (reference.isNull() || frame.size() != QSize(reference.width, reference.height)) return f;
    const QImage a =
        frame.format() == QImage::Format_RGBA8888 ? frame : frame.convertToFormat(QImage::Format_RGBA8888);
    // Format_RGBA8888 rows are 4·width bytes: no padding, so the pixels are contiguous.
    return compareSrgb8(a.constBits(), reference.srgb.constBits(),
                        std::int64_t(reference.width) * reference.height, 4, reference.covered.data());
}

} // namespace lr
