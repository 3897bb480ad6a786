// The linking matrix (issue 38): one row per light of a Document, one column per part row of the model
// (editor/linkedit.h linkPartRows: one per node name, "ground" while the rig's ground is on), and in each
// cell a check box: in Lit mode whether the light lights the part, in Shadow mode whether the part casts the
// light's shadow (no box for a light whose type casts none). PartiallyChecked: the light links some of the
// row's meshes. Checking a cell is setRowLinked on that light: one undo step, minimal lists. Follows the
// document (structural changes reset it; value changes update their rows) and the parts it is given.
#pragma once

#include "core/lightlink.h"
#include "editor/linkedit.h"

#include <QAbstractTableModel>
#include <QPointer>
#include <vector>

namespace lr {

class Document;
struct RigChange;

class LinkMatrixModel : public QAbstractTableModel {
    Q_OBJECT
  public:
    explicit LinkMatrixModel(Document* document, QObject* parent = nullptr);

    // The model's parts (scene/linkparts.h linkParts(model, nullptr)); the ground is added while it is on.
    void setModelParts(std::vector<PartNames> parts);
    const std::vector<PartNames>& parts() const { return m_parts; }
    const std::vector<LinkPartRow>& partRows() const { return m_rows; }

    LinkKind mode() const { return m_mode; }
    void setMode(LinkKind mode);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

  signals:
    void refused(const QString& reason);

  private:
    void rebuild(); // parts and rows from m_modelParts and the rig's ground
    bool groundOn() const;
    bool isCell(const QModelIndex& index) const;
    bool cellHasBox(int light, int column) const;
    void onAboutToChange(const RigChange& change);
    void onChanged(const RigChange& change);

    QPointer<Document> m_doc;
    std::vector<PartNames> m_modelParts, m_parts;
    std::vector<LinkPartRow> m_rows;
    bool m_ground = false;
    bool m_resetting = false;
    LinkKind m_mode = LinkKind::Lit;
};

} // namespace lr
