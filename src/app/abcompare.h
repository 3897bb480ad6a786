// A/B comparison in the viewport (issue 17, part 4). View › Compare A/B › Take snapshot as B copies the rig
// as it is drawn now (solo applied) together with the environment it is lit by; Open rig as B… reads a
// second rig file through the same reader and error box as File › Open rig (a file that cannot be read
// changes nothing, and the document is never touched). While a B is held and a layout is chosen, the
// viewport shows A — the document's rig, live, every edit at once — and B over the same model from the
// same camera with the same view settings (abcompareframe.h draws it):
//   Wipe          one image split by a vertical line the user drags: left of it A, right of it B
//   Side by side  A in the left half, B in the right, each the whole view
// Swap puts B on the left; Leave compare goes back to the normal view (B is kept for the next time). A
// snapshot or an opened rig starts in Wipe. Nothing here is saved with the rig or is an undo step.
// B's environment: a snapshot shares the Scene's when that was loaded for the same spec, else it is loaded
// in the background (scene/environmentloader.h) as is an opened rig's, relative to its file; B is drawn
// without it until then.
#pragma once

#include "core/rig.h"

#include <QFutureWatcher>
#include <QObject>
#include <QRectF>
#include <functional>
#include <memory>

class QAction;
class QMenu;
class QWidget;

namespace lr {

class Document;
class Scene;
struct LoadedEnvironment;
struct EnvironmentLoadResult;

enum class CompareLayout { Off, Wipe, SideBySide };

class AbCompare : public QObject {
    Q_OBJECT
  public:
    static constexpr double kHandlePixels = 6.0; // a press this close to the wipe line drags it

    AbCompare(Document* document, Scene* scene, QWidget* window, QObject* parent = nullptr);
    ~AbCompare() override;

    bool hasB() const { return m_hasB; }
    const Rig& rigB() const { return m_rigB; }
    QString nameB() const { return m_nameB; } // "snapshot 14:02:11" or the file name
    // B's loaded environment; null for none, or while it loads, or when it failed.
    const std::shared_ptr<const LoadedEnvironment>& environmentB() const { return m_environmentB; }

    CompareLayout layout() const { return m_layout; }
    bool isActive() const { return m_hasB && m_layout != CompareLayout::Off; }
    double split() const { return m_split; } // the wipe line, as a fraction of the width (0..1)
    bool swapped() const { return m_swapped; }

    // Widget geometry (any pixel unit): the wipe line's x; where the document's rig (A) is drawn with the
    // whole camera (the widget in Wipe and when inactive, a half in Side by side); whether a point grabs
    // the wipe line.
    double splitX(double width) const { return m_split * width; }
    QRectF documentRect(const QSizeF& size) const;
    bool onWipeHandle(const QPointF& position, const QSizeF& size) const;

    // Labels naming the two sides over this viewport, shown while comparing (abcompareframe.h).
    void attachLabels(QWidget* viewport);

    QAction* snapshotAction() const { return m_snapshot; }
    QAction* openAction() const { return m_open; }
    QAction* wipeAction() const { return m_wipe; }
    QAction* sideBySideAction() const { return m_sideBySide; }
    QAction* swapAction() const { return m_swap; }
    QAction* leaveAction() const { return m_leave; }
    void addActions(QMenu* menu) const;

    // The file dialog for Open rig as B ("" cancels); tests replace it. Default: QFileDialog.
    std::function<QString(const QString& title, const QString& filter)> askOpenPath;

  public slots:
    void takeSnapshot();
    bool openB(const QString& path = QString()); // "" asks for a file; false when nothing was opened
    void setLayout(lr::CompareLayout layout);
    void setSplit(double fraction); // clamped to 0..1
    void setSwapped(bool swapped);
    void leave() { setLayout(CompareLayout::Off); }

  signals:
    void changed(); // anything the viewport draws differently
    void statusMessage(const QString& text);

  private:
    void setB(const Rig& rig, const QString& name, const QString& folder);
    void environmentLoaded();
    void syncActions();

    Document* m_doc;
    Scene* m_scene;
    QWidget* m_window;
    bool m_hasB = false;
    Rig m_rigB;
    QString m_nameB;
    std::shared_ptr<const LoadedEnvironment> m_environmentB;
    QFutureWatcher<EnvironmentLoadResult>* m_watcher;
    int m_loadGeneration = 0, m_runningGeneration = 0;
    CompareLayout m_layout = CompareLayout::Off;
    double m_split = 0.5;
    bool m_swapped = false;
    QAction *m_snapshot, *m_open, *m_wipe, *m_sideBySide, *m_swap, *m_leave;
};

} // namespace lr
