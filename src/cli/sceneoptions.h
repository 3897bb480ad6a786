// The scene options shared by `lightrig render` and `lightrig bench`: which model, rig, camera, size,
// quality, exposure and tone map; and loading the scene they describe (model, rig, camera).
//   --rig RIG.json        without it: core/defaultrig.h's rule (physically based materials: PBR shading with
//                         the model's own lights, else the PBR default rig; otherwise classic shading with
//                         the model's own lights, else the default rig)
//   --shading classic|pbr overrides the shading of whichever rig is used
//   --ground off|visible|catcher   overrides the ground of whichever rig is used (issue 14)
//   --shadows on|off      every light that can cast casts its shadow (at most kMaxShadowCasters), or none
//   --environment FILE|builtin:NAME|studio|none, --environment-intensity EV, --environment-rotation DEG,
//   --environment-background visible|blurred|color   override the rig's environment (environmentoption.h)
//   --camera-index N | --view NAME   default: the model's camera 0, else "three-quarter" framing all
//   --size WxH (1280x720) --quality Q --exposure EV --tonemap clamp|reinhard|aces
#pragma once

#include "environmentoption.h"

#include "core/quality.h"
#include "core/rig.h"
#include "core/rigjson.h"
#include "model/model.h"
#include "render/renderer.h"
#include "scene/camera.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QSize>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

namespace lr::cli {

struct SceneOptions {
    QString rigPath; // empty: model lights or the default rig
    std::optional<int> cameraIndex;
    QString view; // a standardViewNames() name, or empty
    // --view as a list (render: several views per call; read with viewList): standard view names and
    // model cameras "cameraN" (or "N"), in order, without repeats. One entry also sets view or cameraIndex.
    QStringList views;
    QSize size{1280, 720};
    Quality quality = Quality::Exact;               // the first of `qualities`
    std::vector<Quality> qualities{Quality::Exact}; // --quality A,B,... where a list is allowed (bench)
    bool pathTraced = false; // --quality path (render only: src/trace, not a raster tier)
    double exposureEV = 0.0;
    ToneMap toneMap = ToneMap::Clamp;
    std::optional<ShadingModel> shading; // --shading; unset: the rig's own (or the default rule's)
    std::optional<GroundMode> ground;    // --ground; unset: the rig's own
    std::optional<bool> shadows;         // --shadows on|off; unset: the rig's own
    EnvironmentOverrides environment;    // --environment...; unset: the rig's own
};

struct SceneOptionSet {
    QCommandLineOption rig, cameraIndex, view, size, quality, exposure, toneMap, shading, ground, shadows;
    EnvironmentOptionSet environment;
    SceneOptionSet();
    void addTo(QCommandLineParser& parser) const;
    // The parsed values, or a usage error message (exit 2). qualityList: --quality takes a comma list;
    // viewList: --view takes comma lists and may repeat (SceneOptions::views); pathQuality: --quality path
    // is allowed (SceneOptions::pathTraced; with qualityList, "path" may be one of the list, and
    // `qualities` may then be empty).
    std::optional<SceneOptions> read(const QCommandLineParser& parser, QString* usageError,
                                     bool qualityList = false, bool viewList = false,
                                     bool pathQuality = false) const;
};

struct LoadedScene {
    std::shared_ptr<Model> model;
    Rig rig;
    // "RIG.json", "the model's lights", "the default rig" or "the physically based default rig", and the
    // shading: "the model's lights, pbr shading", the ground when there is one and the shadows when some
    // light casts, and the environment: "RIG.json, classic shading, catcher ground, shadows from 2 lights,
    // studio environment"
    QString rigSource;
    // The rig's environment (after the --environment options) decoded and prefiltered; null for none
    // and while it is to be loaded later (environmentLoad). showScene hands it to the renderer.
    std::shared_ptr<const LoadedEnvironment> environment;
    // With EnvironmentLoading::AfterUpload: the environment still to be loaded (null when it is loaded
    // already, or none). showScene starts it, so that it loads while the first frame's first passes run.
    std::shared_ptr<EnvironmentLoad> environmentLoad;
    ViewCamera camera;
    QString cameraSource; // "camera 0 of the model", "view three-quarter"
};

// --shadows on|off applied to a rig: on switches on the shadow of every light whose type casts one (its
// other shadow values kept), off switches every shadow off. False with the reason when on would make more
// than kMaxShadowCasters casters (the rig is left as it was).
bool applyShadowsOption(Rig& rig, bool on, QString* error);
// ", shadows from N lights" when some light casts, else empty: for the summary lines.
QString shadowSummary(const Rig& rig);

// When loadSceneRig loads the rig's environment: at once (its errors are then the rig's), or after the
// model's upload, by showScene (its errors are then the first frame's): `render` and `bench`, whose first
// frame then draws its G-pass while the environment is decoded and prefiltered (docs/performance.md).
enum class EnvironmentLoading { Now, AfterUpload };

// Loads the model, the rig and its environment and picks the camera. False with a one-line reason (exit 1) on
// failure.
bool loadScene(const QString& modelPath, const SceneOptions& options, LoadedScene* scene, QString* error,
               EnvironmentLoading loading = EnvironmentLoading::Now);
// loadScene's three steps, for `render` with several rigs and views per model (src/cli/catalog.h): the
// model (scene->model), then the rig and its environment (rigSource, environment), then the camera of
// options.view / options.cameraIndex (camera, cameraSource). Each false with a one-line reason.
bool loadSceneModel(const QString& modelPath, LoadedScene* scene, QString* error);
bool loadSceneRig(const QString& modelPath, const SceneOptions& options, LoadedScene* scene, QString* error,
                  EnvironmentLoading loading = EnvironmentLoading::Now);
bool chooseSceneCamera(const QString& modelPath, const SceneOptions& options, LoadedScene* scene,
                       QString* error);
// "cameraN" or "N" -> N; nullopt for anything else (a --view list entry naming a model camera).
std::optional<int> viewCameraIndex(const QString& view);

// A rig that does not read, in one line: its first error and "(and N more errors)", N counting the errors
// not listed too (issue 41: 16,384 errors read "(and 200 more errors)").
QString rigErrorLine(const RigReadResult& result, const QString& rigPath);

// Gives the renderer the scene's rig and its environment (Renderer::setRig, setEnvironment): the loaded
// one, or its load (environmentLoad), started here when it was not.
void showScene(Renderer& renderer, const LoadedScene& scene);

// "WxH" with both sides in 1..maxSide.
// *why (when given) tells a side past maxSide ("the width 1234567890 is larger than the limit 32768")
// from text that is not WxH at all.
std::optional<QSize> parseSize(const QString& text, int maxSide = 32768, QString* why = nullptr);

// DISPLAY, WAYLAND_DISPLAY or an explicit QT_QPA_PLATFORM: a platform that may offer OpenGL.
bool haveDisplay();

} // namespace lr::cli
