// The speed/accuracy measurement behind `lightrig bench` and the editor's Quality panel: for each scene
// and quality tier, frame times (wall time with glFinish and GPU timer queries), the first frame (model
// load + upload + shader compile + draw), the shader variants compiled, and the error of the tier's 8-bit
// output against the double-precision reference (reference.h). Optionally the same scene once more with
// the über-shader (every light model compiled in) to show what specialising the shaders saves.
//
// Method (docs/quality.md):
// - each scene × tier runs in a fresh OffscreenRenderer (own context), so its first frame pays the upload
//   and the compile of its own variants; warm-up frames follow, then the timed frames;
// - timings use the tier's own settings (MSAA 4 for exact and balanced, none for fast);
// - errors are measured on a single-sample render of the tier (MSAA only changes silhouette pixels, which
//   the single-sample G-buffer reference cannot represent), over the pixels the model covers;
// - NaN/Inf pixels are counted in the tier's float radiance (RGBA32F) read back from the same view;
// - with shadow casters in the rig, the same single-sample image also gets the shadow measure
//   (compareShadows: share of pixels off the traced visibility outside the penumbra band, mean error);
// - with an environment (BenchScene::environment and the rig's environment block), every renderer shades
//   with it and the reference integrates it, so each tier's error includes the environment's; the
//   reference's own convergence (share of pixels whose estimated error exceeds half a level) is reported;
// - with area lights (rect, disk) the reference integrates them by Monte Carlo (core/areaintegrate.h), and
//   its convergence is reported the same way.
//
// Runs on the calling (GUI) thread; the reference evaluation uses the global thread pool meanwhile.
#pragma once

#include "core/imagecompare.h"
#include "core/quality.h"
#include "core/rig.h"
#include "model/model.h"
#include "render/approximations.h"
#include "render/reference.h"
#include "scene/camera.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace lr {

struct BenchScene {
    QString name; // "helmet_8pt", "Suzanne · 8 point"
    std::shared_ptr<const Model> model;
    double loadMs = 0.0; // importing the model file (counted in each first frame)
    Rig rig;
    ViewCamera camera;
    // The rig's environment loaded (environmentloader.h), or its load (shared by the scenes of one model):
    // every renderer of the run shades with it and the reference integrates it (when rig.environment is
    // not None). A load not yet started starts after the first run's upload, as `render` does, so that
    // run's first frame includes it (BenchResult::environmentConcurrent).
    std::shared_ptr<const LoadedEnvironment> environment;
    std::shared_ptr<EnvironmentLoad> environmentLoad;
};

struct BenchOptions {
    QSize size{1280, 720};
    int warmupFrames = 5;
    int frames = 60;
    std::vector<Quality> tiers{Quality::Exact, Quality::Balanced, Quality::Fast};
    double exposureEV = 0.0;
    ToneMap toneMap = ToneMap::Clamp;
    bool errors = true; // compute the reference and the error figures
    // A scene whose reference would cost more (benchestimate.h benchReferenceWork: light·pixels, area
    // lights weighted) gets none, and no error figures: a note in BenchReport::notes says so. The default
    // (~2 minutes on llvmpipe's 2-core host) admits the standard suite; 65,535 point lights at 1280x720
    // (6e10, ~15 minutes) are over it.
    double maxReferenceWork = 1e10;
    bool uberShader = true;   // one more run per scene: the exact tier with every light model compiled in
    int msaaSamples = -1;     // timed runs: -1 each tier's own (tierMsaaSamples), else this for every tier
    bool interactive = false; // time what the viewport draws while navigating (interaction proxies, lod.h)
    // Degrees the camera orbits the model between timed frames (turntable.h orbitCamera): nothing kept for
    // a still view (the G-buffer, the background) helps then, as while the user orbits. 0: a still camera,
    // as while a light is dragged.
    double orbitDegrees = 0.0;
    // The rig's first light moves between timed frames (±1 % of the model's radius along x, or its
    // direction as much for a directional light), as while the user drags it: its shadow map, if it casts,
    // is rendered again every frame, the other lights' maps are kept.
    bool dragLight = false;
    // Every frame of every raster tier (the timed ones and the image the errors are of) drawn at this
    // fraction of --size and stretched to it (RenderSettings::renderScale): the editor's moving frame.
    double renderScale = 1.0;
    bool keepImages = false; // with errors: keep each tier's image and the reference (BenchResult::image)
    std::uint8_t approximations = render::approx::kDefault; // the tiers' approximations (approximations.h)
};

// MSAA samples a tier renders with (exact, balanced: 4; fast: none).
int tierMsaaSamples(Quality quality);

struct BenchResult {
    QString scene;
    Quality quality = Quality::Exact;
    bool uberShader = false;
    QSize size;
    int msaaSamples = 0;
    int lightsInRig = 0, lightsUploaded = 0;
    qint64 triangles = 0;
    qint64 trianglesDrawn = 0; // per frame: fewer than triangles when an interaction proxy was drawn
    int variants = 0;          // shader variants compiled for this scene and tier (fresh renderer)
    double msMedian = 0.0, msMin = 0.0, msMax = 0.0; // wall time per frame with glFinish
    double gpuMsMedian = -1.0;                       // GL_TIME_ELAPSED; < 0: no timer results
    // Process CPU time per frame, all threads: llvmpipe renders on the CPU, and this is far less
    // sensitive than wall time to other processes on a shared machine.
    double cpuMsMedian = 0.0;
    double firstFrameMs = 0.0; // loadMs + firstDrawMs
    double loadMs = 0.0;
    double firstDrawMs = 0.0; // upload + compile + draw + glFinish in a fresh context
    // The frame after it (the first warm-up frame): a shader compiled again there, because the first
    // frame's later passes changed a state its programs were compiled for, is a stall the median hides.
    double secondFrameMs = 0.0;
    double uploadMs = 0.0; // of which the model upload (buffers, textures and their mipmaps)
    // The scene's environment (LoadedEnvironment): its decoding (in the import worker, with the round
    // trip) and prefiltering; < 0: no environment. environmentConcurrent: it loaded during this run's
    // first frame (BenchScene::environmentLoad, started after the upload), so firstDrawMs includes it;
    // otherwise it was loaded before and a first frame with it waits for it on top of firstDrawMs.
    double environmentDecodeMs = -1.0, environmentPrefilterMs = -1.0;
    bool environmentConcurrent = false;
    int keptFrames = 0; // timed frames that kept the G-buffer of the one before (RenderStats::gbufferKept)
    int shadowMapsRendered = 0; // over the timed frames (RenderStats::shadowMapsRendered)
    bool hasErrors = false;
    ErrorFigures errors; // against the double reference (nonFinite from the float radiance)
    // With errors, when the rig has shadow casters: the shadow measure (reference.h, compareShadows).
    bool hasShadowErrors = false;
    ShadowFigures shadow;
    // With errors, when the reference integrated an environment: its convergence (reference.h), the
    // environment's source and the scene's reference wall time (the same for every tier of the scene).
    bool hasEnvironment = false;
    EnvironmentConvergence environment;
    QString environmentSource;
    // With errors, when the rig has area lights (issue 16): the reference's Monte Carlo convergence for
    // them (reference.h areaConvergence: pixels whose estimated error exceeds half a level, the worst).
    bool hasArea = false;
    EnvironmentConvergence area;
    double referenceMs = 0.0;
    double speedUp = 0.0;    // exact's ms_median / this ms_median for the same scene (0: no exact run)
    double cpuSpeedUp = 0.0; // the same ratio of cpu_ms_median (steadier on a shared machine)
    // BenchOptions::keepImages: the single-sample 8-bit image the errors were measured on, and the
    // reference's (sRGB, RGBA8888); null otherwise.
    QImage image, reference;
    std::vector<std::uint8_t> covered; // with keepImages: the pixels the errors compare (reference.h)
    // With the path tier (tracebench.h): the same image against the converged path-traced image, over
    // the same pixels: what the tier misses of the whole light transport, not only of the direct light.
    bool hasTracedErrors = false;
    ErrorFigures tracedErrors;
};

// The path tier of one scene (tracebench.h): its image after a number of samples against its converged
// image.
struct PathBenchStep {
    int samples = 0;
    double seconds = 0.0; // since the first sample (wall)
    double noise = 0.0;   // PathTracer::noiseEstimate (+infinity under 2 samples)
    ErrorFigures errors;  // against the converged image, every pixel
};

struct PathBenchResult {
    QString scene;
    QSize size;
    int threads = 0, bounces = 0;
    qint64 triangles = 0;
    double buildMs = 0.0; // the traced scene (Embree BVH, textures, environment distribution)
    int convergedSamples = 0;
    double convergedSeconds = 0.0;
    double convergedNoise = 0.0;
    std::vector<PathBenchStep> steps;
    double secondsPerSample = 0.0; // the ladder's last step: wall seconds / samples per pixel
    double samplesPerSecond = 0.0; // samples per pixel per second (its inverse)
    double secondsTo30Db = -1.0;   // the first step within 30 dB of the converged image; < 0: none
    QString error;                 // the scene could not be traced (e.g. classic shading): why
};

struct BenchReport {
    QString glDescription; // "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 core"
    BenchOptions options;
    std::vector<BenchResult> results;
    double referenceMs = 0.0; // total CPU time of the references (wall)
    QString loadAverage;      // /proc/loadavg at the end of the run (empty where unavailable)
    QString glibcTunables;    // GLIBC_TUNABLES the run had: malloc on huge pages or not (core/hugepages.h)
    QStringList notes;        // what the run left out and why (a reference over maxReferenceWork)
    std::vector<PathBenchResult> path; // the path tier per scene (tracebench.h), when asked for
};

// Where and how much a tier's image differs from the reference: each pixel the largest channel difference
// in 8-bit levels times `gain` (clamped), as a heat map from black (identical) through red to yellow/white.
// Images of different sizes (or null ones) give a null image.
QImage benchDifferenceImage(const QImage& image, const QImage& reference, int gain = 16);

// Called now and then with the fraction done and what is being measured; return false to cancel.
using BenchProgress = std::function<bool(double fraction, const QString& what)>;

enum class BenchStatus { Ok, Failed, Cancelled };

// Needs a QGuiApplication whose platform offers OpenGL. Results are appended to report->results in the
// order scene × (tiers..., über-shader).
BenchStatus runQualityBench(const std::vector<BenchScene>& scenes, const BenchOptions& options,
                            BenchReport* report, QString* error, const BenchProgress& progress = {});

} // namespace lr
