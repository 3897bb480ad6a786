#include "editor/lighttablemodel.h"

#include <QDataStream>
#include <QIODevice>
#include <QMimeData>
#include <algorithm>

namespace lr {

namespace {

QString typeLabel(LightType t) {
    QString s = toString(t);
    s[0] = s[0].toUpper();
    return s;
}

QString formatNumber(double v) {
    return QString::number(v, 'g', 4);
}

bool hasRangeColumn(const Light& l) {
    return l.usesFalloff() && l.falloff.model != FalloffModel::None;
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
    switch (column) {
    case NameColumn:
        return LightProperty::Name;
    case TypeColumn:
        return LightProperty::Type;
    case OnColumn:
        return LightProperty::Enabled;
    case ColorColumn:
        return LightProperty::Color;
    case IntensityColumn:
        return LightProperty::Intensity;
    case FalloffColumn:
        return LightProperty::FalloffRange;
    default:
        return LightProperty::Any;
    }
}

QVariant LightTableModel::data(const QModelIndex& index, int role) const {
    if (!m_doc || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Light& l = m_doc->light(index.row());
    const int col = index.column();
    switch (role) {
    case LightIdRole:
        return QVariant::fromValue(m_doc->lightId(index.row()));
    case PropertyRole:
        return propertyOf(col) == LightProperty::Any ? QVariant() : QVariant(int(propertyOf(col)));
    case Qt::CheckStateRole:
        if (col == OnColumn) return l.enabled ? Qt::Checked : Qt::Unchecked;
        if (col == SoloColumn) return m_doc->isSoloed(index.row()) ? Qt::Checked : Qt::Unchecked;
        return {};
    case Qt::DecorationRole:
        if (col == ColorColumn) return displayColor(l.effectiveColor());
        return {};
    case Qt::DisplayRole:
        switch (col) {
        case NameColumn:
            return l.name;
        case TypeColumn:
            return typeLabel(l.type);
        case IntensityColumn:
            return formatNumber(l.intensity);
        case FalloffColumn:
            return hasRangeColumn(l) && l.falloff.hasRange() ? formatNumber(l.falloff.range)
                                                             : QStringLiteral("—");
        default:
            return {};
        }
    case Qt::EditRole:
        switch (col) {
        case NameColumn:
            return l.name;
        case TypeColumn:
            return int(l.type);
        case ColorColumn:
            return QVariant::fromValue(l.color);
        case IntensityColumn:
            return l.intensity;
        case FalloffColumn:
            return hasRangeColumn(l) && l.falloff.hasRange() ? QVariant(l.falloff.range) : QVariant();
        default:
            return {};
        }
    case SortRole:
        switch (col) {
        case NameColumn:
            return l.name.toLower();
        case TypeColumn:
            return int(l.type);
        case OnColumn:
            return int(l.enabled);
        case SoloColumn:
            return int(m_doc->isSoloed(index.row()));
        case ColorColumn: {
            const glm::dvec3 c = l.effectiveColor();
            return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
        }
        case IntensityColumn:
            return l.intensity;
        case FalloffColumn:
            return hasRangeColumn(l) && l.falloff.hasRange() ? l.falloff.range : -1.0;
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
            if (!l.usesFalloff()) return tr("%1 lights have no distance falloff").arg(typeLabel(l.type));
            return tr("Falloff: %1").arg(toString(l.falloff.model));
        case SoloColumn:
            return tr("Solo: while any light is soloed, only soloed lights render (not saved)");
        default:
            return {};
        }
    case Qt::TextAlignmentRole:
        if (col == IntensityColumn || col == FalloffColumn) return int(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    default:
        return {};
    }
}

QVariant LightTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal) return QAbstractTableModel::headerData(section, orientation, role);
    if (role == Qt::DisplayRole) {
        switch (section) {
        case NameColumn:
            return tr("Name");
        case TypeColumn:
            return tr("Type");
        case OnColumn:
            return tr("On");
        case SoloColumn:
            return tr("Solo");
        case ColorColumn:
            return tr("Colour");
        case IntensityColumn:
            return tr("Intensity");
        case FalloffColumn:
            return tr("Range");
        default:
            return {};
        }
    }
    if (role == Qt::ToolTipRole && section == FalloffColumn)
        return tr("The distance falloff's range (— when none)");
    return {};
}

Qt::ItemFlags LightTableModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::ItemIsDropEnabled;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled;
    switch (index.column()) {
    case OnColumn:
    case SoloColumn:
        f |= Qt::ItemIsUserCheckable;
        break;
    case FalloffColumn:
        if (m_doc && hasRangeColumn(m_doc->light(index.row()))) f |= Qt::ItemIsEditable;
        break;
    default:
        f |= Qt::ItemIsEditable;
        break;
    }
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
    if (role == Qt::CheckStateRole) {
        const bool on = value.toInt() == Qt::Checked;
        if (column == OnColumn)
            ok = m_doc->setLightsEnabled(rows, on, &error);
        else if (column == SoloColumn) {
            m_doc->setSoloed(rows, on);
            ok = true;
        } else
            error = tr("this column has no checkbox");
    } else if (role == Qt::EditRole) {
        if (column == NameColumn) {
            if (rows.size() == 1)
                ok = m_doc->renameLight(rows.front(), value.toString(), &error);
            else
                ok = m_doc->setLightValue(rows, LightProperty::Name, value, &error);
        } else if (column == OnColumn) {
            ok = m_doc->setLightsEnabled(rows, value.toBool(), &error);
        } else if (column == SoloColumn) {
            m_doc->setSoloed(rows, value.toBool());
            ok = true;
        } else if (propertyOf(column) != LightProperty::Any) {
            QVariant v = value;
            // A number typed as text ("2.5") is fine; an empty range cell means "no range".
            if (column == FalloffColumn && v.metaType().id() == QMetaType::QString &&
                v.toString().trimmed().isEmpty())
                v = QVariant();
            ok = m_doc->setLightValue(rows, propertyOf(column), v, &error);
        } else {
            error = tr("this column cannot be edited");
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
        int first = 0, last = ColumnCount - 1;
        switch (c.lightProperty) {
        case LightProperty::Name:
            first = last = NameColumn;
            break;
        case LightProperty::Enabled:
            first = last = OnColumn;
            break;
        case LightProperty::Color:
        case LightProperty::Temperature:
            first = last = ColorColumn;
            break;
        case LightProperty::Intensity:
            first = last = IntensityColumn;
            break;
        case LightProperty::FalloffModel:
        case LightProperty::FalloffRange:
            first = last = FalloffColumn;
            break;
        case LightProperty::Type:
        case LightProperty::Any:
            break;
        default:
            return; // not shown in the table
        }
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
