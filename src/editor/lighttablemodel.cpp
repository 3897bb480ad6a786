#include "editor/lighttablemodel.h"

#include "core/lightgroups.h"

#include <QCoreApplication>
#include <QDataStream>
#include <QGuiApplication>
#include <QIODevice>
#include <QMimeData>
#include <QPalette>
#include <algorithm>

namespace lr {

namespace {

QString formatNumber(double v) {
    return QString::number(v, 'g', 4);
}

// The light property each column shows, in column order (Any: the Solo column, which is view state).
constexpr LightProperty kColumnProperty[LightTableModel::ColumnCount] = {
    LightProperty::Name,      LightProperty::Group,        LightProperty::Type,
    LightProperty::Enabled,   LightProperty::Any,          LightProperty::Color,
    LightProperty::Intensity, LightProperty::FalloffRange, LightProperty::ShadowEnabled,
};

// A light without a group of its own: its group is named after it (core/lightgroups.h), which the Group
// column shows greyed.
bool ownGroup(const Light& l) {
    return l.group.trimmed().isEmpty();
}

const LightPropertyInfo* columnRow(int column) {
    return column >= 0 && column < LightTableModel::ColumnCount ? lightPropertyInfo(kColumnProperty[column])
                                                                : nullptr;
}

// Whether the cell has a value: its property is shown for this light (lightproperty.h).
bool hasCell(const LightPropertyInfo* row, const Light& l) {
    return row && row->isShown(l);
}

QString headerLabel(const LightPropertyInfo& row) {
    return (row.tableLabel ? QCoreApplication::translate("lr::LightProperty", row.tableLabel)
                           : row.displayLabel())
        .remove(QLatin1Char('&'));
}

} // namespace

LightTableModel::LightTableModel(Document* document, QObject* parent)
    : QAbstractTableModel(parent), m_doc(document) {
    connect(document, &Document::rigAboutToChange, this, &LightTableModel::onAboutToChange);
    connect(document, &Document::rigChanged, this, &LightTableModel::onChanged);
    connect(document, &Document::soloChanged, this, &LightTableModel::onSoloChanged);
}

int LightTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || !m_doc ? 0 : m_doc->lightCount();
}

int LightTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

LightProperty LightTableModel::propertyOf(int column) {
    return column >= 0 && column < ColumnCount ? kColumnProperty[column] : LightProperty::Any;
}

QVariant LightTableModel::data(const QModelIndex& index, int role) const {
    if (!m_doc || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Light& l = m_doc->light(index.row());
    const int col = index.column();
    const LightPropertyInfo* row = columnRow(col);
    const bool cell = hasCell(row, l);
    const QVariant value = cell ? row->get(l) : QVariant();
    using K = LightValueKind;
    switch (role) {
    case LightIdRole:
        return QVariant::fromValue(m_doc->lightId(index.row()));
    case PropertyRole:
        return row ? QVariant(int(row->id)) : QVariant();
    case Qt::CheckStateRole:
        if (col == SoloColumn) return m_doc->isSoloed(index.row()) ? Qt::Checked : Qt::Unchecked;
        // No checkbox where the property does not apply (a rim light's shadow).
        if (row && row->kind == K::Bool && cell) return value.toBool() ? Qt::Checked : Qt::Unchecked;
        return {};
    case Qt::DecorationRole:
        if (row && row->kind == K::Color) return displayColor(l.effectiveColor());
        return {};
    case Qt::DisplayRole:
        if (!row) return {};
        if (col == GroupColumn) return lightGroupName(l, index.row());
        switch (row->kind) {
        case K::Text:
            return value;
        case K::Enum:
            return row->choices().value(value.toInt());
        case K::Number:
        case K::OptionalNumber:
            return value.isValid() ? formatNumber(value.toDouble()) : QStringLiteral("—");
        default:
            return {};
        }
    case Qt::EditRole:
        if (!row || row->kind == K::Bool) return {};
        return row->kind == K::Enum ? QVariant(value.toInt()) : value;
    case Qt::ForegroundRole:
        if (col == GroupColumn && ownGroup(l)) {
            // The palette's placeholder colour where there is one (a guiless test has no palette).
            if (qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
                return QGuiApplication::palette().brush(QPalette::PlaceholderText);
            return QColor(128, 128, 128);
        }
        return {};
    case SortRole:
        if (col == SoloColumn) return int(m_doc->isSoloed(index.row()));
        if (col == GroupColumn) return lightGroupName(l, index.row()).toLower(); // lights of a group together
        if (!row) return {};
        switch (row->kind) {
        case K::Text:
            return value.toString().toLower();
        case K::Enum:
        case K::Bool:
            return value.toInt();
        case K::Color: {
            const glm::dvec3 c = l.effectiveColor();
            return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
        }
        case K::Number:
        case K::OptionalNumber:
            return value.isValid() ? value.toDouble() : -1.0;
        default:
            return {};
        }
    case Qt::ToolTipRole:
        switch (col) {
        case ColorColumn: {
            QString tip = tr("Linear RGB %1, %2, %3")
                              .arg(formatNumber(l.color.x), formatNumber(l.color.y), formatNumber(l.color.z));
            if (l.temperature) tip += tr(", %1 K").arg(formatNumber(*l.temperature));
            return tip;
        }
        case FalloffColumn:
            if (!l.usesFalloff()) return tr("%1 lights have no distance falloff").arg(lightTypeLabel(l.type));
            return tr("Falloff: %1").arg(toString(l.falloff.model));
        case GroupColumn:
            return ownGroup(l) ? tr("No group set: the light is a group of its own, \"%1\"")
                                     .arg(lightGroupName(l, index.row()))
                               : tr("Renders into the light group \"%1\"").arg(l.group);
        case SoloColumn:
            return tr("Solo: while any light is soloed, only soloed lights render (not saved)");
        case ShadowColumn:
            if (!l.castsShadows()) return tr("%1 lights cast no shadow").arg(lightTypeLabel(l.type));
            return l.shadow.enabled ? tr("Casts a shadow (%1 × %1 texels)").arg(l.shadow.resolution)
                                    : tr("Casts no shadow");
        default:
            return {};
        }
    case Qt::TextAlignmentRole:
        if (row && (row->kind == K::Number || row->kind == K::OptionalNumber))
            return int(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    default:
        return {};
    }
}

QVariant LightTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal) return QAbstractTableModel::headerData(section, orientation, role);
    const LightPropertyInfo* row = columnRow(section);
    if (role == Qt::DisplayRole) {
        if (section == SoloColumn) return tr("Solo");
        return row ? QVariant(headerLabel(*row)) : QVariant();
    }
    if (role == Qt::ToolTipRole && section == GroupColumn)
        return tr(
            "The light group it renders into for mixing: lights with one group share one image; greyed, "
            "a light without one is a group of its own");
    if (role == Qt::ToolTipRole && section == FalloffColumn)
        return tr("The distance falloff's range (— when none)");
    if (role == Qt::ToolTipRole && section == ShadowColumn)
        return tr("Whether the light casts a shadow (at most %1 lights)").arg(kMaxShadowCasters);
    return {};
}

Qt::ItemFlags LightTableModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::ItemIsDropEnabled;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled;
    const LightPropertyInfo* row = columnRow(index.column());
    const bool cell = m_doc && hasCell(row, m_doc->light(index.row()));
    if (index.column() == SoloColumn || (row && row->kind == LightValueKind::Bool && cell))
        f |= Qt::ItemIsUserCheckable;
    else if (cell && !(row && row->kind == LightValueKind::Bool))
        f |= Qt::ItemIsEditable;
    return f;
}

bool LightTableModel::refuse(const QString& reason) {
    m_lastError = reason;
    if (!reason.isEmpty()) emit editRefused(reason);
    return false;
}

bool LightTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid)) return false;
    return setDataForRows({index.row()}, index.column(), value, role);
}

bool LightTableModel::setDataForRows(const QList<int>& rows, int column, const QVariant& value, int role) {
    if (!m_doc || rows.isEmpty()) return false;
    m_lastError.clear();
    for (int r : rows)
        if (r < 0 || r >= m_doc->lightCount()) return refuse(tr("no light at row %1").arg(r));
    QString error;
    bool ok = false;
    const LightPropertyInfo* row = columnRow(column);
    if (column == SoloColumn && (role == Qt::CheckStateRole || role == Qt::EditRole)) {
        m_doc->setSoloed(rows, role == Qt::CheckStateRole ? value.toInt() == Qt::Checked : value.toBool());
        ok = true;
    } else if (role == Qt::CheckStateRole) {
        if (row && row->kind == LightValueKind::Bool)
            ok = m_doc->setLightValue(rows, row->id, value.toInt() == Qt::Checked, &error);
        else
            error = tr("this column has no checkbox");
    } else if (role == Qt::EditRole) {
        if (!row) {
            error = tr("this column cannot be edited");
        } else {
            QVariant v = value;
            if (row->kind == LightValueKind::Bool) v = value.toBool();
            // A number typed as text ("2.5") is fine; an empty optional number means "none".
            if (row->kind == LightValueKind::OptionalNumber && v.metaType().id() == QMetaType::QString &&
                v.toString().trimmed().isEmpty())
                v = QVariant();
            ok = m_doc->setLightValue(rows, row->id, v, &error);
        }
    } else {
        return false;
    }
    if (!ok) return refuse(error);
    return true;
}

// ---- drag and drop ----

QStringList LightTableModel::mimeTypes() const {
    return {QString::fromLatin1(kMimeType)};
}

QMimeData* LightTableModel::mimeData(const QModelIndexList& indexes) const {
    QList<int> rows;
    for (const QModelIndex& i : indexes)
        if (i.isValid() && i.model() == this) rows.append(i.row());
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    if (rows.isEmpty()) return nullptr;
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out << rows;
    auto* mime = new QMimeData;
    mime->setData(QString::fromLatin1(kMimeType), bytes);
    return mime;
}

namespace {
QList<int> decodeRows(const QMimeData* data) {
    QList<int> rows;
    if (!data || !data->hasFormat(QString::fromLatin1(LightTableModel::kMimeType))) return rows;
    QDataStream in(data->data(QString::fromLatin1(LightTableModel::kMimeType)));
    in >> rows;
    if (in.status() != QDataStream::Ok) rows.clear();
    return rows;
}
} // namespace

bool LightTableModel::canDropMimeData(const QMimeData* data, Qt::DropAction action, int, int,
                                      const QModelIndex&) const {
    return action == Qt::MoveAction && data && data->hasFormat(QString::fromLatin1(kMimeType));
}

bool LightTableModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int,
                                   const QModelIndex& parent) {
    if (!m_doc || action != Qt::MoveAction) return false;
    const QList<int> rows = decodeRows(data);
    if (rows.isEmpty()) return false;
    for (int r : rows)
        if (r < 0 || r >= m_doc->lightCount()) return false;
    // Dropped on an item: before it. Between items: at row. Below the last row: at the end.
    int destination = row;
    if (destination < 0) destination = parent.isValid() ? parent.row() : m_doc->lightCount();
    QString error;
    const bool ok = m_doc->moveLights(rows, destination, &error);
    if (!ok) refuse(error);
    return ok;
}

bool LightTableModel::moveRows(const QModelIndex& sourceParent, int sourceRow, int count,
                               const QModelIndex& destinationParent, int destinationChild) {
    if (!m_doc || sourceParent.isValid() || destinationParent.isValid() || count <= 0) return false;
    QList<int> rows;
    for (int i = 0; i < count; ++i)
        rows.append(sourceRow + i);
    QString error;
    if (!m_doc->moveLights(rows, destinationChild, &error)) return refuse(error);
    return true;
}

// ---- following the document ----

void LightTableModel::onAboutToChange(const RigChange& c) {
    switch (c.kind) {
    case RigChange::Inserted:
        beginInsertRows({}, c.first, c.last);
        break;
    case RigChange::Removed:
        beginRemoveRows({}, c.first, c.last);
        break;
    case RigChange::Moved:
        beginMoveRows({}, c.first, c.last, {}, c.destination);
        break;
    case RigChange::Reset:
        beginResetModel();
        break;
    case RigChange::Reordered:
        emit layoutAboutToBeChanged({}, QAbstractItemModel::VerticalSortHint);
        m_layoutPersistent = persistentIndexList();
        break;
    default:
        break;
    }
}

void LightTableModel::onChanged(const RigChange& c) {
    onStructureChanged(c);
    if (c.isStructural() && c.kind != RigChange::Reset) {
        // An unnamed light's own group is "light N" by its index, which insertions, removals and moves
        // change.
        for (int r = 0; r < rowCount(); ++r) {
            const Light& l = m_doc->light(r);
            if (ownGroup(l) && l.name.trimmed().isEmpty()) {
                emit dataChanged(index(0, GroupColumn), index(rowCount() - 1, GroupColumn));
                break;
            }
        }
    }
}

void LightTableModel::onStructureChanged(const RigChange& c) {
    switch (c.kind) {
    case RigChange::Inserted:
        endInsertRows();
        break;
    case RigChange::Removed:
        endRemoveRows();
        break;
    case RigChange::Moved:
        endMoveRows();
        break;
    case RigChange::Reset:
        endResetModel();
        break;
    case RigChange::Reordered: {
        QList<int> newRowOf(c.order.size());
        for (int i = 0; i < c.order.size(); ++i)
            newRowOf[c.order[i]] = i;
        QModelIndexList to;
        to.reserve(m_layoutPersistent.size());
        for (const QModelIndex& from : std::as_const(m_layoutPersistent))
            to << index(newRowOf.value(from.row(), from.row()), from.column());
        changePersistentIndexList(m_layoutPersistent, to);
        m_layoutPersistent.clear();
        emit layoutChanged({}, QAbstractItemModel::VerticalSortHint);
        break;
    }
    case RigChange::LightValues: {
        // The columns that show the property, or a value shown with it (lightproperty.h: shownWith); a type
        // change or several values: every column.
        int first = ColumnCount, last = -1;
        const bool all = c.lightProperty == LightProperty::Any || c.lightProperty == LightProperty::Type;
        const LightPropertyInfo* changed = lightPropertyInfo(c.lightProperty);
        for (int col = 0; col < ColumnCount; ++col) {
            const LightProperty p = kColumnProperty[col];
            if (all ||
                (p != LightProperty::Any && (p == c.lightProperty || (changed && changed->shownWith == p)))) {
                first = std::min(first, col);
                last = std::max(last, col);
            }
        }
        if (last < 0) return; // not shown in the table
        emit dataChanged(index(c.first, first), index(c.last, last));
        break;
    }
    case RigChange::RigValues:
        break;
    }
}

void LightTableModel::onSoloChanged() {
    if (rowCount() > 0)
        emit dataChanged(index(0, SoloColumn), index(rowCount() - 1, SoloColumn), {Qt::CheckStateRole});
}

} // namespace lr
