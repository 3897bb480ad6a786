// The Quality panel: measures, on demand, what each quality tier costs and how far it is from the
// double-precision reference for the user's own scene and view (the same measurement as `lightrig bench`,
// src/render/qualitybench.h), with progress and cancel, and shows the results three ways: a table in plain
// words (every column explains itself in its tooltip), the time/error chart, and a visual comparison of the
// selected tier's image, the reference and where they differ. Table, chart and comparison share a splitter;
// "Open large" floats the dock at a size where the chart is readable.
// "Use tier" stores the selected row's tier in the view settings (the Render settings dock's combo box).
//
// The measurement runs on the GUI thread between event-loop passes (OpenGL needs the thread of its
// context; the double reference runs on the thread pool), so the editor stays responsive and Cancel works.
#pragma once

#include "core/quality.h"
#include "render/interactionbench.h"
#include "render/qualitybench.h"

#include <QDockWidget>
#include <QImage>
#include <functional>
#include <optional>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace lr {

class MainWindow;

// The scene to measure, as the editor shows it now.
struct QualityRequest {
    BenchScene scene;
    double exposureEV = 0.0;
    ToneMap toneMap = ToneMap::Clamp;
    QSize viewportSize; // device pixels
};

class QualityDock : public QDockWidget {
    Q_OBJECT
  public:
    // Returns the current scene, or nullopt with *whyNot ("no model loaded").
    using SceneProvider = std::function<std::optional<QualityRequest>(QString* whyNot)>;

    explicit QualityDock(QWidget* parent = nullptr);
    void setSceneProvider(SceneProvider provider) { m_provider = std::move(provider); }
    // Called with the tier of the selected row when the user presses "Use tier".
    void setTierChooser(std::function<void(Quality)> chooser) { m_chooser = std::move(chooser); }

    bool isRunning() const { return m_running; }
    const BenchReport& report() const { return m_report; }
    // The last measurement's times per tier and interaction, and each tier's verdict (core/tieroffer.h);
    // every tier offered before a measurement and after clearOffers.
    const TierTimesTable& times() const { return m_times; }
    const TierOffers& offers() const { return m_offers; }
    void setFrames(int frames); // timed frames per tier (default 30)

    // The table's columns, for the tests and the docs: header text and its tooltip.
    static QStringList columnNames();
    static QStringList columnToolTips();

  public slots:
    void measure(); // no-op while running
    void cancel();
    // Times per tier and interaction (as measure() takes them, or kept from before): their verdicts
    // replace the dock's and offersChanged is emitted.
    void setMeasuredTimes(const TierTimesTable& times);
    // The scene changed: the verdicts no longer hold (the table stays, for reading).
    void clearOffers();

  signals:
    void finished(bool ok, const QString& message); // ok false: failed or cancelled
    void offersChanged();

  private:
    void showReport();
    void setRunning(bool running);
    void updateChart();
    void updateComparison();
    void openLarge();
    bool eventFilter(QObject* watched, QEvent* event) override;

    SceneProvider m_provider;
    std::function<void(Quality)> m_chooser;
    QComboBox* m_sizeChoice = nullptr;
    QSpinBox* m_frames = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_stop = nullptr;
    QPushButton* m_use = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QTableWidget* m_table = nullptr;
    QLabel* m_chart = nullptr;
    QLabel* m_compareCaption = nullptr;
    QLabel* m_tierImage = nullptr;
    QLabel* m_referenceImage = nullptr;
    QLabel* m_differenceImage = nullptr;
    QPushButton* m_large = nullptr;
    QImage m_differenceCache;
    int m_differenceRow = -1;
    BenchReport m_report;
    TierTimesTable m_times;
    TierOffers m_offers;
    QImage m_chartImage;
    bool m_running = false;
    bool m_cancelRequested = false;
};

// Creates the Quality dock for the editor's main window (current model, render rig with solo applied,
// viewport camera and size, exposure and tone map; "Use tier" sets the view settings' quality), docks it
// on the right, tabified with the Render settings dock, and returns it. Its verdicts go to the Render
// settings dock; when the view's tier is not offered, the view switches to exact and the status bar says
// why. A new model or environment clears them.
QualityDock* addQualityDock(MainWindow* window);

} // namespace lr
