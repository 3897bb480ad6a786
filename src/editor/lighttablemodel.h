// The light table: one row per light of a Document, columns name, group (issue 37: a light without one shows
// its own group's name, greyed: lightGroupName), type, on, solo, colour, intensity, the main falloff
// parameter (the range; "—" when the light has none) and shadow (a checkbox; none for types that cast no
// shadow). Every column but solo shows one light
// property (propertyOf) and reads its header, text, editability and edits from the property's row in the
// light-property table (editor/lightproperty.h); solo is view state. Editing goes through the document's
// commands (setData -> one undo step), never into the rig directly. Follows the document's structural changes
// (including undo/redo) with proper insert/remove/move/reset signals, and value changes with dataChanged on
// the affected cells only.
#pragma once

#include "editor/document.h"

#include <QAbstractTableModel>
#include <QPointer>

namespace lr {

class LightTableModel : public QAbstractTableModel {
    Q_OBJECT
  public:
    enum Column {
        NameColumn,
        GroupColumn,
        TypeColumn,
        OnColumn,
        SoloColumn,
        ColorColumn,
        IntensityColumn,
        FalloffColumn,
        ShadowColumn,
        ColumnCount
    };
    enum Role {
        LightIdRole = Qt::UserRole + 1, // LightId (quint64) of the row
        SortRole,     // a sortable scalar per column (name, type index, 0/1, luminance, ...)
        PropertyRole, // the LightProperty the cell edits (int), invalid when none
    };
    static constexpr const char* kMimeType = "application/x-lightrig-light-rows";

    explicit LightTableModel(Document* document, QObject* parent = nullptr);
    Document* document() const { return m_doc; }

    // Roles: DisplayRole formatted text; EditRole the raw value (QString name and group, int type index,
    // glm::dvec3 linear colour, double intensity/range, invalid range for none); CheckStateRole for on and
    // solo; DecorationRole the colour swatch (QColor, effective colour incl. temperature, HDR scaled);
    // ForegroundRole the placeholder colour of a group the light does not set; ToolTipRole details.
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    // EditRole (Name, Group, Type, Color [glm::dvec3 linear or QColor sRGB], Intensity, Falloff range) or
    // CheckStateRole (On, Shadow: an undo step; Solo: transient). Switching on a shadow beyond
    // kMaxShadowCasters is refused with the limit. Invalid values are refused: returns false and emits
    // editRefused(reason).
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    // The same edit applied to several rows as ONE undo step (the view calls this when several rows are
    // selected). Rows where the column does not apply (e.g. range of a directional light) are skipped.
    bool setDataForRows(const QList<int>& rows, int column, const QVariant& value, int role = Qt::EditRole);
    QString lastError() const { return m_lastError; }

    // Drag and drop reordering: rows travel as their indices under kMimeType; a drop becomes a MoveLights.
    Qt::DropActions supportedDropActions() const override { return Qt::MoveAction; }
    Qt::DropActions supportedDragActions() const override { return Qt::MoveAction; }
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                      const QModelIndex& parent) override;
    bool moveRows(const QModelIndex& sourceParent, int sourceRow, int count,
                  const QModelIndex& destinationParent,
                  int destinationChild) override; // -> MoveLights (one undo step)

    static LightProperty propertyOf(int column); // Any when the column edits no light property

  signals:
    void editRefused(const QString& reason);

  private:
    void onAboutToChange(const RigChange& change);
    void onChanged(const RigChange& change);
    void onStructureChanged(const RigChange& change);
    void onSoloChanged();
    bool refuse(const QString& reason);

    QPointer<Document> m_doc;
    QString m_lastError;
    QModelIndexList m_layoutPersistent; // between the two halves of a Reordered change
};

} // namespace lr
