// The Presets dock and menu: built-in and user presets with thumbnails. Applying one replaces the rig as
// one undo step; "Save rig as preset" stores the current rig with a thumbnail rendered by LightRig itself.
// Each preset shows its shading (a "PBR" or "Classic" badge under its name, kShadingRole).
#pragma once

#include "presetstore.h"

#include <QDockWidget>
#include <QHash>
#include <QIcon>
#include <QTimer>
#include <functional>

class QListWidget;
class QListWidgetItem;
class QMenu;
class QToolButton;

namespace lr {

class Document;

class PresetsDock : public QDockWidget {
    Q_OBJECT
  public:
    // Renders a rig on the current model for a thumbnail (null image when it cannot).
    using ThumbnailRenderer = std::function<QImage(const Rig& rig, const QSize& size)>;
    static constexpr int kThumbnailSize = 96;
    // An item's data in this role: its preset's shading ("classic", "pbr"; "" when unreadable), which the
    // item also shows as a "PBR" / "Classic" badge under its name.
    static constexpr int kShadingRole = Qt::UserRole + 2;

    PresetsDock(Document* document, PresetStore* store, QWidget* parent = nullptr);
    // Also renders the thumbnails of presets that have none (built-ins), a few per event-loop pass.
    void setThumbnailRenderer(ThumbnailRenderer renderer);
    // While it returns true (the user orbits or drags in the viewport) no thumbnail is rendered: each costs
    // a frame or more and its own shader compiles on the GUI thread, which made the moving view stutter
    // (issue 40). They resume kBusyRetryMs after it turns false.
    void setBusyCheck(std::function<bool()> busy) { m_busy = std::move(busy); }
    static constexpr int kBusyRetryMs = 500;
    // Fills `menu` with an entry per preset (kept up to date) plus "Save rig as preset…".
    void attachMenu(QMenu* menu);
    QListWidget* list() const { return m_list; }

  public slots:
    bool applyPreset(const lr::PresetEntry& entry); // false (and an error shown) when it cannot be read
    void saveAsPreset();                            // asks for a name
    bool saveAsPreset(const QString& name);         // no dialog (tests); asks before overwriting
    void reload();
    // The model changed: rendered thumbnails (not the saved ones) are redone on it.
    void invalidateThumbnails();
    bool thumbnailsPending() const { return !m_pending.isEmpty(); }

  private:
    void deleteSelected();
    void renderNextThumbnail();
    void rebuildMenu(QMenu* menu);
    PresetEntry entryOf(const QListWidgetItem* item) const;

    Document* m_doc;
    PresetStore* m_store;
    QListWidget* m_list;
    QToolButton* m_delete = nullptr;
    ThumbnailRenderer m_renderThumbnail;
    std::function<bool()> m_busy;
    QHash<QString, QIcon> m_rendered; // preset path -> thumbnail rendered on the current model
    QStringList m_pending;            // preset paths still to render
    QTimer m_thumbnailTimer;          // one thumbnail per event-loop pass
};

} // namespace lr
