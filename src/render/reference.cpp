#include "reference.h"

#include "core/areaintegrate.h"
#include "core/colour.h"
#include "core/lighting.h"
#include "core/shapinglights.h"
#include "gbuffer.h"
#include "referencelayers.h"
#include "scene/linkparts.h"

#include <QtConcurrent/QtConcurrentMap>
#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <numeric>

namespace lr {

namespace {

// A caster's visibility as stored in ReferenceImage::visibility: 0 and 255 only when exact.
std::uint8_t visibilityCode(double v) {
    if (!(v > 0.0)) return 0;
    if (v >= 1.0) return 255;
    return std::uint8_t(std::clamp(std::lround(v * 255.0), 1L, 254L));
}

int largestChannelDifference(const glm::dvec3& a, const glm::dvec3& b, double exposureEV, ToneMap op) {
    const glm::dvec3 ea = encodeSrgb(a, exposureEV, op), eb = encodeSrgb(b, exposureEV, op);
    int d = 0;
    for (int c = 0; c < 3; ++c)
        d = std::max(d, std::abs(int(toLevel(ea[c])) - int(toLevel(eb[c]))));
    return d;
}

// Covered pixels over the target, the largest and mean error and samples of one integrator's figures.
EnvironmentConvergence convergenceOf(const ReferenceImage& r, const std::vector<float>& error,
                                     const std::vector<std::int32_t>& samplesTaken) {
    EnvironmentConvergence c;
    double errors = 0.0, samples = 0.0;
    for (size_t i = 0; i < r.covered.size() && i < error.size(); ++i) {
        if (!r.covered[i]) continue;
        ++c.pixels;
        const double e = error[i];
        errors += e, samples += samplesTaken[i];
        c.maxErrorLevels = std::max(c.maxErrorLevels, e);
        if (e > kEnvironmentTargetLevels) ++c.over;
    }
    if (c.pixels > 0)
        c.meanErrorLevels = errors / double(c.pixels), c.meanSamples = samples / double(c.pixels);
    return c;
}

// The rig's links over the model's parts and the ground's (groundModel's one mesh, when the ground is
// on): what SceneDescription::links() resolves for the same model and rig.
LinkResolution referenceLinks(const Model& model, const Rig& rig) {
    std::vector<PartNames> parts = linkParts(&model, nullptr);
    if (rig.ground.mode != GroundMode::Off) parts.push_back(PartNames::theGround());
    return resolveLinks(rig.lights, parts);
}

std::optional<ReferenceScene> makeScene(const Model& model, const Rig& rig, const SceneFrame& frame,
                                        const glm::dmat4& view, const RenderSettings& settings,
                                        QString* error,
                                        const std::shared_ptr<const LoadedEnvironment>& environment,
                                        const LinkResolution& links,
                                        const std::vector<std::shared_ptr<const GoboImage>>& gobos,
                                        const std::vector<std::shared_ptr<const IesProfile>>& ies);

} // namespace

bool ReferenceScene::hasAreaLights() const {
    return std::any_of(lights.begin(), lights.end(),
                       [](const lighting::ShadeLight<double>& l) { return traitsOf(l.type).isArea; });
}

int ReferenceScene::casters() const {
    return int(
        std::count_if(emitters.begin(), emitters.end(), [](const ShadowEmitter& e) { return e.casts; }));
}

std::optional<ReferenceScene>
makeReferenceScene(const Model& model, const Rig& rig, const SceneFrame& frame, const glm::dmat4& view,
                   const RenderSettings& settings, QString* error,
                   const std::shared_ptr<const LoadedEnvironment>& environment) {
    return makeScene(model, rig, frame, view, settings, error, environment, referenceLinks(model, rig), {},
                     {});
}

std::optional<ReferenceScene> makeReferenceScene(const SceneDescription& scene, const glm::dmat4& view,
                                                 const RenderSettings& settings, QString* error) {
    static const Model none;
    return makeScene(scene.model() ? *scene.model() : none, scene.rig(), scene.frame(), view, settings, error,
                     scene.environment(), scene.links(), scene.lightAssets().gobos, scene.lightAssets().ies);
}

namespace {

// Switches the lights of `lights` (ReferenceScene::lights: the rig's enabled ones, rig index
// rigIndex[k]) that do not light lighting class `c` off: every term of theirs is then exactly 0.
std::vector<lighting::ShadeLight<double>> lightsOfClass(std::vector<lighting::ShadeLight<double>> lights,
                                                        const std::vector<size_t>& rigIndex,
                                                        const LinkResolution& links, int c) {
    for (size_t k = 0; k < lights.size(); ++k)
        if (!((links.litMask[rigIndex[k]] >> c) & 1u))
            lights[k].color = lights[k].specular = lights[k].ambient = glm::dvec3(0.0);
    return lights;
}

std::optional<ReferenceScene> makeScene(const Model& model, const Rig& rig, const SceneFrame& frame,
                                        const glm::dmat4& view, const RenderSettings& settings,
                                        QString* error,
                                        const std::shared_ptr<const LoadedEnvironment>& environment,
                                        const LinkResolution& links,
                                        const std::vector<std::shared_ptr<const GoboImage>>& gobos,
                                        const std::vector<std::shared_ptr<const IesProfile>>& ies) {
    ReferenceScene s;
    s.lights = prepareLights(rig, frame, view);
    applyLightShaping(s.lights, rig, ies, gobos, view); // issue 39: exactly as core shades them
    s.iesProfiles = ies;
    s.settings = prepareSettings(rig, frame);
    s.exposureEV = settings.exposureEV;
    s.toneMap = settings.toneMap;
    const QColor bg = settings.background.toRgb();
    s.background = colour::srgbToLinear(glm::dvec3(bg.redF(), bg.greenF(), bg.blueF()));
    std::vector<size_t> rigIndex;                  // of each of s.lights
    for (size_t i = 0; i < rig.lights.size(); ++i) // the lights prepareLights() kept, in its order
        if (rig.lights[i].enabled) {
            s.emitters.push_back(shadowEmitter(rig, frame, rig.lights[i]));
            rigIndex.push_back(i);
        }
    for (size_t k = 0; k < rigIndex.size() && k < s.lights.size(); ++k) // keeps the images alive
        if (s.lights[k].gobo) s.gobos.push_back(gobos[rigIndex[k]]);
    if (links.active && rigIndex.size() == s.lights.size()) {
        for (size_t k = 0; k < rigIndex.size(); ++k)
            s.emitters[k].shadowMask = links.shadowMask[rigIndex[k]];
        s.litClass = links.litClass;
        for (int c = 0; c < std::max(1, links.litClasses); ++c)
            s.lightsOfClass.push_back(lightsOfClass(s.lights, rigIndex, links, c));
    }
    s.viewToWorld = glm::inverse(view);
    s.areaConvergence = areaintegrate::defaultConvergence(settings.exposureEV, settings.toneMap);
    s.areaConvergence.targetLevels = kEnvironmentTargetLevels;
    if (s.casters() > 0 || s.linked()) {
        auto tracer = std::make_shared<const ShadowTracer>(model, rig.ground.mode != GroundMode::Off,
                                                           EmbreeScene::shadowClassMasks(links));
        if (!tracer->ok()) {
            if (error) *error = tracer->error();
            return std::nullopt;
        }
        s.tracer = std::move(tracer);
    }
    if (!rig.environment.isNone() && environment && !environment->image.isNull()) {
        // The image shared, not copied: the aliasing pointer keeps the loaded environment alive.
        std::shared_ptr<const EnvironmentImage> image(environment, &environment->image);
        s.environment = std::make_shared<const envintegrate::EnvironmentField>(
            std::move(image), rig.environment.intensity, rig.environment.rotation, rig.environment.diffuse);
        s.environmentConvergence.exposureEV = settings.exposureEV;
        s.environmentConvergence.toneMap = settings.toneMap;
        s.environmentConvergence.targetLevels = kEnvironmentTargetLevels;
        s.environmentSource = environment->source;
    }
    return s;
}

} // namespace

EnvironmentConvergence environmentConvergence(const ReferenceImage& r) {
    return r.environment ? convergenceOf(r, r.environmentError, r.environmentSamples)
                         : EnvironmentConvergence{};
}

EnvironmentConvergence areaConvergence(const ReferenceImage& r) {
    return r.area ? convergenceOf(r, r.areaError, r.areaSamples) : EnvironmentConvergence{};
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
    // Traced only with a tracer and one emitter per light (makeReferenceScene's pairing).
    m_out.casters =
        m_scene.tracer && m_scene.emitters.size() == m_scene.lights.size() ? m_scene.casters() : 0;
    if (m_out.casters > 0) {
        m_out.visibility.assign(size_t(w) * size_t(h) * size_t(m_out.casters), 255);
        m_out.shadowClass.assign(size_t(w) * size_t(h), 0);
    }
    m_out.environment = m_scene.environment != nullptr;
    if (m_out.environment) {
        m_out.environmentError.assign(size_t(w) * size_t(h), 0.0f);
        m_out.environmentSamples.assign(size_t(w) * size_t(h), 0);
    }
    m_out.area = m_scene.hasAreaLights();
    if (m_out.area) {
        m_out.areaError.assign(size_t(w) * size_t(h), 0.0f);
        m_out.areaSamples.assign(size_t(w) * size_t(h), 0);
    }
    m_out.groupCount = std::max(0, m_scene.groups.count);
    if (m_out.groupCount > 0)
        m_out.groupRadiance.assign(size_t(w) * size_t(h) * size_t(m_out.groupCount), glm::dvec3(0.0));
    m_rowIndices.resize(size_t(h));
    std::iota(m_rowIndices.begin(), m_rowIndices.end(), 0);
}

QFuture<void> ReferenceJob::start() {
    m_finished = false;
    return QtConcurrent::map(m_rowIndices, [this](int y) { evaluateRow(y); });
}

void ReferenceJob::finish() {
    if (m_finished) return;
    markShadowBand(&m_out);
    m_finished = true;
}

void ReferenceJob::evaluateRow(int y) {
    using V = glm::dvec3;
    const GBuffer& g = m_gbuffer;
    const ReferenceScene& sc = m_scene;
    const glm::dvec3 bg = encodeSrgb(sc.background, 0.0, ToneMap::Clamp);
    const int casters = m_out.casters;
    const bool traced = sc.tracer && (casters > 0 || sc.linked());
    const size_t n = sc.lights.size();
    std::vector<double> visibility(n, 1.0), dark(n, 1.0);
    for (size_t k = 0; k < n; ++k)
        if (casters > 0 && sc.emitters[k].casts) dark[k] = 0.0;
    // Area lights go through shade.h with visibility 0 (their ambient only) and through areaintegrate for
    // their direct terms: `shaded` is `visibility` so masked, `litShaded`/`darkShaded` all lit/`dark`.
    std::vector<bool> isArea(n, false);
    for (size_t k = 0; k < n; ++k)
        isArea[k] = traitsOf(sc.lights[k].type).isArea;
    std::vector<double> shaded(n, 1.0), litShaded(n, 1.0), darkShaded = dark;
    for (size_t k = 0; k < n; ++k)
        if (isArea[k]) litShaded[k] = darkShaded[k] = 0.0;
    std::vector<V> direct;
    const glm::dvec3 eye(sc.viewToWorld[3]);
    const glm::dmat3 toWorld(sc.viewToWorld);
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
        std::span<const lighting::ShadeLight<double>> lights = sc.lights;
        if (traced) {
            // The surface the eye's ray meets here: its geometric normal (shadow rays), its part (links).
            const glm::dvec3 p(sc.viewToWorld * glm::dvec4(s.position, 1.0));
            const glm::dvec3 shadingNormal = lighting::safeNormalize(
                glm::dvec3(sc.viewToWorld * glm::dvec4(s.normal, 0.0)), glm::dvec3(0, 1, 0));
            const ShadowTracer::Seen seen = sc.tracer->surfaceSeen(eye, p, shadingNormal);
            if (sc.linked()) lights = sc.lightsAt(seen.part);
            if (casters > 0) tracePixel(s, lights, i, p, seen.normal, visibility);
        }
        for (size_t k = 0; k < n; ++k)
            shaded[k] = isArea[k] ? 0.0 : visibility[k];
        V radiance = lighting::shadeSurface<double>(s, lights, sc.settings, shaded);
        if (m_out.area) {
            const areaintegrate::Estimate a = areaintegrate::integrate(
                lights, visibility, s, sc.settings, std::uint64_t(i), sc.areaConvergence, radiance,
                casters > 0 || m_out.groupCount > 0 ? &direct : nullptr);
            radiance += a.radiance;
            m_out.areaError[i] = float(a.errorLevels);
            m_out.areaSamples[i] = a.samples;
        }
        V environment(0.0);
        if (sc.environment) {
            const envintegrate::Estimate e = sc.environment->integrate(
                s, sc.settings, toWorld, std::uint64_t(i), sc.environmentConvergence, radiance);
            environment = e.radiance;
            radiance += environment;
            m_out.environmentError[i] = float(e.errorLevels);
            m_out.environmentSamples[i] = e.samples;
        }
        if (casters > 0) {
            // Whether the casters' direct light shows here at all: the image with all of it and with none
            // (the environment, never shadowed, in both).
            V lit = lighting::shadeSurface<double>(s, lights, sc.settings, litShaded) + environment;
            V unlit = lighting::shadeSurface<double>(s, lights, sc.settings, darkShaded) + environment;
            for (size_t k = 0; k < direct.size(); ++k)
                lit += direct[k], unlit += dark[k] * direct[k];
            m_out.shadowClass[i] =
                largestChannelDifference(lit, unlit, sc.exposureEV, sc.toneMap) > kShadowThresholdLevels ? 1
                                                                                                         : 0;
        }
        if (m_out.groupCount > 0) {
            if (!m_out.area) direct.assign(n, V(0.0));
            splitReferencePixel(sc, lights, s, shaded, visibility, direct, environment,
                                &m_out.groupRadiance[i * size_t(m_out.groupCount)]);
        }
        m_out.radiance[i] = radiance;
        m_out.covered[i] = 1;
        const V encoded = encodeSrgb(radiance, sc.exposureEV, sc.toneMap);
        for (int c = 0; c < 3; ++c)
            px[c] = toLevel(encoded[c]);
    }
}

void ReferenceJob::tracePixel(const lighting::Surface<double>& s,
                              std::span<const lighting::ShadeLight<double>> lights, size_t pixel,
                              const glm::dvec3& p, const glm::dvec3& n, std::vector<double>& visibility) {
    const ReferenceScene& sc = m_scene;
    int k = 0;
    for (size_t l = 0; l < lights.size(); ++l) {
        if (!sc.emitters[l].casts) continue;
        // Where the light's direct terms add nothing (outside its cone or range, facing away from it
        // without a wrapped diffuse; an area light's emitter wholly behind or below the surface) visibility
        // cannot matter: nothing is traced, it is 1.
        const std::span<const lighting::ShadeLight<double>> one(&lights[l], 1);
        constexpr double kLit[] = {1.0}, kUnlit[] = {0.0};
        double v = 1.0;
        if (traitsOf(lights[l].type).isArea ? areaintegrate::reaches(lights[l], s)
                                            : lighting::shadeSurface<double>(s, one, sc.settings, kLit) !=
                                                  lighting::shadeSurface<double>(s, one, sc.settings, kUnlit))
            v = sc.tracer->visibility(p, n, sc.emitters[l], std::uint32_t(pixel * 977u + size_t(k) * 7919u));
        visibility[l] = v;
        m_out.visibility[pixel * size_t(m_out.casters) + size_t(k)] = visibilityCode(v);
        ++k;
    }
}

ReferenceImage computeReference(const GBuffer& gbuffer, const ReferenceScene& scene) {
    ReferenceJob job(gbuffer, scene);
    job.start().waitForFinished();
    job.finish();
    return job.result();
}

void markShadowBand(ReferenceImage* r) {
    const int w = r->width, h = r->height, nc = r->casters;
    if (nc <= 0 || r->isNull()) return;
    const size_t n = size_t(w) * size_t(h);
    // Per caster: the smallest and largest code of the covered pixels within the band radius (separable:
    // rows, then columns of the row results).
    std::vector<std::uint8_t> rowLo(n), rowHi(n);
    constexpr int R = kShadowBandRadius;
    for (int k = 0; k < nc; ++k) {
        const auto code = [&](size_t i) { return r->visibility[i * size_t(nc) + size_t(k)]; };
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                std::uint8_t lo = 255, hi = 0;
                for (int xx = std::max(0, x - R); xx <= std::min(w - 1, x + R); ++xx) {
                    const size_t j = size_t(y) * size_t(w) + size_t(xx);
                    if (!r->covered[j]) continue;
                    lo = std::min(lo, code(j)), hi = std::max(hi, code(j));
                }
                rowLo[size_t(y) * size_t(w) + size_t(x)] = lo, rowHi[size_t(y) * size_t(w) + size_t(x)] = hi;
            }
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t i = size_t(y) * size_t(w) + size_t(x);
                if (!r->covered[i]) continue;
                std::uint8_t lo = 255, hi = 0;
                for (int yy = std::max(0, y - R); yy <= std::min(h - 1, y + R); ++yy) {
                    const size_t j = size_t(yy) * size_t(w) + size_t(x);
                    lo = std::min(lo, rowLo[j]), hi = std::max(hi, rowHi[j]);
                }
                const std::uint8_t v = code(i);
                if ((v > 0 && v < 255) || lo < hi) r->shadowClass[i] = 2;
            }
    }
}

ShadowFigures compareShadows(const QImage& frame, const ReferenceImage& reference) {
    ShadowFigures f;
    if (reference.casters <= 0 || reference.isNull() ||
        frame.size() != QSize(reference.width, reference.height))
        return f;
    const QImage a =
        frame.format() == QImage::Format_RGBA8888 ? frame : frame.convertToFormat(QImage::Format_RGBA8888);
    const std::uint8_t* pa = a.constBits();
    const std::uint8_t* pb = reference.srgb.constBits();
    double sum = 0.0;
    const size_t n = size_t(reference.width) * size_t(reference.height);
    for (size_t i = 0; i < n; ++i) {
        if (!reference.covered[i]) continue;
        if (reference.shadowClass[i] == 2) ++f.band;
        if (reference.shadowClass[i] != 1) continue;
        int largest = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(pa[4 * i + size_t(c)]) - int(pb[4 * i + size_t(c)]));
            sum += d;
            largest = std::max(largest, d);
        }
        ++f.compared;
        if (largest > kShadowThresholdLevels) ++f.differing;
    }
    f.meanLevels = f.compared > 0 ? sum / (3.0 * double(f.compared)) : 0.0;
    return f;
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
