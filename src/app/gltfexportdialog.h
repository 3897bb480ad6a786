// File › Export glTF… (issue 17, docs/export.md): the model with the rig's lights as KHR_lights_punctual, the
// viewport's view as its first camera and the environment as a note, or the lights alone. The dialog lists
// every lossy conversion (core/gltflights.h's table, as `lightrig export` prints them) before anything is
// written; the export (model/gltfexport.h) then runs off the GUI thread and is written atomically, and a
// failure is an error box naming the file and the reason. It proposes MODEL-lightrig.glb in the folder of
// the last export, else the rig file's folder, else the folder rigs were last opened or saved in (never the
// model's folder unless the user exported there: it is often a download or a shared library); the view
// camera's planes enclose the model with margin (ViewCamera::withExportClipPlanes).
#pragma once

#include "core/gltflights.h"

#include <QDialog>

class QCheckBox;
class QLineEdit;
class QListWidget;

namespace lr {

class MainWindow;

class GltfExportDialog : public QDialog {
    Q_OBJECT
  public:
    GltfExportDialog(const std::vector<LossyConversion>& losses, const QString& suggestedPath,
                     QWidget* parent = nullptr);

    QString path() const;
    bool lightsOnly() const;
    QListWidget* lossList() const { return m_losses; } // one row per lossy conversion (tests)
    QLineEdit* pathEdit() const { return m_path; }
    QCheckBox* lightsOnlyBox() const { return m_lightsOnly; }

    void accept() override; // refuses a path that does not end in .glb or .gltf

  private:
    QLineEdit* m_path;
    QCheckBox* m_lightsOnly;
    QListWidget* m_losses;
};

// The whole interaction: dialog, export, write, status bar or error box.
void exportGltfInteractive(MainWindow* window);

} // namespace lr
