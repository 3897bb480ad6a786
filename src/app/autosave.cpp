#include "autosave.h"

#include "core/atomicwrite.h"
#include "core/rigjson.h"
#include "editor/document.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QUndoStack>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <utility>

namespace lr {

namespace {

const QString kLockSuffix = QStringLiteral(".lock");
const QString kRigSuffix = QStringLiteral(".rig.json");
const QString kMetaSuffix = QStringLiteral(".meta.json");

// A lock that only counts as stale when its process is gone: QLockFile's default also calls a lock stale
// after 30 s without a touch, which would let a second editor take a live session's autosave.
std::unique_ptr<QLockFile> makeLock(const QString& path) {
    auto lock = std::make_unique<QLockFile>(path);
    lock->setStaleLockTime(0);
    return lock;
}

QString newSessionId() {
    return QStringLiteral("session-%1-%2")
        .arg(QCoreApplication::applicationPid())
        .arg(QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMddThhmmsszzz")));
}

} // namespace

QString Autosave::defaultDir() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave");
}

Autosave::Autosave(Document* document, const QString& dir, QObject* parent)
    : QObject(parent), m_doc(document), m_dir(QDir::cleanPath(dir)), m_id(newSessionId()) {
    QDir().mkpath(m_dir);
    m_lock = makeLock(QDir(m_dir).filePath(m_id + kLockSuffix));
    if (!m_lock->tryLock(0))
        m_lastError =
            tr("cannot lock %1 (error %2): autosaves of this session may be offered to another editor")
                .arg(QDir(m_dir).filePath(m_id + kLockSuffix))
                .arg(int(m_lock->error()));
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &Autosave::saveInBackground);
    connect(&m_writing, &QFutureWatcher<QString>::finished, this, [this] {
        if (!std::exchange(m_inFlight, false)) return; // already handled by waitForWrite()
        finishWrite(m_writing.result());
        if (std::exchange(m_writeAgain, false)) saveInBackground();
    });
    connect(m_doc, &Document::rigChanged, this, &Autosave::schedule);
    connect(m_doc->undoStack(), &QUndoStack::indexChanged, this, &Autosave::schedule);
    connect(m_doc, &Document::modifiedChanged, this, &Autosave::onModifiedChanged);
    connect(m_doc, &Document::fileChanged, this, [this] {
        if (!m_doc->isModified()) discard();
    });
    if (m_doc->isModified()) schedule();
}

Autosave::~Autosave() {
    discard();
    m_lock.reset(); // unlocks: removes ID.lock
}

QString Autosave::rigPath() const {
    return QDir(m_dir).filePath(m_id + kRigSuffix);
}
QString Autosave::metaPath() const {
    return QDir(m_dir).filePath(m_id + kMetaSuffix);
}

void Autosave::schedule() {
    if (!m_doc->isModified()) {
        // Undo back to the saved state (or a fresh load): nothing unsaved is left to protect.
        m_timer.stop();
        discard();
        return;
    }
    // Debounced: each change restarts the delay, but a stream of changes (a long slider drag) still gets
    // saved after m_maxDelayMs.
    if (!m_timer.isActive()) m_pendingSince.start();
    const qint64 waited = m_pendingSince.elapsed();
    m_timer.start(int(std::clamp<qint64>(std::min<qint64>(m_delayMs, m_maxDelayMs - waited), 0, m_delayMs)));
}

void Autosave::onModifiedChanged(bool modified) {
    if (modified)
        schedule();
    else {
        m_timer.stop();
        discard();
    }
}

namespace {
// The rig first, then the sidecar: a sidecar never points at a missing or older rig, and a rig without a
// sidecar is still offered (without its original path). Runs on a worker thread: only copies are used.
QString writeAutosave(const Rig& rig, const QString& original, const QString& rigPath,
                      const QString& metaPath) {
    QString error;
    if (!saveRigFile(rig, rigPath, &error)) return error;
    QJsonObject meta;
    meta.insert(QStringLiteral("original"), original);
    meta.insert(QStringLiteral("saved"), QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    meta.insert(QStringLiteral("name"), rig.name);
    meta.insert(QStringLiteral("lights"), qint64(rig.lights.size()));
    error = writeFileAtomically(metaPath, QJsonDocument(meta).toJson());
    if (!error.isEmpty()) return QStringLiteral("%1: not saved: %2").arg(metaPath, error);
    return {};
}
} // namespace

void Autosave::finishWrite(const QString& error) {
    m_lastError = error;
    if (error.isEmpty())
        emit saved(rigPath());
    else
        emit failed(error);
}

bool Autosave::saveNow() {
    m_timer.stop();
    waitForWrite();
    if (!m_doc->isModified()) {
        discard();
        return true;
    }
    finishWrite(writeAutosave(m_doc->rig(), m_doc->filePath(), rigPath(), metaPath()));
    return m_lastError.isEmpty();
}

void Autosave::saveInBackground() {
    if (!m_doc->isModified()) {
        discard();
        return;
    }
    if (m_inFlight) { // one write at a time; the newest state follows when it is done
        m_writeAgain = true;
        return;
    }
    // A 4096-light rig takes a few hundred milliseconds to write and check: not on the GUI thread.
    m_inFlight = true;
    m_writing.setFuture(
        QtConcurrent::run(writeAutosave, m_doc->rig(), m_doc->filePath(), rigPath(), metaPath()));
}

void Autosave::waitForWrite() {
    if (!m_inFlight) return;
    m_writing.waitForFinished();
    m_inFlight = false; // the watcher's queued finished() is ignored
    m_writeAgain = false;
    finishWrite(m_writing.result());
}

void Autosave::discard() {
    waitForWrite(); // a write in flight must not recreate the files after they are removed
    const bool had = QFile::exists(rigPath()) || QFile::exists(metaPath());
    QFile::remove(metaPath());
    QFile::remove(rigPath());
    if (had) emit discarded();
}

std::vector<RecoveredAutosave> Autosave::findRecoverable(const QString& dirPath) {
    std::vector<RecoveredAutosave> out;
    const QDir dir(dirPath);
    if (!dir.exists()) return out;
    QStringList ids;
    for (const QString& f :
         dir.entryList({QLatin1Char('*') + kRigSuffix, QLatin1Char('*') + kLockSuffix}, QDir::Files))
        ids << (f.endsWith(kRigSuffix) ? f.chopped(kRigSuffix.size()) : f.chopped(kLockSuffix.size()));
    ids.removeDuplicates();
    for (const QString& id : ids) {
        std::shared_ptr<QLockFile> lock = makeLock(dir.filePath(id + kLockSuffix));
        if (!lock->tryLock(0)) continue; // a running editor's (or one we may not touch)
        RecoveredAutosave a;
        a.id = id;
        a.rigPath = dir.filePath(id + kRigSuffix);
        a.metaPath = dir.filePath(id + kMetaSuffix);
        a.lock = lock;
        if (!QFile::exists(a.rigPath)) { // a crash before the first autosave: only the lock was left
            remove(a);
            continue;
        }
        QFile metaFile(a.metaPath);
        if (metaFile.open(QIODevice::ReadOnly) && metaFile.size() < 64 * 1024) {
            const QJsonObject meta = QJsonDocument::fromJson(metaFile.readAll()).object();
            a.originalPath = meta.value(QStringLiteral("original")).toString();
            a.saved =
                QDateTime::fromString(meta.value(QStringLiteral("saved")).toString(), Qt::ISODateWithMs);
            a.rigName = meta.value(QStringLiteral("name")).toString();
        }
        if (!a.saved.isValid()) a.saved = QFileInfo(a.rigPath).lastModified().toUTC();
        out.push_back(std::move(a));
    }
    std::sort(out.begin(), out.end(),
              [](const RecoveredAutosave& x, const RecoveredAutosave& y) { return x.saved > y.saved; });
    return out;
}

QString Autosave::restore(Document* document, const RecoveredAutosave& autosave, QString* note) {
    const RigReadResult recovered = readRigFile(autosave.rigPath);
    if (!recovered.ok()) return recovered.errors.join(QLatin1Char('\n'));
    bool base = false;
    if (!autosave.originalPath.isEmpty()) {
        const QString error = document->load(autosave.originalPath);
        base = error.isEmpty();
        if (!base && note)
            *note = tr("%1 could not be opened, so the recovered rig is untitled: %2")
                        .arg(autosave.originalPath, error.section(QLatin1Char('\n'), 0, 0));
    }
    if (!base) document->newRig(Rig{});
    if (document->rig() == *recovered.rig) return {}; // the file already holds exactly this rig
    QString error;
    if (!document->replaceRig(*recovered.rig, tr("Recover unsaved changes"), &error)) return error;
    return {};
}

void Autosave::remove(RecoveredAutosave& autosave) {
    QFile::remove(autosave.metaPath);
    QFile::remove(autosave.rigPath);
    if (autosave.lock) autosave.lock->unlock();
    autosave.lock.reset();
}

} // namespace lr
