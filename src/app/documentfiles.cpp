#include "documentfiles.h"

#include "core/defaultrig.h"
#include "core/rigjson.h"
#include "editor/document.h"
#include "errordialog.h"
#include "lightimport.h"
#include "model/isolatedimport.h"
#include "recentfiles.h"
#include "scene.h"
#include "texturesconsent.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QtConcurrent/QtConcurrentRun>

namespace lr {

namespace {
const QString kRigFilter = QObject::tr("LightRig rigs (*.json);;All files (*)");

QString folderKey(DocumentFiles::FileKind kind) {
    return kind == DocumentFiles::FileKind::Rig ? QStringLiteral("files/lastRigDir")
                                                : QStringLiteral("files/lastModelDir");
}
} // namespace

QString DocumentFiles::lastFolder(FileKind kind) {
    // "files/lastDir" was the one folder both kinds shared before: still a better start than home.
    const QSettings s;
    const QString dir = s.value(folderKey(kind), s.value(QStringLiteral("files/lastDir"))).toString();
    return !dir.isEmpty() && QFileInfo(dir).isDir() ? dir : QDir::homePath();
}

void DocumentFiles::rememberFolder(FileKind kind, const QString& filePath) {
    if (filePath.isEmpty() || filePath.startsWith(QLatin1String(":/"))) return; // bundled resources
    QSettings().setValue(folderKey(kind), QFileInfo(filePath).absolutePath());
}

struct DocumentFiles::Load {
    QString path;
    bool allowOutside = false; // ModelLoadOptions::allowTexturesOutsideFolder: the user said Load
    std::atomic<bool> cancelled{false};
};

DocumentFiles::DocumentFiles(Document* document, Scene* scene, RecentFiles* recent, QWidget* window)
    : QObject(window), m_doc(document), m_scene(scene), m_recent(recent), m_window(window) {
    askUnsaved = [this](const QString& name) {
        const auto answer = QMessageBox::warning(
            m_window, tr("Unsaved changes"), tr("The rig %1 has unsaved changes. Save them?").arg(name),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        return answer == QMessageBox::Save      ? UnsavedAnswer::Save
               : answer == QMessageBox::Discard ? UnsavedAnswer::Discard
                                                : UnsavedAnswer::Cancel;
    };
    // The folders are remembered when a file of that kind was opened or saved (rememberFolder), not here.
    askOpenPath = [this](const QString& title, const QString& filter) {
        return QFileDialog::getOpenFileName(m_window, title, lastFolder(m_askingKind), filter);
    };
    askSavePath = [this](const QString& title, const QString& suggested, const QString& filter) {
        return QFileDialog::getSaveFileName(m_window, title, suggested, filter);
    };
    askTexturesOutsideFolder = [this](const QString& path, const QStringList& references) {
        return askLoadTexturesOutsideFolder(m_window, path, references);
    };
}

DocumentFiles::~DocumentFiles() {
    if (m_loading) m_loading->cancelled = true;
    if (m_watcher) m_watcher->waitForFinished();
}

bool DocumentFiles::isRigFile(const QString& path) {
    return QFileInfo(path).suffix().compare(QLatin1String("json"), Qt::CaseInsensitive) == 0;
}

bool DocumentFiles::maybeSave() {
    if (!m_doc->isModified()) return true;
    switch (askUnsaved(m_doc->displayName())) {
    case UnsavedAnswer::Save:
        return save();
    case UnsavedAnswer::Discard:
        return true;
    case UnsavedAnswer::Cancel:
        return false;
    }
    return false;
}

bool DocumentFiles::newRig() {
    if (!maybeSave()) return false;
    m_doc->newRig(Rig{});
    emit statusMessage(tr("New rig"));
    return true;
}

bool DocumentFiles::openRig(const QString& requested) {
    QString path = requested;
    if (path.isEmpty()) {
        m_askingKind = FileKind::Rig;
        path = askOpenPath(tr("Open rig"), kRigFilter);
    }
    if (path.isEmpty()) return false;
    auto refuse = [this, &path](const QString& error) {
        const QStringList lines = error.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        showError(m_window, {tr("Open rig"),
                             tr("Could not open %1: %n error(s). The rig that was open is unchanged.",
                                nullptr, int(lines.size()))
                                 .arg(QFileInfo(path).fileName()),
                             lines});
        return false;
    };
    // Check the file before asking about unsaved changes: a file that cannot be opened must not cost the
    // user a question (or a save) first.
    const RigReadResult check = readRigFile(path);
    if (!check.ok())
        return refuse(check.errors.isEmpty() ? tr("%1: could not be read").arg(path)
                                             : check.errors.join(QLatin1Char('\n')));
    if (!maybeSave()) return false;
    QStringList warnings;
    const QString error = m_doc->load(path, &warnings); // read again: it may have changed while we asked
    if (!error.isEmpty()) return refuse(error);
    rememberFolder(FileKind::Rig, path);
    m_recent->add(path);
    emit rigOpened(path);
    emit statusMessage(warnings.isEmpty()
                           ? tr("Opened %1").arg(QDir::toNativeSeparators(path))
                           : tr("Opened %1 with %n warning(s): %2", nullptr, int(warnings.size()))
                                 .arg(QDir::toNativeSeparators(path), warnings.first()));
    return true;
}

bool DocumentFiles::save() {
    if (m_doc->filePath().isEmpty() || m_doc->filePath().startsWith(QLatin1String(":/"))) return saveAs();
    if (confirmWrite && !confirmWrite(m_doc->filePath())) return false;
    const QString error = m_doc->save();
    if (!error.isEmpty()) {
        showError(m_window, {tr("Save rig"), tr("Could not save the rig."), error.split(QLatin1Char('\n'))});
        return false;
    }
    emit statusMessage(tr("Saved %1").arg(QDir::toNativeSeparators(m_doc->filePath())));
    return true;
}

bool DocumentFiles::saveAs(const QString& requested) {
    QString path = requested;
    if (path.isEmpty()) {
        const QString name = m_doc->rig().name.isEmpty() ? tr("rig") : m_doc->rig().name;
        const QString suggested =
            m_doc->filePath().isEmpty() || m_doc->filePath().startsWith(QLatin1String(":/"))
                ? QDir(lastFolder(FileKind::Rig)).filePath(name + QStringLiteral(".json"))
                : m_doc->filePath();
        path = askSavePath(tr("Save rig as"), suggested, kRigFilter);
    }
    if (path.isEmpty()) return false;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
    if (confirmWrite && !confirmWrite(path)) return false;
    const QString error = m_doc->saveAs(path);
    if (!error.isEmpty()) {
        showError(m_window, {tr("Save rig"), tr("Could not save the rig."), error.split(QLatin1Char('\n'))});
        return false;
    }
    rememberFolder(FileKind::Rig, path);
    m_recent->add(path);
    emit rigOpened(path);
    emit statusMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

bool DocumentFiles::openModel(const QString& requested) {
    QString path = requested;
    if (path.isEmpty()) {
        m_askingKind = FileKind::Model;
        path = askOpenPath(tr("Open model"), modelFileFilter() + tr(";;All files (*)"));
    }
    if (path.isEmpty()) return false;
    startModelLoad(path, false);
    return true;
}

void DocumentFiles::startModelLoad(const QString& path, bool allowOutside) {
    cancelModelLoad(); // a newer request supersedes a running one
    auto load = std::make_shared<Load>();
    load->path = path;
    load->allowOutside = allowOutside;
    m_loading = load;
    emit modelLoadStarted(path);
    emit statusMessage(
        allowOutside
            ? tr("Loading %1 with its textures from outside its folder…").arg(QDir::toNativeSeparators(path))
            : tr("Loading %1…").arg(QDir::toNativeSeparators(path)));
    ModelLoadOptions options;
    options.allowTexturesOutsideFolder = allowOutside;
    QPointer<DocumentFiles> self(this);
    options.progress = [load, self](double fraction) {
        if (self)
            QMetaObject::invokeMethod(
                self.data(),
                [self, load, fraction] {
                    if (self && self->m_loading == load) emit self->modelLoadProgress(fraction);
                },
                Qt::QueuedConnection);
        return !load->cancelled.load();
    };
    auto* watcher = new QFutureWatcher<ModelLoadResult>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, load] {
        watcher->deleteLater();
        if (m_watcher == watcher) m_watcher = nullptr;
        if (m_loading != load) return; // superseded or cancelled: its result is dropped
        modelImported(load, watcher->result());
    });
    m_watcher = watcher;
    watcher->setFuture(QtConcurrent::run([path, options] { return importModelIsolated(path, options); }));
}

void DocumentFiles::modelImported(const std::shared_ptr<Load>& load, const ModelLoadResult& result) {
    const QString name = QFileInfo(load->path).fileName();
    QString note;
    if (result.ok() && !load->allowOutside && !result.model->texturesOutsideFolder.isEmpty()) {
        // Asked while the load still counts as running, so a newer request made meanwhile supersedes it.
        const QStringList refs = result.model->texturesOutsideFolder;
        QPointer<DocumentFiles> self(this);
        const bool allow = askTexturesOutsideFolder ? askTexturesOutsideFolder(load->path, refs) : false;
        if (!self || m_loading != load) return;
        if (allow) {
            m_loading.reset();
            emit modelLoadFinished();
            startModelLoad(load->path, true);
            return;
        }
        note = tr("; %n texture(s) outside the model's folder not loaded (parts untextured)", nullptr,
                  int(refs.size()));
    }
    m_loading.reset();
    if (result.ok()) {
        const auto& model = *result.model;
        if (rigFollowsModel()) {
            const DefaultRigChoice chosen =
                chooseDefaultRig(model.hasPbrMaterials(), model.lights, load->path);
            if (!(chosen.rig == m_doc->rig())) m_doc->newRig(chosen.rig);
            m_automaticRig = m_doc->rig();
            note += tr("; lit by %1, %2 shading").arg(chosen.source, toString(chosen.rig.shading.model));
        }
        m_scene->setModel(result.model, load->path);
        if (!load->path.startsWith(QLatin1String(":/"))) m_recent->add(load->path);
        rememberFolder(FileKind::Model, load->path);
        const auto& m = *result.model;
        emit statusMessage(tr("Loaded %1: %2 triangles, %3 meshes, %4 materials in %5 ms%6%7")
                               .arg(name)
                               .arg(m.triangleCount())
                               .arg(m.meshes.size())
                               .arg(m.materials.size())
                               .arg(m.loadMs, 0, 'f', 0)
                               .arg(m.warnings.isEmpty()
                                        ? QString()
                                        : tr(" (%n warning(s))", nullptr, int(m.warnings.size())),
                                    note));
        emit modelLoaded(load->path);
        emit modelLoadFinished();
    } else {
        // Finished (the Loading bar goes) before the error dialog opens, not behind it; then the failure,
        // whose handler may start another load (the bundled model as a fallback).
        emit modelLoadFinished();
        if (result.cancelled) return;
        emit modelLoadFailed(load->path, result.error);
        showError(m_window, {tr("Open model"),
                             tr("Could not open %1. The model that was open is unchanged.").arg(name),
                             {result.error}});
    }
}

void DocumentFiles::cancelModelLoad() {
    if (!m_loading) return;
    m_loading->cancelled = true;
    m_loading.reset();
    emit statusMessage(tr("Model loading cancelled"));
    emit modelLoadFinished();
}

void DocumentFiles::markRigAutomatic() {
    m_automaticRig = m_doc->rig();
}

bool DocumentFiles::rigFollowsModel() const {
    return m_automaticRig && m_doc->filePath().isEmpty() && !m_doc->isModified() &&
           m_doc->undoStack()->count() == 0 && m_doc->rig() == *m_automaticRig;
}

bool DocumentFiles::importLightsFromModel() {
    const Model& model = *m_scene->model();
    if (model.lights.lights.empty()) {
        showError(m_window, {tr("Import lights from model"),
                             tr("%1 has no lights of its own.")
                                 .arg(m_scene->path().isEmpty() ? tr("The model")
                                                                : QFileInfo(m_scene->path()).fileName()),
                             {}});
        return false;
    }
    const std::vector<Light> lights = lightsInRigSpace(model.lights, m_doc->rig(), m_scene->frame());
    QString error;
    if (!m_doc->addLights(-1, lights, tr("Import %n light(s) from the model", nullptr, int(lights.size())),
                          &error)) {
        showError(m_window,
                  {tr("Import lights from model"), tr("Could not import the model's lights."), {error}});
        return false;
    }
    emit statusMessage(tr("Imported %n light(s) from the model", nullptr, int(lights.size())));
    return true;
}

bool DocumentFiles::openFile(const QString& path) {
    if (!QFileInfo(path).isFile() && !path.startsWith(QLatin1String(":/"))) {
        showError(m_window, {tr("Open"), tr("%1: no such file").arg(QDir::toNativeSeparators(path)), {}});
        m_recent->remove(path);
        return false;
    }
    return isRigFile(path) ? openRig(path) : openModel(path);
}

} // namespace lr
