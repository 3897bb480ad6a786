// The Mixer dock (issue 37, docs/light-mixing.md "In the editor"): re-balances a finished render per light
// group with no render. It holds one RenderLayers (scene/renderlayers.h) — the per-group images of a render
// of the document's rig — and a LightMix: per group a row (mixergrouprow.h: on/off, EV, tint) and the mixed
// image (mixGroupImages) shown as the viewport shows a render (setDisplay: exposure and tone map), redrawn
// at each change of a control. A/B (the button, or holding the mouse on the image) shows the unmixed sum.
// Reset gives the identity mix; Save mix…/Open mix… write and read mix files (core/lightmixfile.h; a bad file
// is reported in the error dialog and the mix stays as it was); Apply to rig writes the mix into the rig as
// one undo step that keeps every light's id (editor/applylightmix.h), lists what a rig cannot hold, and
// resets the mix (the rig now holds it). Capture asks for layers (captureRequested; MainWindow fills the
// dock).
//
// The layers are of the rig as it was rendered: once the rig differs (a light edited, added, removed), the
// dock says they are stale and keeps working on them; Apply finds the groups' lights by their ids then.
#pragma once

#include "core/lightmix.h"
#include "core/rig.h"
#include "core/types.h"
#include "editor/document.h"
#include "scene/renderlayers.h"

#include <QDockWidget>
#include <QImage>
#include <functional>
#include <map>

class QLabel;
class QPushButton;
class QVBoxLayout;

namespace lr {

class MixerGroupRow;
class MixerPreview;

class MixerDock : public QDockWidget {
    Q_OBJECT
  public:
    explicit MixerDock(Document* document, QWidget* parent = nullptr);
    ~MixerDock() override;

    // New layers, rendered from the document's rig as it is now; `what` says how ("traced, 64 samples",
    // "raster, exact"). The mix keeps its values for the groups the layers have (others are dropped).
    void setLayers(RenderLayers layers, const QString& what);
    // The same for a render that began earlier (a background render): `rig` and `ids` are the document's
    // rig() and lightIds() when it began, which the layers' light indices refer to.
    void setLayers(RenderLayers layers, const QString& what, const Rig& rig, const QList<LightId>& ids);
    void clearLayers();
    // The viewport's exposure (EV) and tone map: the preview shows the mix as the viewport would.
    void setDisplay(double exposureEV, ToneMap toneMap);

    bool hasLayers() const { return !m_layers.groupImages.empty(); }
    const RenderLayers& layers() const { return m_layers; }
    QString what() const { return m_what; }
    bool isStale() const { return m_stale; } // the rig changed since the layers were rendered

    const LightMix& mix() const { return m_mix; }
    void setMix(const LightMix& mix); // the rows follow; mixChanged
    MixerGroupRow* row(const QString& group) const;

    bool showsUnmixed() const { return m_unmixed || m_held; } // A/B
    void setShowUnmixed(bool unmixed);
    // What the preview shows, at the layers' size: mixGroupImages(layers, the mix or, during A/B, none).
    FloatImage shownImage() const;
    // The preview's image: shownImage reduced to the preview's size (mixerpreview.h), as displayed.
    QImage previewImage() const;
    QStringList notApplied() const { return m_notes; } // the last Apply's lines (what the rig could not hold)

    // File dialogs ("" cancels); tests replace them. Default: QFileDialog.
    std::function<QString(const QString& title, const QString& filter)> askOpenPath;
    std::function<QString(const QString& title, const QString& suggested, const QString& filter)> askSavePath;

  public slots:
    void resetMix();
    bool saveMix(const QString& path = QString()); // "" asks for a file
    bool openMix(const QString& path = QString()); // "" asks; a bad file: the error dialog, mix unchanged
    bool applyToRig();

  signals:
    void captureRequested();
    void mixChanged();
    void statusMessage(const QString& text);

  private:
    void buildRows();
    void rebuildPreviewLayers();
    void redraw();
    void updateStale();
    void updateControls();
    void showNotes(const QStringList& lines);
    QString groupToolTip(const LightGroup& group) const;

    Document* m_doc;
    RenderLayers m_layers;
    RenderLayers m_small; // groups reduced to the preview's size
    QString m_what;
    Rig m_rigThen;
    QList<LightId> m_idsThen;
    bool m_stale = false;
    LightMix m_mix;
    bool m_unmixed = false, m_held = false;
    double m_exposure = 0.0;
    ToneMap m_toneMap = ToneMap::Aces;
    QStringList m_notes;
    std::map<QString, MixerGroupRow*> m_rows;

    MixerPreview* m_preview = nullptr;
    QLabel* m_caption = nullptr;
    QLabel* m_staleLabel = nullptr;
    QLabel* m_notesLabel = nullptr;
    QWidget* m_rowsBox = nullptr;
    QVBoxLayout* m_rowsLayout = nullptr;
    QPushButton *m_capture = nullptr, *m_ab = nullptr, *m_reset = nullptr;
    QPushButton *m_open = nullptr, *m_save = nullptr, *m_apply = nullptr;
};

} // namespace lr
