#include "environmentloading.h"

#include "editor/document.h"
#include "render/environmentloader.h"
#include "scene.h"

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
      m_watcher(new QFutureWatcher<EnvironmentLoadResult>(this)) {
    connect(m_watcher, &QFutureWatcherBase::finished, this, &EnvironmentLoading::finished);
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
    m_watcher->waitForFinished();
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
    start();
}

void EnvironmentLoading::start() {
    m_runningFor = std::exchange(m_pending, std::nullopt);
    m_current = m_runningFor;
    const bool was = m_running;
    m_running = true;
    const auto [spec, folder] = *m_runningFor;
    m_watcher->setFuture(QtConcurrent::run([spec, folder] { return loadEnvironment(spec, folder); }));
    if (!was) emit loadingChanged(true);
}

void EnvironmentLoading::finished() {
    const EnvironmentLoadResult result = m_watcher->result();
    const auto loadedFor = std::exchange(m_runningFor, std::nullopt);
    if (m_pending) { // superseded: the newer request starts, this result is dropped
        start();
        return;
    }
    m_running = false;
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
            emit failed(m_error);
        }
    }
    emit loadingChanged(false);
    emit loaded();
}

} // namespace lr
