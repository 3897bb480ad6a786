#include "filewatch.h"

#include "core/rigjson.h"
#include "editor/document.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QUndoStack>

namespace lr {

namespace {
QString absolute(const QString& path) {
    if (path.isEmpty() || path.startsWith(QLatin1String(":/"))) return {}; // untitled or a built-in preset
    return QFileInfo(path).absoluteFilePath();
}
} // namespace

RigFileWatch::RigFileWatch(Document* document, QObject* parent) : QObject(parent), m_doc(document) {
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(300); // editors write in several steps; look once they are done
    connect(&m_debounce, &QTimer::timeout, this, &RigFileWatch::checkNow);
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, [this] { m_debounce.start(); });
    connect(&m_watcher, &QFileSystemWatcher::directoryChanged, this, [this] { m_debounce.start(); });
    connect(m_doc, &Document::fileChanged, this, &RigFileWatch::follow);
    // A load of the same path again (reload, File > Open of the open file) emits no fileChanged: a fresh
    // document (reset, nothing to undo, clean) means the file was just read.
    connect(m_doc, &Document::rigChanged, this, [this](const RigChange& change) {
        if (change.kind == RigChange::Reset && m_doc->undoStack()->count() == 0 && !m_doc->isModified())
            resetBaseline();
    });
    // After a save the file holds exactly what the editor writes for the current rig.
    connect(m_doc, &Document::modifiedChanged, this, [this](bool modified) {
        if (modified || m_path.isEmpty()) return;
        const Fingerprint f = readFingerprint(m_path);
        if (isOurs(f)) m_baseline = f;
    });
    follow(m_doc->filePath());
}

RigFileWatch::Fingerprint RigFileWatch::fingerprintOf(const QByteArray& data) {
    return {data.size(), QCryptographicHash::hash(data, QCryptographicHash::Sha256)};
}

RigFileWatch::Fingerprint RigFileWatch::readFingerprint(const QString& path, QByteArray* data) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    const QByteArray bytes = file.read(kMaxRigFileBytes + 1);
    if (data) *data = bytes;
    return fingerprintOf(bytes);
}

bool RigFileWatch::isOurs(const Fingerprint& f) const {
    return f.size >= 0 && f == fingerprintOf(writeRigJson(m_doc->rig()));
}

void RigFileWatch::follow(const QString& path) {
    const QString p = absolute(path);
    if (!m_watcher.files().isEmpty()) m_watcher.removePaths(m_watcher.files());
    if (!m_watcher.directories().isEmpty()) m_watcher.removePaths(m_watcher.directories());
    m_path = p;
    resetBaseline();
    rewatch();
}

void RigFileWatch::resetBaseline() {
    m_baseline = m_path.isEmpty() ? Fingerprint{} : readFingerprint(m_path);
}

void RigFileWatch::rewatch() {
    if (m_path.isEmpty()) return;
    // A file replaced by rename drops out of the watcher; watch it again, and its folder to see it return.
    if (QFile::exists(m_path) && !m_watcher.files().contains(m_path)) m_watcher.addPath(m_path);
    const QString dir = QFileInfo(m_path).absolutePath();
    if (!m_watcher.directories().contains(dir)) m_watcher.addPath(dir);
}

void RigFileWatch::checkNow() {
    if (m_path.isEmpty() || m_asking) return;
    rewatch();
    const Fingerprint now = readFingerprint(m_path);
    if (now == m_baseline) return;
    if (now.size < 0) {
        m_baseline = now;
        if (notify)
            notify(tr("%1 was deleted or renamed on disk. The rig is still open; save it to write the file "
                      "again.")
                       .arg(QDir::toNativeSeparators(m_path)));
        return;
    }
    if (isOurs(now)) { // our own save, or someone wrote exactly this rig
        m_baseline = now;
        return;
    }
    emit changedOnDisk(m_path);
    const bool modified = m_doc->isModified();
    m_asking = true;
    const ChangedAnswer answer = askChanged ? askChanged(m_path, modified)
                                            : (modified ? ChangedAnswer::KeepMine : ChangedAnswer::Reload);
    m_asking = false;
    if (answer == ChangedAnswer::Reload) {
        const QString path = m_path;
        const QString error = m_doc->load(path);
        if (error.isEmpty()) {
            resetBaseline();
            emit reloaded(path);
        } else {
            m_baseline = now; // seen; the rig stays as it was
            if (notify)
                notify(tr("Could not reload %1; the rig is unchanged.\n%2")
                           .arg(QDir::toNativeSeparators(path), error));
        }
    } else {
        m_baseline = now; // acknowledged: the next save overwrites it without asking again
    }
    // The file may have changed again while the question was open.
    if (readFingerprint(m_path) != m_baseline) m_debounce.start();
}

bool RigFileWatch::confirmSave(const QString& path) {
    if (m_path.isEmpty() || absolute(path) != m_path) return true;
    const Fingerprint now = readFingerprint(m_path);
    if (now == m_baseline || now.size < 0 || isOurs(now)) return true;
    m_asking = true;
    const bool overwrite = askOverwrite && askOverwrite(m_path);
    m_asking = false;
    if (overwrite) m_baseline = now;
    return overwrite;
}

} // namespace lr
