#include "editor/linkmatrixmodel.h"

#include "editor/document.h"

namespace lr {

LinkMatrixModel::LinkMatrixModel(Document* document, QObject* parent)
    : QAbstractTableModel(parent), m_doc(document) {
    connect(document, &Document::rigAboutToChange, this, &LinkMatrixModel::onAboutToChange);
    connect(document, &Document::rigChanged, this, &LinkMatrixModel::onChanged);
    rebuild();
}

bool LinkMatrixModel::isCell(const QModelIndex& index) const {
    return index.isValid() && index.model() == this && index.row() < rowCount() &&
           index.column() < columnCount();
}

bool LinkMatrixModel::groundOn() const {
    return m_doc && m_doc->rig().ground.mode != GroundMode::Off;
}

void LinkMatrixModel::rebuild() {
    m_ground = groundOn();
    m_parts = m_modelParts;
    if (m_ground) m_parts.push_back(PartNames::theGround());
    m_rows = linkPartRows(m_parts);
}

void LinkMatrixModel::setModelParts(std::vector<PartNames> parts) {
    beginResetModel();
    m_modelParts = std::move(parts);
    rebuild();
    endResetModel();
}

void LinkMatrixModel::setMode(LinkKind mode) {
    if (mode == m_mode) return;
    m_mode = mode;
    // Which cells have a box changes with the mode (a rim light has no shadow): every cell and the flags.
    if (rowCount() > 0 && columnCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
    if (columnCount() > 0) emit headerDataChanged(Qt::Horizontal, 0, columnCount() - 1);
}

int LinkMatrixModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || !m_doc ? 0 : m_doc->lightCount();
}

int LinkMatrixModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

bool LinkMatrixModel::cellHasBox(int light, int column) const {
    return !m_rows[size_t(column)].name.isEmpty() &&
           (m_mode == LinkKind::Lit || m_doc->light(light).castsShadows());
}

QVariant LinkMatrixModel::data(const QModelIndex& index, int role) const {
    if (!m_doc || !isCell(index)) return {};
    const Light& l = m_doc->light(index.row());
    const LinkPartRow& row = m_rows[size_t(index.column())];
    const bool box = cellHasBox(index.row(), index.column());
    const LinkState state = linkState(linkSet(l.link, m_mode), m_parts, row);
    switch (role) {
    case Qt::CheckStateRole:
        if (!box) return {};
        return state == LinkState::On    ? Qt::Checked
               : state == LinkState::Off ? Qt::Unchecked
                                         : Qt::PartiallyChecked;
    case Qt::DisplayRole:
        return box ? QVariant() : QVariant(QStringLiteral("—"));
    case Qt::ToolTipRole:
        if (!box)
            return row.name.isEmpty() ? tr("%1 has no name a rig could link it by").arg(row.label)
                                      : tr("%1 casts no shadow").arg(l.name);
        if (m_mode == LinkKind::Lit)
            return state == LinkState::On    ? tr("%1 lights %2").arg(l.name, row.label)
                   : state == LinkState::Off ? tr("%1 does not light %2").arg(l.name, row.label)
                                             : tr("%1 lights some meshes of %2").arg(l.name, row.label);
        return state == LinkState::On ? tr("%2 casts the shadow of %1").arg(l.name, row.label)
               : state == LinkState::Off
                   ? tr("%2 casts no shadow of %1").arg(l.name, row.label)
                   : tr("Some meshes of %2 cast the shadow of %1").arg(l.name, row.label);
    case Qt::TextAlignmentRole:
        return int(Qt::AlignCenter);
    default:
        return {};
    }
}

Qt::ItemFlags LinkMatrixModel::flags(const QModelIndex& index) const {
    if (!m_doc || !isCell(index)) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (cellHasBox(index.row(), index.column())) f |= Qt::ItemIsUserCheckable;
    return f;
}

bool LinkMatrixModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!m_doc || role != Qt::CheckStateRole || !(flags(index) & Qt::ItemIsUserCheckable)) return false;
    const bool on = value.toInt() == Qt::Checked; // from PartiallyChecked a click checks
    QString error;
    const bool done =
        setRowLinked(m_doc, {index.row()}, m_mode, m_parts, m_rows[size_t(index.column())], on, &error);
    if (!error.isEmpty()) emit refused(error);
    return done; // the document's rigChanged updated the cell
}

QVariant LinkMatrixModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (!m_doc) return {};
    if (orientation == Qt::Horizontal) {
        if (section < 0 || section >= columnCount()) return {};
        const LinkPartRow& row = m_rows[size_t(section)];
        if (role == Qt::DisplayRole) return row.label;
        if (role == Qt::ToolTipRole) return row.toolTip;
        return {};
    }
    if (section < 0 || section >= rowCount()) return {};
    if (role == Qt::DisplayRole) return m_doc->light(section).name;
    return {};
}

void LinkMatrixModel::onAboutToChange(const RigChange& change) {
    if (!change.isStructural() || m_resetting) return;
    m_resetting = true;
    beginResetModel();
}

void LinkMatrixModel::onChanged(const RigChange& change) {
    if (change.isStructural()) {
        if (!m_resetting) beginResetModel(); // a change announced to no one: reset all the same
        m_resetting = false;
        rebuild();
        endResetModel();
        return;
    }
    if (change.kind == RigChange::RigValues) {
        if (groundOn() == m_ground) return;
        beginResetModel(); // the ground's column comes or goes
        rebuild();
        endResetModel();
        return;
    }
    const LightProperty p = change.lightProperty;
    if (p != LightProperty::Link && p != LightProperty::Any && p != LightProperty::Name &&
        p != LightProperty::Type)
        return;
    if (columnCount() > 0 && change.first >= 0 && change.last < rowCount())
        emit dataChanged(index(change.first, 0), index(change.last, columnCount() - 1));
    if (p == LightProperty::Name) emit headerDataChanged(Qt::Vertical, change.first, change.last);
}

} // namespace lr
