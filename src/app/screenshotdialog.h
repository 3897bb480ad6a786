// "Export screenshot" options (form ui/screenshotdialog.ui): file, size independent of the window,
// supersampling 1–4×, transparent background (PNG only), PNG or JPEG, gizmos on/off, path traced with its
// samples per pixel. Remembered in QSettings.
#pragma once

#include <QDialog>
#include <QSize>
#include <memory>

namespace Ui {
class ScreenshotDialog;
}
class QCheckBox;
class QSpinBox;

namespace lr {

struct ScreenshotOptions {
    QString path;
    QSize size{1920, 1080};
    int supersample = 2; // 1..4
    bool transparent = false;
    bool gizmos = false;
    QByteArray format = "PNG"; // "PNG" or "JPEG"
    // Path traced (issue 36; tracedshot.h): this many samples per pixel instead of the raster tier
    // (supersampling and gizmos do not apply: the samples antialias, and gizmos are not in the scene).
    bool pathTraced = false;
    int traceSamples = 64;
    // Rendered pixels per tile side when exported with progress (screenshotexport.h): small enough that
    // the window repaints and Cancel answers between tiles even on a software renderer. Not in the form.
    int tileSize = 1024;
};

class ScreenshotDialog : public QDialog {
    Q_OBJECT
  public:
    ScreenshotDialog(const QSize& viewportSize, const QString& suggestedPath, QWidget* parent = nullptr);
    ~ScreenshotDialog() override;

    ScreenshotOptions options() const;
    void setOptions(const ScreenshotOptions& options);
    Ui::ScreenshotDialog* form() const { return m_ui.get(); }

    void accept() override; // validates (path, writable folder) and remembers the options

  private:
    void syncFormat();
    void browse();

    std::unique_ptr<Ui::ScreenshotDialog> m_ui;
    QSize m_viewportSize;
    QCheckBox* m_pathTraced;
    QSpinBox* m_traceSamples;
};

} // namespace lr
