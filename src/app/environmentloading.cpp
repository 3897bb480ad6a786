#include "environmentloading.h"

#include "editor/document.h"
#include "scene.h"
#include "scene/environmentloader.h"

#include <QDir>
#include <QFileInfo>
#include <QtConcurrent/QtConcurrentRun>

namespace lr {

namespace {
// The folder matters only to an image given by a relative path.
bool usesFolder(const Environment& e) {
    return e.source == EnvironmentSource::Image &&
           !e.file.startsWith(QLatin1String(kBuiltinEnvironmentPrefix)) && QFileInfo(e.file).isRelative();
}

bool sameLoad(const std::pair<Environment, QString>& a, const std::pair<Environment, QString>& b) {
    return a.first.sameRadiance(b.first) && (!usesFolder(a.first) || a.second == b.second);
}
} // namespace

EnvironmentLoading::EnvironmentLoading(Document* document, Scene* scene, QObject* parent)
    : QObject(parent), m_doc(document), m_scene(scene),
      m_watcher(new QFutureWatcher<EnvironmentLoadResult>(this)),
      m_trialWatcher(new QFutureWatcher<EnvironmentLoadResult>(this)) {
    connect(m_watcher, &QFutureWatcherBase::finished, this, &EnvironmentLoading::finished);
    connect(m_trialWatcher, &QFutureWatcherBase::finished, this, &EnvironmentLoading::tried);
    connect(m_doc, &Document::rigChanged, this, [this](const RigChange& c) {
        if (c.kind == RigChange::Reset ||
            (c.kind == RigChange::RigValues &&
             (c.rigProperty == RigProperty::Environment || c.rigProperty == RigProperty::Any)))
            update();
    });
    connect(m_doc, &Document::fileChanged, this, &EnvironmentLoading::update);
    update();
}

EnvironmentLoading::~EnvironmentLoading() {
    // The running load cannot be interrupted (loadEnvironment blocks); wait so it does not outlive us.
    m_watcher->disconnect(this);
    m_trialWatcher->disconnect(this);
    m_watcher->waitForFinished();
    m_trialWatcher->waitForFinished();
}

QString EnvironmentLoading::rigFolder(const Document* document) {
    return document->filePath().isEmpty() ? QDir::currentPath()
                                          : QFileInfo(document->filePath()).absolutePath();
}

void EnvironmentLoading::update() {
    const Environment& spec = m_doc->rig().environment;
    std::pair<Environment, QString> want{spec, rigFolder(m_doc)};
    if (spec.isNone()) { // nothing to load: drop what is shown and whatever was wanted
        m_pending.reset();
        m_current = want;
        m_error.clear();
        m_scene->setEnvironment(nullptr);
        if (!m_running) emit loaded();
        return;
    }
    if (m_running) { // the running load is for it, or it waits for that one to end
        if (sameLoad(*m_runningFor, want))
            m_pending.reset();
        else
            m_pending = std::move(want);
        return;
    }
    if (m_current && sameLoad(*m_current, want)) return; // shown already (or failed already)
    m_pending = std::move(want);
    if (usePreloaded()) {
        emit loaded();
        return;
    }
    start();
}

bool EnvironmentLoading::usePreloaded() {
    auto preloaded = std::exchange(m_preloaded, std::nullopt);
    if (!preloaded || !m_pending || !sameLoad(preloaded->first, *m_pending)) return false;
    m_current = std::exchange(m_pending, std::nullopt);
    m_error.clear();
    m_scene->setEnvironment(preloaded->second);
    if (!preloaded->second->warnings.isEmpty()) emit warnings(preloaded->second->warnings);
    return true;
}

void EnvironmentLoading::setBusy(bool running, bool trying) {
    const bool was = isLoading();
    m_running = running;
    m_trying = trying;
    if (isLoading() != was) emit loadingChanged(isLoading());
}

void EnvironmentLoading::start() {
    m_runningFor = std::exchange(m_pending, std::nullopt);
    m_current = m_runningFor;
    const auto [spec, folder] = *m_runningFor;
    m_watcher->setFuture(QtConcurrent::run([spec, folder] { return loadEnvironment(spec, folder); }));
    setBusy(true, m_trying);
}

void EnvironmentLoading::tryEnvironment(const Environment& spec, std::function<void()> accept) {
    Trial trial{{spec, rigFolder(m_doc)}, std::move(accept)};
    if (m_trying) { // the newest try waits for the running one to end (which is then dropped)
        m_nextTrial = std::move(trial);
        return;
    }
    m_trial = std::move(trial);
    launchTrial();
    setBusy(m_running, true);
}

void EnvironmentLoading::launchTrial() {
    const auto [spec, folder] = m_trial->want;
    m_trialWatcher->setFuture(QtConcurrent::run([spec, folder] { return loadEnvironment(spec, folder); }));
}

void EnvironmentLoading::tried() {
    const EnvironmentLoadResult result = m_trialWatcher->result();
    std::optional<Trial> trial = std::exchange(m_trial, std::nullopt);
    if (m_nextTrial) { // superseded: the newest try starts, this result is dropped
        m_trial = std::exchange(m_nextTrial, std::nullopt);
        launchTrial();
        return;
    }
    setBusy(m_running, false);
    if (!trial) return;
    if (!result.environment) {
        emit refused(result.error.isEmpty() ? tr("could not load the environment") : result.error);
        emit loaded();
        return;
    }
    m_preloaded.emplace(trial->want, result.environment);
    trial->accept(); // edits the rig: update() (or the running load's end) takes the preloaded environment
}

void EnvironmentLoading::finished() {
    const EnvironmentLoadResult result = m_watcher->result();
    const auto loadedFor = std::exchange(m_runningFor, std::nullopt);
    if (m_pending) { // superseded: the newer request starts, this result is dropped
        if (!usePreloaded()) {
            start();
            return;
        }
    }
    // Still what the rig wants (a change back to None meanwhile cleared m_current's spec)?
    const std::pair<Environment, QString> now{m_doc->rig().environment, rigFolder(m_doc)};
    if (loadedFor && !now.first.isNone() && sameLoad(*loadedFor, now)) {
        m_current = loadedFor;
        if (result.environment) {
            m_error.clear();
            m_scene->setEnvironment(result.environment);
            if (!result.environment->warnings.isEmpty()) emit warnings(result.environment->warnings);
        } else {
            m_error = result.error.isEmpty() ? tr("could not load the environment") : result.error;
            m_scene->setEnvironment(nullptr);
        }
    }
    // Not loading any more before the error is said (an error box must not stand over "Loading…").
    setBusy(false, m_trying);
    emit loaded();
    if (loadedFor && !m_error.isEmpty() && sameLoad(*loadedFor, now)) emit failed(m_error);
}

} // namespace lr
