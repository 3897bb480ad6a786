// Path-traced pictures of the editor's scene off the GUI thread (issue 36): what the viewport's traced view
// (tracedview.h) and a path-traced screenshot (screenshotjob.h) share. TracedInputs fixes the scene as it
// is drawn now (model, rig with solo applied, environment, camera, view settings); TracedShot builds the
// traced scene and renders a number of samples per pixel on the calling thread (a worker), with progress
// and a cancel that returns within one tile (or after the scene build, which cannot be stopped).
#pragma once

#include "scene/camera.h"
#include "viewsettings.h"

#include "core/rig.h"

#include <QImage>
#include <QMutex>
#include <atomic>
#include <memory>

namespace lr {

struct LoadedEnvironment;
struct Model;

namespace trace {
class PathTracer;
class TraceScene;
struct TraceSettings;
} // namespace trace

struct TracedInputs {
    std::shared_ptr<const Model> model;
    Rig rig;
    std::shared_ptr<const LoadedEnvironment> environment;
    ViewCamera camera;
    ViewOptions options;
};

// The tracer's display image (exposure and tone map of `options`): transparent where no environment is
// seen and `transparent` asks for it, else laid over the view's background colour, untouched by exposure
// and tone map as the raster's background is.
QImage tracedDisplay(const trace::PathTracer& tracer, const ViewOptions& options, bool transparent);
// The tracer's settings for the view's options: the background colour (linear) and, where no environment
// is seen, escaped rays to alpha so that tracedDisplay lays the image over that colour.
trace::TraceSettings viewTraceSettings(const ViewOptions& options, const trace::TraceScene& scene);

class TracedShot {
  public:
    TracedShot(TracedInputs inputs, QSize size, int samples, bool transparent);
    ~TracedShot();

    // Blocking (call it on a worker): the image, or null with *error ("cancelled" when cancel() stopped it).
    QImage render(QString* error);
    void cancel(); // any thread
    int samplesDone() const { return m_done.load(); }
    int samples() const { return m_samples; }

  private:
    TracedInputs m_inputs;
    QSize m_size;
    int m_samples;
    bool m_transparent;
    std::atomic<bool> m_cancelled{false};
    std::atomic<int> m_done{0};
    QMutex m_lock; // guards m_tracer's creation against cancel()
    std::unique_ptr<trace::PathTracer> m_tracer;
};

} // namespace lr
