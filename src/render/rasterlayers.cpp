#include "rasterlayers.h"

#include "layerscommon.h"
#include "shadowplan.h"

#include <QElapsedTimer>
#include <algorithm>

namespace lr {

namespace {

bool fail(QString* error, const QString& message) {
    if (error) *error = message;
    return false;
}

// Puts the renderer's rig back however the split ends.
struct RigRestore {
    Renderer& renderer;
    Rig rig;
    ~RigRestore() { renderer.setRig(rig); }
};

void subtractRgb(FloatImage* image, const FloatImage& minus) {
    if (minus.pixels.size() != image->pixels.size()) return;
    for (size_t i = 0; i < image->pixels.size(); ++i)
        image->pixels[i] -= glm::vec4(glm::vec3(minus.pixels[i]), 0.0f);
}

void copyAlpha(FloatImage* image, const FloatImage& from) {
    for (size_t i = 0; i < image->pixels.size() && i < from.pixels.size(); ++i)
        image->pixels[i].w = from.pixels[i].w;
}

// "background": zero (the radiance has no background colour), or over a shadow catcher what the other
// groups leave of the beauty (the catcher's composite: a ratio of lit to unlit light, not a sum).
FloatImage backgroundImage(const RenderLayers& layers, size_t background, bool catcher) {
    FloatImage out;
    out.width = layers.beauty.width;
    out.height = layers.beauty.height;
    out.pixels.assign(layers.beauty.pixels.size(), glm::vec4(0.0f));
    if (!catcher) return out;
    for (size_t i = 0; i < out.pixels.size(); ++i) {
        glm::dvec3 rest(layers.beauty.pixels[i]);
        for (size_t g = 0; g < layers.groupImages.size(); ++g)
            if (g != background) rest -= glm::dvec3(glm::vec3(layers.groupImages[g].pixels[i]));
        out.pixels[i] = glm::vec4(glm::vec3(rest), 0.0f);
    }
    return out;
}

} // namespace

Rig groupPassRig(const Rig& rig, const LightGroup& group, int shadowResolution,
                 const std::vector<bool>& casts) {
    Rig out = rig;
    const bool lights = group.kind == LightGroupKind::Lights;
    for (size_t i = 0; i < out.lights.size(); ++i) {
        Light& l = out.lights[i];
        const bool in =
            lights && std::find(group.lights.begin(), group.lights.end(), int(i)) != group.lights.end();
        l.enabled = l.enabled && in;
        if (i < casts.size() && !casts[i]) l.shadow.enabled = false;
        if (shadowResolution > 0 && l.shadow.enabled) l.shadow.resolution = shadowResolution;
    }
    if (group.kind != LightGroupKind::Ambient) out.ambient = glm::dvec3(0.0);
    if (group.kind != LightGroupKind::Environment) out.environment.source = EnvironmentSource::None;
    return out;
}

qint64 rasterLayersBytes(QSize size, int groups) {
    return qint64(std::max(0, groups) + 5) * qint64(std::max(0, size.width())) *
           qint64(std::max(0, size.height())) * qint64(sizeof(glm::vec4));
}

std::optional<RenderLayers> renderRasterLayers(OffscreenRenderer& offscreen, const ViewCamera& camera,
                                               QSize size, const RenderSettings& settings, QString* error,
                                               RasterLayersStats* stats, const TileProgress& progress) {
    Renderer& renderer = offscreen.renderer();
    const SceneDescription& scene = renderer.scene();
    if (!scene.model()) return fail(error, QStringLiteral("light-group layers need a model")), std::nullopt;
    const int tile = offscreen.maxTileSize();
    if (size.isEmpty() || size.width() > tile || size.height() > tile)
        return fail(error, QStringLiteral("light-group layers are rendered in one tile: at most %1x%1 pixels "
                                          "here, asked for %2x%3")
                               .arg(tile)
                               .arg(size.width())
                               .arg(size.height())),
               std::nullopt;
    QElapsedTimer clock;
    clock.start();
    const Rig rig = scene.rig();
    RigRestore restore{renderer, rig};
    RenderLayers layers;
    layers.groups = sceneLightGroups(scene);

    // The beauty's shadows: the casters its array holds, at its resolution.
    const std::vector<render::ShadowView> views = render::planShadows(rig, scene.frame(), scene.bounds());
    const int shadowResolution = views.empty() ? 0 : views.front().resolution;
    std::vector<bool> casts(rig.lights.size(), true);
    for (size_t i = 0; i < rig.lights.size(); ++i)
        casts[i] = !rig.lights[i].hasShadow() || std::any_of(views.begin(), views.end(), [&](const auto& v) {
            return v.rigIndex == int(i);
        });

    // The passes: the G-buffer, the beauty, the emission's (when it emits), each group's but the emission's
    // and the background's.
    const bool emits = std::any_of(layers.groups.begin(), layers.groups.end(),
                                   [](const LightGroup& g) { return g.kind == LightGroupKind::Emissive; });
    const int total = 2 + int(emits) +
                      int(std::count_if(layers.groups.begin(), layers.groups.end(), [](const LightGroup& g) {
                          return g.kind == LightGroupKind::Lights || g.kind == LightGroupKind::Environment ||
                                 g.kind == LightGroupKind::Ambient;
                      }));
    int done = 0;
    const auto advance = [&] {
        if (progress && !progress(done, total)) return fail(error, QStringLiteral("cancelled"));
        ++done;
        return true;
    };
    if (!advance()) return std::nullopt;
    GBuffer gbuffer;
    if (!offscreen.renderGBuffer(camera, size, settings, &gbuffer, error)) return std::nullopt;
    fillAuxiliaryLayers(gbuffer, renderer.effectiveCamera(camera).view(), &layers);
    gbuffer = GBuffer();

    if (!advance()) return std::nullopt;
    QElapsedTimer beautyClock;
    beautyClock.start();
    if (!offscreen.renderRadiance(camera, size, settings, &layers.beauty, error)) return std::nullopt;
    const double beautyMs = double(beautyClock.nsecsElapsed()) * 1e-6;
    int passes = 1;
    // Every pass shades as the beauty did: Auto's choice depends on the light count.
    RenderSettings s = settings;
    if (settings.quality != Quality::Fast)
        s.shadingPath = renderer.stats().deferred ? ShadingPath::Deferred : ShadingPath::Forward;
    const auto pass = [&](const LightGroup& group, FloatImage* out) {
        if (!advance()) return false;
        renderer.setRig(groupPassRig(rig, group, shadowResolution, casts));
        ++passes;
        if (offscreen.renderRadiance(camera, size, s, out, error)) return true;
        if (error) *error = QStringLiteral("light group '%1': %2").arg(group.name, *error);
        return false;
    };
    FloatImage emission;
    const LightGroup nothing{QStringLiteral("emissive"), LightGroupKind::Emissive, {}};
    if (emits && !pass(nothing, &emission)) return std::nullopt;

    layers.groupImages.resize(layers.groups.size());
    size_t background = layers.groups.size();
    for (size_t g = 0; g < layers.groups.size(); ++g) {
        const LightGroup& group = layers.groups[g];
        FloatImage& image = layers.groupImages[g];
        if (group.kind == LightGroupKind::Background) {
            background = g;
            continue;
        }
        if (group.kind == LightGroupKind::Emissive) {
            image = emission;
        } else {
            if (!pass(group, &image)) return std::nullopt;
            if (emits) subtractRgb(&image, emission);
        }
        copyAlpha(&image, layers.beauty);
    }
    if (background < layers.groups.size()) {
        layers.groupImages[background] =
            backgroundImage(layers, background, rig.ground.mode == GroundMode::Catcher);
        copyAlpha(&layers.groupImages[background], layers.beauty);
    }
    if (progress && !progress(total, total)) return fail(error, QStringLiteral("cancelled")), std::nullopt;
    if (stats) {
        stats->passes = passes;
        stats->groups = int(layers.groups.size());
        stats->beautyMs = beautyMs;
        stats->splitMs = double(clock.nsecsElapsed()) * 1e-6 - beautyMs;
        stats->bytes = rasterLayersBytes(size, int(layers.groups.size()));
    }
    return layers;
}

} // namespace lr
