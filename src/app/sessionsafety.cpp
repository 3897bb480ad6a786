#include "sessionsafety.h"

#include "documentfiles.h"
#include "editor/document.h"
#include "filewatch.h"
#include "mainwindow.h"

#include <QDir>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QTimer>

namespace lr {

namespace {

QString describeAutosave(const RecoveredAutosave& a) {
    const QString name = a.rigName.isEmpty() ? QObject::tr("(unnamed)") : a.rigName;
    const QString file =
        a.originalPath.isEmpty() ? QObject::tr("never saved") : QDir::toNativeSeparators(a.originalPath);
    return QObject::tr("the rig \"%1\" (%2), autosaved %3")
        .arg(name, file, QLocale().toString(a.saved.toLocalTime(), QLocale::ShortFormat));
}

} // namespace

SessionSafety::SessionSafety(MainWindow* window, const QString& autosaveDir)
    : QObject(window), m_window(window), m_autosave(new Autosave(window->document(), autosaveDir, this)),
      m_watch(new RigFileWatch(window->document(), this)) {
    askRecovery = [this](const RecoveredAutosave& a) {
        QMessageBox box(QMessageBox::Warning, tr("Recover unsaved changes"),
                        tr("LightRig did not exit cleanly last time. Unsaved changes were recovered: %1.")
                            .arg(describeAutosave(a)),
                        QMessageBox::NoButton, m_window);
        box.setInformativeText(tr("Restore them into the editor, or discard them for good?"));
        QPushButton* restore = box.addButton(tr("&Restore"), QMessageBox::AcceptRole);
        box.addButton(tr("&Discard"), QMessageBox::DestructiveRole);
        box.setDefaultButton(restore);
        box.exec();
        return box.clickedButton() == restore ? RecoveryAnswer::Restore : RecoveryAnswer::Discard;
    };
    m_watch->askChanged = [this](const QString& path, bool modified) {
        const QString file = QFileInfo(path).fileName();
        QMessageBox box(QMessageBox::Question, tr("Rig changed on disk"),
                        tr("%1 was changed on disk by another program.").arg(file), QMessageBox::NoButton,
                        m_window);
        box.setInformativeText(
            modified ? tr("Reload it and lose your unsaved changes, or keep your version "
                          "(saving will overwrite the file)?")
                     : tr("Reload it, or keep the version shown (saving will overwrite the file)?"));
        QPushButton* reload = box.addButton(tr("&Reload"), QMessageBox::DestructiveRole);
        QPushButton* keep = box.addButton(tr("&Keep mine"), QMessageBox::RejectRole);
        box.setDefaultButton(modified ? keep : reload);
        box.exec();
        return box.clickedButton() == reload ? RigFileWatch::ChangedAnswer::Reload
                                             : RigFileWatch::ChangedAnswer::KeepMine;
    };
    m_watch->askOverwrite = [this](const QString& path) {
        return QMessageBox::warning(
                   m_window, tr("Overwrite changed file?"),
                   tr("%1 has changed on disk since it was opened. Overwrite it with your rig?")
                       .arg(QDir::toNativeSeparators(path)),
                   QMessageBox::Save | QMessageBox::Cancel, QMessageBox::Cancel) == QMessageBox::Save;
    };
    m_watch->notify = [this](const QString& text) { m_window->statusBar()->showMessage(text, 15000); };
    connect(m_autosave, &Autosave::failed, this, [this](const QString& error) {
        m_window->statusBar()->showMessage(tr("Autosave failed: %1").arg(error), 15000);
    });
    RigFileWatch* watch = m_watch;
    window->files()->confirmWrite = [watch](const QString& path) { return watch->confirmSave(path); };
}

bool SessionSafety::offerRecovery() {
    std::vector<RecoveredAutosave> found = Autosave::findRecoverable(m_autosave->dir());
    if (found.empty()) return false;
    RecoveredAutosave& newest = found.front();
    if (askRecovery(newest) == RecoveryAnswer::Discard) {
        Autosave::remove(newest);
        return false;
    }
    QString note;
    const QString error = Autosave::restore(m_window->document(), newest, &note);
    if (!error.isEmpty()) {
        QMessageBox::warning(m_window, tr("Recover unsaved changes"),
                             tr("The autosave could not be restored; it is kept in %1.\n\n%2")
                                 .arg(QDir::toNativeSeparators(newest.rigPath), error));
        return false; // the lock is released with `found`; the file stays for another try
    }
    // Safe under this session before the old copy goes.
    if (m_window->document()->isModified() && !m_autosave->saveNow()) return true;
    Autosave::remove(newest);
    m_window->statusBar()->showMessage(note.isEmpty() ? tr("Recovered unsaved changes") : note, 15000);
    return true;
}

SessionSafety* installSessionSafety(MainWindow* window, bool offerRecovery) {
    auto* safety = new SessionSafety(window);
    if (offerRecovery) QTimer::singleShot(0, safety, [safety] { safety->offerRecovery(); });
    return safety;
}

} // namespace lr
