// The Presets dock and menu: built-in and user presets with thumbnails. Applying one replaces the rig as
// one undo step; "Save rig as preset" stores the current rig with a thumbnail rendered by LightRig itself.
#pragma once

#include "presetstore.h"

#include <QDockWidget>
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

    PresetsDock(Document* document, PresetStore* store, QWidget* parent = nullptr);
    void setThumbnailRenderer(ThumbnailRenderer renderer) { m_renderThumbnail = std::move(renderer); }
    // Fills `menu` with an entry per preset (kept up to date) plus "Save rig as preset…".
    void attachMenu(QMenu* menu);
    QListWidget* list() const { return m_list; }

public slots:
    bool applyPreset(const lr::PresetEntry& entry);  // false (and an error shown) when it cannot be read
    void saveAsPreset();                              // asks for a name
    bool saveAsPreset(const QString& name);           // no dialog (tests); asks before overwriting
    void reload();

private:
    void deleteSelected();
    void rebuildMenu(QMenu* menu);
    PresetEntry entryOf(const QListWidgetItem* item) const;

    Document* m_doc;
    PresetStore* m_store;
    QListWidget* m_list;
    QToolButton* m_delete = nullptr;
    ThumbnailRenderer m_renderThumbnail;
};

}  // namespace lr
