// Render settings' "Environment" box (issue 15, parts 2 and 3): the rig's environment — none, an HDR image
// (a file, relative to the rig's folder once it is saved, or a bundled one) or the procedural studio (sky and
// floor colours, softboxes: softboxeditor.h) — with its intensity (EV), rotation about the up axis, what it
// shows behind the model (itself, blurred, or the background colour) and the classic diffuse model. Every
// edit is one undo step (RigProperty::Environment through the document's rig-value command; a slider or
// field gesture merges into one). It shows the document's rig, following undo, redo and loads, and the
// state of the background load (environmentloading.h): "Loading environment…" or the load's error.
#pragma once

#include "core/environment.h"

#include <QGroupBox>
#include <QStringList>
#include <functional>
#include <optional>

class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

namespace lr {

class ColorButton;
class EvDragSlider;
class Document;
class EnvironmentLoading;
class NumberEdit;
class SoftboxEditor;

// The bundled environments the image list offers ("builtin:NAME").
QStringList bundledEnvironmentFiles();

class EnvironmentBox : public QGroupBox {
    Q_OBJECT
  public:
    explicit EnvironmentBox(Document* document, QWidget* parent = nullptr);
    ~EnvironmentBox() override;

    // Shows its loads' state (loading, the last error).
    void setLoading(EnvironmentLoading* loading);
    // The file dialog's result: stored relative to the rig's folder when the rig has a file, else absolute.
    // With a loading set, the image is tried first: the rig takes it only once it loads (a file that
    // cannot be read leaves the rig and the view as they were and says why).
    void chooseImageFile(const QString& absolutePath);
    SoftboxEditor* softboxEditor() const { return m_softboxes; }
    // Whether the rig format has the environment's classic diffuse model (Environment::diffuse).
    static bool hasClassicDiffuse();

  private:
    void load();
    // One undo step (continuous: merged with the rest of the gesture until finishGesture).
    void edit(const std::function<void(Environment&)>& change, bool continuous = false);
    void finishGesture();
    void browse();
    void setImage(const QString& file);
    void showStatus();

    Document* m_doc;
    EnvironmentLoading* m_loading = nullptr;
    std::optional<int> m_editToken;
    QComboBox *m_source, *m_file, *m_background, *m_diffuse;
    QToolButton* m_browse;
    NumberEdit *m_intensity, *m_rotation, *m_blur;
    EvDragSlider* m_intensitySlider;
    QSlider* m_rotationSlider;
    double m_dragStartEv = 0.0;
    ColorButton *m_zenith, *m_horizon, *m_floor;
    QWidget *m_imageRow, *m_studio;
    SoftboxEditor* m_softboxes;
    QLabel *m_status, *m_message;
    QList<QWidget*> m_imageOnly, m_studioOnly, m_anySource;
};

} // namespace lr
