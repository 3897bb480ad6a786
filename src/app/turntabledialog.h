// "Export turntable" options (issue 17): the frames' file name with a run of # for the frame number
// (lightrig_####.png), how many frames (evenly spaced over 360°), what turns (the camera orbits the model's
// centre, or the rig's lights turn and the camera stays), and the screenshot's size, supersampling and
// transparency (PNG or JPEG by the name's suffix). Remembered in QSettings. Built in code, no form.
#pragma once

#include "render/turntable.h"
#include "screenshotdialog.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace lr {

struct TurntableOptions {
    ScreenshotOptions shot; // shot.path: the pattern with # (render/turntable.h framePath); no gizmos
    int frames = 36;
    TurntableRotation rotate = TurntableRotation::Camera;
};

class TurntableDialog : public QDialog {
    Q_OBJECT
  public:
    TurntableDialog(const QSize& viewportSize, const QString& suggestedPath, QWidget* parent = nullptr);

    TurntableOptions options() const;
    void setOptions(const TurntableOptions& options);
    QString message() const; // why accept() refused, for tests

    void accept() override; // validates (name, # for several frames, writable folder), remembers the options

  private:
    QLineEdit* m_path;
    QSpinBox *m_frames, *m_width, *m_height, *m_supersample;
    QComboBox* m_rotate;
    QCheckBox* m_transparent;
    QLabel* m_message;
};

} // namespace lr
