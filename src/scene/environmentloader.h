// The rig's environment made ready for the renderer and the reference (issue 15): an image file decoded
// in the isolated import worker (untrusted input, like models), a bundled image ("builtin:NAME", trusted,
// decoded in process) or the procedural studio rendered; the rig's dimmed spots applied; then prefiltered
// (envprefilter.h). Blocking: the editor calls it on a worker thread (QtConcurrent), the command line
// directly.
#pragma once

#include "core/environment.h"

#include <QFuture>
#include <QString>
#include <QStringList>
#include <memory>

namespace lr {

struct LoadedEnvironment {
    Environment spec;       // what it was loaded for (its sameRadiance() part matters)
    QString source;         // the file as resolved ("/abs/studio.exr", "builtin:studio", "studio")
    EnvironmentImage image; // the radiance after spots, before rotation and intensity (the reference's)
    PrefilteredEnvironment prefiltered;
    QStringList warnings;       // sanitised texels, resampling, ... each naming the file
    double decodeSeconds = 0.0; // decoding (in the worker) including the round trip
};

struct EnvironmentLoadResult {
    std::shared_ptr<const LoadedEnvironment> environment; // null on failure, and for source None
    QString error; // "could not read rigs/hdr/sky.exr: <reason>" (naming the file)
};

// `rigFolder`: where a relative Environment::file is resolved (the rig file's folder; the current folder
// for a rig that was never saved).
EnvironmentLoadResult loadEnvironment(const Environment& spec, const QString& rigFolder);

// An environment to load once, when first asked for, shared by whatever shades with it (the command line's
// scenes, their renderers and the reference): start() runs loadEnvironment on the thread pool, so that the
// caller overlaps it with other work (the command line starts it after the model's upload: the renderer
// waits for it only at the first pass that samples it, Renderer::setEnvironment), and result() waits for
// it. GUI-thread object: the work is the pool's.
class EnvironmentLoad {
  public:
    EnvironmentLoad(const Environment& spec, const QString& rigFolder);
    QFuture<EnvironmentLoadResult> start(); // the first call starts it
    bool started() const { return m_future.isValid(); }
    EnvironmentLoadResult result(); // starts it when not started, and waits
    // The loaded environment when the load has finished and succeeded; null otherwise (never waits).
    std::shared_ptr<const LoadedEnvironment> loaded() const;
    const Environment& spec() const { return m_spec; }
    const QString& rigFolder() const { return m_rigFolder; }

  private:
    Environment m_spec;
    QString m_rigFolder;
    QFuture<EnvironmentLoadResult> m_future;
};

// For what holds an environment either loaded or as its load (the command line's scenes): the loaded one,
// or the load's once it has finished and succeeded; null otherwise (never waits).
std::shared_ptr<const LoadedEnvironment> loadedEnvironment(const std::shared_ptr<EnvironmentLoad>& load,
                                                           std::shared_ptr<const LoadedEnvironment> loaded);

// Whether `loaded` is what loadEnvironment(spec, rigFolder) would give: the same radiance from the same
// resolved file (intensity, rotation, background and blur are the renderer's uniforms, never loaded).
bool environmentServes(const LoadedEnvironment& loaded, const Environment& spec, const QString& rigFolder);

// Where Environment::file points: "builtin:NAME" and "" as they are, an absolute path cleaned, a relative
// one resolved against `rigFolder` (the current folder when empty).
QString resolveEnvironmentFile(const QString& file, const QString& rigFolder);

} // namespace lr
