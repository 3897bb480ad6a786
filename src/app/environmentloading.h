// Loads the document's environment in the background (issue 15): whenever the rig's environment changes in
// what needs re-filtering (Environment::sameRadiance false) or the rig file's folder changes (a relative
// image path then names another file), lr::loadEnvironment (scene/environmentloader.h; blocking: decode in
// the import worker, prefilter) runs on QtConcurrent's pool, never on the window's thread. At most one load
// runs at a time; edits made meanwhile supersede it (the newest request starts when it ends, stale results
// are dropped). A finished current load goes to the Scene, which the viewport and the snapshots render from.
// Intensity, rotation, background and blur are read from the rig at each frame: changing them only
// re-renders. A failure leaves the rig as it is and the environment undrawn, and says why (failed()).
// A new image chosen in the editor is tried first (tryEnvironment, issue 41): the rig takes it only once it
// has loaded, so a file that cannot be read leaves the rig and what is drawn as they were (refused()).
#pragma once

#include "core/environment.h"

#include <QFutureWatcher>
#include <QObject>
#include <functional>
#include <memory>
#include <optional>

namespace lr {

class Document;
class Scene;
struct EnvironmentLoadResult;
struct LoadedEnvironment;

class EnvironmentLoading : public QObject {
    Q_OBJECT
  public:
    EnvironmentLoading(Document* document, Scene* scene, QObject* parent = nullptr);
    ~EnvironmentLoading() override;

    bool isLoading() const { return m_running || m_trying; }
    QString lastError() const { return m_error; }
    // Where a relative Environment::file is resolved: the rig file's folder, the current folder when
    // untitled.
    static QString rigFolder(const Document* document);
    // Loads `spec` in the background before the rig has it: when it loads, `accept` runs (it edits the
    // rig to `spec`; the load is then shown without loading again); when it fails, refused(error) and
    // nothing changes. A newer try supersedes one that has not finished.
    void tryEnvironment(const Environment& spec, std::function<void()> accept);

  signals:
    void loadingChanged(bool loading);
    void loaded(); // the Scene has the current environment (or none)
    // "could not read hdr/sky.exr: ..." naming the file; the rig is unchanged, nothing is drawn for it.
    void failed(const QString& error);
    void warnings(const QStringList& warnings);
    // A tried environment could not be loaded (naming the file): the rig and the Scene are as they were.
    void refused(const QString& error);

  private:
    void update();
    void start();
    void finished();
    void tried();
    void launchTrial();
    void setBusy(bool running, bool trying);
    bool usePreloaded();

    Document* m_doc;
    Scene* m_scene;
    QFutureWatcher<EnvironmentLoadResult>* m_watcher;
    bool m_running = false;
    // What the Scene shows or a load is for (spec and folder); the running load's; the newest wanted.
    std::optional<std::pair<Environment, QString>> m_current, m_runningFor, m_pending;
    QString m_error;
    // The try in progress, the newest one waiting for it, and a tried load the rig is about to take.
    QFutureWatcher<EnvironmentLoadResult>* m_trialWatcher;
    bool m_trying = false;
    struct Trial {
        std::pair<Environment, QString> want;
        std::function<void()> accept;
    };
    std::optional<Trial> m_trial, m_nextTrial;
    std::optional<std::pair<std::pair<Environment, QString>, std::shared_ptr<const LoadedEnvironment>>>
        m_preloaded;
};

} // namespace lr
