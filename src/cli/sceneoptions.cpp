#include "sceneoptions.h"

#include "core/defaultrig.h"
#include "core/lighting.h"
#include "core/rigjson.h"
#include "model/isolatedimport.h"

#include <QRegularExpression>
#include <algorithm>
#include <cmath>

namespace lr::cli {

SceneOptionSet::SceneOptionSet()
    : rig(QStringLiteral("rig"),
          QStringLiteral(
              "Rig file (.json). Default: the model's own lights when it has some, else the default rig."),
          QStringLiteral("RIG")),
      cameraIndex(QStringLiteral("camera-index"), QStringLiteral("Use camera N of the model file (from 0)."),
                  QStringLiteral("N")),
      view(QStringLiteral("view"),
           QStringLiteral("Standard view framing the model: %1. Default: the model's camera 0 if it has one, "
                          "else three-quarter.")
               .arg(standardViewNames().join(QStringLiteral(", "))),
           QStringLiteral("NAME")),
      size(QStringLiteral("size"), QStringLiteral("Image size in pixels (default 1280x720)."),
           QStringLiteral("WxH")),
      quality(QStringLiteral("quality"),
              QStringLiteral("Quality tier: %1 (default exact).").arg(allowedNames<Quality>()),
              QStringLiteral("Q")),
      exposure(QStringLiteral("exposure"),
               QStringLiteral("Exposure in EV: radiance is scaled by 2^EV (default 0)."),
               QStringLiteral("EV")),
      toneMap(QStringLiteral("tonemap"),
              QStringLiteral("Tone map: %1 (default clamp).").arg(allowedNames<ToneMap>()),
              QStringLiteral("OP")),
      shading(QStringLiteral("shading"),
              QStringLiteral("Shading: %1 (default: the rig's; without --rig, pbr for a model with "
                             "physically based materials, else classic).")
                  .arg(allowedNames<ShadingModel>()),
              QStringLiteral("MODEL")),
      ground(QStringLiteral("ground"),
             QStringLiteral("Ground plane under the model: %1 (default: the rig's). catcher: invisible but "
                            "for the shadows it receives (kept in the alpha of a --transparent image).")
                 .arg(allowedNames<GroundMode>()),
             QStringLiteral("MODE")),
      shadows(
          QStringLiteral("shadows"),
          QStringLiteral("on: every point, spot and directional light casts its shadow (at most %1); off: "
                         "none. Default: as the rig says.")
              .arg(kMaxShadowCasters),
          QStringLiteral("on|off")) {}

void SceneOptionSet::addTo(QCommandLineParser& parser) const {
    parser.addOptions({rig, cameraIndex, view, size, quality, exposure, toneMap, shading, ground, shadows});
    parser.addOptions(environment.options());
}

std::optional<QSize> parseSize(const QString& text, int maxSide, QString* why) {
    static const QRegularExpression re(QStringLiteral("^(\\d+)[xX](\\d+)$"));
    const QRegularExpressionMatch m = re.match(text.trimmed());
    QString reason = QStringLiteral("expected WxH with sides 1..%1").arg(maxSide);
    const auto refuse = [&] {
        if (why) *why = reason;
        return std::nullopt;
    };
    if (!m.hasMatch()) return refuse();
    int side[2] = {0, 0};
    for (int i = 0; i < 2; ++i) {
        const QString digits = m.captured(i + 1);
        bool ok = false;
        const qulonglong v = digits.toULongLong(&ok);
        if (!ok || v > qulonglong(maxSide)) { // past 2^64 too
            reason = QStringLiteral("the %1 %2 is larger than the limit %3")
                         .arg(i == 0 ? QStringLiteral("width") : QStringLiteral("height"), digits)
                         .arg(maxSide);
            return refuse();
        }
        side[i] = int(v);
    }
    if (side[0] < 1 || side[1] < 1) {
        reason = QStringLiteral("each side must be at least 1");
        return refuse();
    }
    return QSize(side[0], side[1]);
}

std::optional<int> viewCameraIndex(const QString& view) {
    static const QRegularExpression re(QStringLiteral("^(?:camera)?(\\d{1,6})$"));
    const QRegularExpressionMatch m = re.match(view);
    if (!m.hasMatch()) return std::nullopt;
    return m.captured(1).toInt();
}

std::optional<SceneOptions> SceneOptionSet::read(const QCommandLineParser& p, QString* usageError,
                                                 bool qualityList, bool viewList, bool pathQuality) const {
    SceneOptions o;
    auto bad = [&](const QString& message) {
        *usageError = message;
        return std::nullopt;
    };
    o.rigPath = p.value(rig);
    if (p.isSet(rig) && o.rigPath.isEmpty()) return bad(QStringLiteral("--rig needs a file name"));
    if (p.isSet(cameraIndex) && p.isSet(view))
        return bad(QStringLiteral("--camera-index and --view exclude each other"));
    if (p.isSet(cameraIndex)) {
        bool ok = false;
        const int n = p.value(cameraIndex).toInt(&ok);
        if (!ok || n < 0)
            return bad(QStringLiteral("--camera-index must be a whole number >= 0, got '%1'")
                           .arg(p.value(cameraIndex)));
        o.cameraIndex = n;
    }
    if (p.isSet(view) && viewList) {
        for (const QString& value : p.values(view))
            for (const QString& part : value.split(QLatin1Char(','))) {
                const QString v = part.trimmed();
                if (!standardViewNames().contains(v) && !viewCameraIndex(v))
                    return bad(QStringLiteral("--view must be one of %1 or cameraN, got '%2'")
                                   .arg(standardViewNames().join(QStringLiteral(", ")), v));
                const QString name =
                    viewCameraIndex(v) ? QStringLiteral("camera%1").arg(*viewCameraIndex(v)) : v;
                if (!o.views.contains(name)) o.views.append(name);
            }
        if (o.views.size() == 1 && !viewCameraIndex(o.views.first())) o.view = o.views.first();
        if (o.views.size() == 1 && viewCameraIndex(o.views.first()))
            o.cameraIndex = viewCameraIndex(o.views.first());
    } else if (p.isSet(view)) {
        o.view = p.value(view);
        if (!standardViewNames().contains(o.view))
            return bad(QStringLiteral("--view must be one of %1, got '%2'")
                           .arg(standardViewNames().join(QStringLiteral(", ")), o.view));
    }
    if (p.isSet(size)) {
        QString why;
        const auto s = parseSize(p.value(size), 32768, &why);
        if (!s) return bad(QStringLiteral("--size: %1, got '%2'").arg(why, p.value(size)));
        o.size = *s;
    }
    if (p.isSet(quality) && pathQuality && p.value(quality) == QLatin1String("path")) {
        o.pathTraced = true;
        if (qualityList) o.qualities.clear(); // bench: the path tier alone
    } else if (p.isSet(quality)) {
        const QStringList names =
            qualityList ? p.value(quality).split(QLatin1Char(',')) : QStringList{p.value(quality)};
        o.qualities.clear();
        for (const QString& name : names) {
            if (qualityList && pathQuality && name.trimmed() == QLatin1String("path")) {
                o.pathTraced = true; // bench's path tier beside the raster tiers
                continue;
            }
            const auto q = fromString<Quality>(name.trimmed());
            if (!q)
                return bad(QStringLiteral("--quality must be %1%2, got '%3'")
                               .arg(pathQuality
                                        ? QString(allowedNames<Quality>())
                                                  .replace(QStringLiteral(" or "), QStringLiteral(", ")) +
                                              QStringLiteral(" or \"path\"")
                                        : allowedNames<Quality>(),
                                    qualityList ? QStringLiteral(" (or a comma list)") : QString(),
                                    p.value(quality)));
            if (std::find(o.qualities.begin(), o.qualities.end(), *q) == o.qualities.end())
                o.qualities.push_back(*q);
        }
        if (!o.qualities.empty()) o.quality = o.qualities.front();
    }
    if (p.isSet(exposure)) {
        bool ok = false;
        o.exposureEV = p.value(exposure).toDouble(&ok);
        if (!ok || !std::isfinite(o.exposureEV) || std::abs(o.exposureEV) > 60.0)
            return bad(QStringLiteral("--exposure must be a number of EV in -60..60, got '%1'")
                           .arg(p.value(exposure)));
    }
    if (p.isSet(toneMap)) {
        const auto t = fromString<ToneMap>(p.value(toneMap));
        if (!t)
            return bad(QStringLiteral("--tonemap must be %1, got '%2'")
                           .arg(allowedNames<ToneMap>(), p.value(toneMap)));
        o.toneMap = *t;
    }
    if (p.isSet(shading)) {
        const auto m = fromString<ShadingModel>(p.value(shading));
        if (!m)
            return bad(QStringLiteral("--shading must be %1, got '%2'")
                           .arg(allowedNames<ShadingModel>(), p.value(shading)));
        o.shading = *m;
    }
    if (p.isSet(ground)) {
        const auto g = fromString<GroundMode>(p.value(ground));
        if (!g)
            return bad(QStringLiteral("--ground must be %1, got '%2'")
                           .arg(allowedNames<GroundMode>(), p.value(ground)));
        o.ground = *g;
    }
    if (p.isSet(shadows)) {
        const QString v = p.value(shadows);
        if (v != QLatin1String("on") && v != QLatin1String("off"))
            return bad(QStringLiteral("--shadows must be \"on\" or \"off\", got '%1'").arg(v));
        o.shadows = v == QLatin1String("on");
    }
    const auto env = environment.read(p, usageError);
    if (!env) return std::nullopt;
    o.environment = *env;
    return o;
}

bool applyShadowsOption(Rig& rig, bool on, QString* error) {
    int casters = 0;
    for (const Light& l : rig.lights)
        casters += on && l.castsShadows();
    if (casters > kMaxShadowCasters) {
        *error =
            QStringLiteral("--shadows on: %1 lights of the rig can cast shadows; at most %2 can (one shadow "
                           "map each): use a rig that switches on the shadows of the lights that matter")
                .arg(casters)
                .arg(kMaxShadowCasters);
        return false;
    }
    for (Light& l : rig.lights)
        if (l.castsShadows()) l.shadow.enabled = on;
    return true;
}

QString shadowSummary(const Rig& rig) {
    int casters = 0;
    for (const Light& l : rig.lights)
        casters += l.hasShadow();
    if (casters == 0) return {};
    return casters == 1 ? QStringLiteral(", shadows from 1 light")
                        : QStringLiteral(", shadows from %1 lights").arg(casters);
}

bool loadScene(const QString& modelPath, const SceneOptions& options, LoadedScene* scene, QString* error,
               EnvironmentLoading loading) {
    return loadSceneModel(modelPath, scene, error) &&
           loadSceneRig(modelPath, options, scene, error, loading) &&
           chooseSceneCamera(modelPath, options, scene, error);
}

bool loadSceneModel(const QString& modelPath, LoadedScene* scene, QString* error) {
    // In `lightrig import-worker`: an importer crash, hang or allocation bomb is a message, not our end.
    ModelLoadResult loaded = importModelIsolated(modelPath);
    if (!loaded.ok()) {
        *error = loaded.error.isEmpty() ? QStringLiteral("could not import %1").arg(modelPath) : loaded.error;
        return false;
    }
    scene->model = loaded.model;
    return true;
}

QString rigErrorLine(const RigReadResult& r, const QString& rigPath) {
    QString line = r.errors.value(0, QStringLiteral("%1: cannot read the rig").arg(rigPath));
    if (r.errorCount() > 1) line += QStringLiteral(" (and %1 more errors)").arg(r.errorCount() - 1);
    return line;
}

bool loadSceneRig(const QString& modelPath, const SceneOptions& options, LoadedScene* scene, QString* error,
                  EnvironmentLoading loading) {
    const Model& model = *scene->model;
    if (!options.rigPath.isEmpty()) {
        const RigReadResult r = readRigFile(options.rigPath);
        if (!r.ok()) {
            *error = rigErrorLine(r, options.rigPath);
            return false;
        }
        scene->rig = options.shading ? withShading(*r.rig, *options.shading) : *r.rig;
        scene->rigSource = options.rigPath;
    } else {
        DefaultRigChoice chosen =
            chooseDefaultRig(model.hasPbrMaterials(), model.lights, modelPath, options.shading);
        scene->rig = std::move(chosen.rig);
        scene->rigSource = chosen.source;
    }
    if (options.ground) scene->rig.ground.mode = *options.ground;
    if (options.shadows && !applyShadowsOption(scene->rig, *options.shadows, error)) return false;
    scene->rigSource += QStringLiteral(", %1 shading").arg(toString(scene->rig.shading.model));
    if (scene->rig.ground.mode != GroundMode::Off)
        scene->rigSource += QStringLiteral(", %1 ground").arg(toString(scene->rig.ground.mode));
    scene->rigSource += shadowSummary(scene->rig);
    applyEnvironmentOverrides(scene->rig.environment, options.environment);
    const Environment& environment = scene->rig.environment;
    const QString folder = environmentFolder(options.rigPath);
    scene->environmentLoad.reset();
    if (loading == EnvironmentLoading::AfterUpload && !environment.isNone() &&
        !(scene->environment && environmentServes(*scene->environment, environment, folder))) {
        scene->environment.reset();
        scene->environmentLoad = std::make_shared<EnvironmentLoad>(environment, folder);
    } else if (!loadCliEnvironment(environment, folder, &scene->environment, error)) {
        return false;
    }
    if (const QString env = environmentName(scene->rig.environment); !env.isEmpty())
        scene->rigSource += QStringLiteral(", ") + env;
    return true;
}

bool chooseSceneCamera(const QString& modelPath, const SceneOptions& options, LoadedScene* scene,
                       QString* error) {
    const Model& model = *scene->model;
    const double aspect = double(options.size.width()) / double(options.size.height());
    const auto fromFile = [&](int index) {
        const Camera& c = model.cameras[size_t(index)];
        const double focus = glm::dot(model.bounds.center() - c.position,
                                      lighting::safeNormalize(c.forward, glm::dvec3(0, 0, -1)));
        scene->camera = fromModelCamera(c, focus > 0.0 ? focus : model.bounds.radius());
        scene->cameraSource = QStringLiteral("camera %1 of the model").arg(index);
    };
    if (options.cameraIndex) {
        if (*options.cameraIndex >= int(model.cameras.size())) {
            *error = QStringLiteral("%1 has %2 camera(s); --camera-index %3 is out of range")
                         .arg(modelPath)
                         .arg(model.cameras.size())
                         .arg(*options.cameraIndex);
            return false;
        }
        fromFile(*options.cameraIndex);
    } else if (options.view.isEmpty() && !model.cameras.empty()) {
        fromFile(0);
    } else {
        const QString name = options.view.isEmpty() ? QStringLiteral("three-quarter") : options.view;
        scene->camera = *standardView(name, model.bounds, aspect);
        scene->cameraSource = QStringLiteral("view ") + name;
    }
    return true;
}

void showScene(Renderer& renderer, const LoadedScene& scene) {
    renderer.setRig(scene.rig);
    if (scene.environmentLoad)
        renderer.setEnvironment(scene.environmentLoad->start());
    else
        renderer.setEnvironment(scene.environment);
}

bool haveDisplay() {
    return qEnvironmentVariableIsSet("DISPLAY") || qEnvironmentVariableIsSet("WAYLAND_DISPLAY") ||
           qEnvironmentVariableIsSet("QT_QPA_PLATFORM");
}

} // namespace lr::cli
