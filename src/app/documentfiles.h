// File handling for the main window: new/open/save rigs (with the Save/Discard/Cancel question for unsaved
// changes), opening models in the background (the current scene stays interactive; cancellable; a newer
// request supersedes an older one), importing a model's lights, and opening whatever is dropped on the
// window. A failed open changes nothing and reports FILE: field: reason in a copyable message.
#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QPointer>
#include <atomic>
#include <functional>
#include <memory>

#include "core/rig.h"
#include "model/modelloader.h"

#include <optional>

class QWidget;

namespace lr {

class Document;
class RecentFiles;
class Scene;

class DocumentFiles : public QObject {
    Q_OBJECT
  public:
    enum class UnsavedAnswer { Save, Discard, Cancel };
    enum class FileKind { Rig, Model };

    // The folder the open/save dialogs start in, one per kind of file (QSettings "files/lastRigDir",
    // "files/lastModelDir"): a model's folder is never proposed for a rig. rememberFolder is called when a
    // file of that kind was opened or saved.
    static QString lastFolder(FileKind kind);
    static void rememberFolder(FileKind kind, const QString& filePath);

    DocumentFiles(Document* document, Scene* scene, RecentFiles* recent, QWidget* window);
    ~DocumentFiles() override;

    // Hooks for tests and scripted runs: the question asked before unsaved changes would be lost, and the
    // file dialogs (return "" for cancel). Defaults use QMessageBox / QFileDialog.
    std::function<UnsavedAnswer(const QString& documentName)> askUnsaved;
    // askOpenPath's default starts in lastFolder() of the kind being opened.
    std::function<QString(const QString& title, const QString& filter)> askOpenPath;
    std::function<QString(const QString& title, const QString& suggested, const QString& filter)> askSavePath;
    // Asked before the rig is written to a path (sessionsafety.cpp: "changed on disk since opened,
    // overwrite?"); false cancels the save. Unset: always write.
    std::function<bool(const QString& path)> confirmWrite;
    // Asked when an opened model's textures were refused for lying outside its folder (texturesconsent.h);
    // true imports it again allowing them, false keeps it without them. Default: the message box.
    std::function<bool(const QString& modelPath, const QStringList& references)> askTexturesOutsideFolder;

    bool maybeSave(); // true when it is fine to drop the current rig (saved, discarded or unmodified)
    bool newRig();
    // "" asks for a file. The file is read and checked first: one that cannot be opened is reported without
    // asking about unsaved changes; then maybeSave(), then the load.
    bool openRig(const QString& path = QString());
    bool save(); // untitled: save as
    bool saveAs(const QString& path = QString());
    // Starts loading a model ("" asks for a file); returns false only when nothing was started.
    bool openModel(const QString& path = QString());
    bool isLoadingModel() const { return m_loading != nullptr; }
    void cancelModelLoad();
    bool importLightsFromModel();
    // The rig now open was chosen automatically (the startup default): while it stays untouched (untitled,
    // no undo step, unchanged), a model that finishes loading replaces it with core/defaultrig.h's choice
    // for that model (its own lights and physically based shading for a PBR model, and so on).
    void markRigAutomatic();
    bool rigFollowsModel() const;
    // A dropped or recent file: rig files (.json) open as rigs, anything else as a model.
    bool openFile(const QString& path);
    static bool isRigFile(const QString& path);

  signals:
    void modelLoadStarted(const QString& path);
    void modelLoadProgress(double fraction);
    void modelLoaded(const QString& path);
    void modelLoadFailed(const QString& path, const QString& error); // after modelLoadFinished; not on cancel
    void modelLoadFinished(); // loaded, failed or cancelled (before a failure is reported: no bar behind it)
    void statusMessage(const QString& text);
    void rigOpened(const QString& path); // openRig loaded it (the Document holds it now)

  private:
    struct Load;
    void startModelLoad(const QString& path, bool allowOutside);
    void modelImported(const std::shared_ptr<Load>& load, const ModelLoadResult& result);

    Document* m_doc;
    Scene* m_scene;
    RecentFiles* m_recent;
    QPointer<QWidget> m_window;
    std::shared_ptr<Load> m_loading;
    QFutureWatcher<ModelLoadResult>* m_watcher = nullptr;
    FileKind m_askingKind = FileKind::Rig; // which kind askOpenPath's default dialog is asked for
    std::optional<Rig> m_automaticRig;     // markRigAutomatic()'s rig, while it may follow the model
};

} // namespace lr
