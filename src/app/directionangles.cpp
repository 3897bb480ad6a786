#include "directionangles.h"

#include "editor/document.h"
#include "numberedit.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace lr {

DirectionAngles directionAngles(const glm::dvec3& direction) {
    const double len = glm::length(direction);
    if (!(len > 0.0) || !std::isfinite(len)) return {};
    const glm::dvec3 d = direction / len;
    DirectionAngles a;
    a.elevation = glm::degrees(std::asin(std::clamp(d.y, -1.0, 1.0))); // clamped: asin's domain
    const double horizontal = std::hypot(d.x, d.z);
    a.azimuth = horizontal > 1e-12 ? glm::degrees(std::atan2(d.x, -d.z)) : 0.0;
    if (a.azimuth <= -180.0) a.azimuth = 180.0;
    return a;
}

glm::dvec3 directionFromAngles(const DirectionAngles& a) {
    const double az = glm::radians(a.azimuth), el = glm::radians(a.elevation);
    return {std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az)};
}

DirectionAnglesEdit::DirectionAnglesEdit(Document* document, QFormLayout* form, QWidget* parent)
    : QWidget(parent), m_doc(document), m_form(form), m_azimuth(new NumberEdit(this)),
      m_elevation(new NumberEdit(this)) {
    setObjectName(QStringLiteral("directionAngles"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_azimuth->setObjectName(QStringLiteral("directionAzimuth"));
    m_azimuth->setLimits(-180.0, 180.0);
    m_azimuth->setWhat(tr("azimuth"));
    m_azimuth->setPrefix(tr("az "));
    m_azimuth->setSuffix(QStringLiteral("°"));
    m_azimuth->setToolTip(tr("Azimuth: the direction's angle around the vertical (y) axis. 0° travels "
                             "towards −Z, 90° towards +X, ±180° towards +Z"));
    m_elevation->setObjectName(QStringLiteral("directionElevation"));
    m_elevation->setLimits(-90.0, 90.0);
    m_elevation->setWhat(tr("elevation"));
    m_elevation->setPrefix(tr("el "));
    m_elevation->setSuffix(QStringLiteral("°"));
    m_elevation->setToolTip(tr("Elevation: the direction's angle above the horizontal plane. −90° shines "
                               "straight down, 90° straight up"));
    layout->addWidget(m_azimuth, 1);
    layout->addWidget(m_elevation, 1);
    connect(m_azimuth, &NumberEdit::valueEdited, this, [this](double v) { apply(true, v); });
    connect(m_elevation, &NumberEdit::valueEdited, this, [this](double v) { apply(false, v); });
    m_idle.setSingleShot(true);
    m_idle.setInterval(1000);
    connect(&m_idle, &QTimer::timeout, this, [this] { m_edit.reset(); });
    for (NumberEdit* e : {m_azimuth, m_elevation})
        connect(e, &QAbstractSpinBox::editingFinished, this, [this] { m_edit.reset(); });
    connect(m_doc, &Document::rigChanged, this, &DirectionAnglesEdit::refresh);
    connect(m_doc, &Document::selectionChanged, this, [this] {
        m_edit.reset();
        refresh();
    });
}

DirectionAnglesEdit::~DirectionAnglesEdit() = default;

void DirectionAnglesEdit::refresh() {
    const QList<int> rows = m_doc->selectedRows();
    bool shown = !rows.isEmpty();
    for (int row : rows)
        shown = shown && m_doc->light(row).usesDirection();
    if (m_form) m_form->setRowVisible(this, shown);
    if (!shown) return;
    int current = m_doc->currentRow();
    if (current < 0 || !rows.contains(current)) current = rows.first();
    const DirectionAngles a = directionAngles(m_doc->light(current).direction);
    // The field being typed in keeps its text; a vertical direction keeps the azimuth shown.
    if (!m_azimuth->hasFocus() && std::abs(a.elevation) < 90.0 - 1e-9) m_azimuth->setValueQuietly(a.azimuth);
    if (!m_elevation->hasFocus()) m_elevation->setValueQuietly(a.elevation);
}

void DirectionAnglesEdit::apply(bool azimuth, double degrees) {
    QList<int> rows;
    QVariantList values;
    for (int row : m_doc->selectedRows()) {
        const Light& l = m_doc->light(row);
        if (!l.usesDirection()) continue;
        DirectionAngles a = directionAngles(l.direction);
        if (std::abs(a.elevation) >= 90.0 - 1e-9) a.azimuth = m_azimuth->value(); // vertical: no azimuth
        (azimuth ? a.azimuth : a.elevation) = degrees;
        rows.append(row);
        values.append(QVariant::fromValue(directionFromAngles(a)));
    }
    if (rows.isEmpty()) return;
    if (!m_edit) m_edit = std::make_unique<ContinuousEdit>(m_doc);
    m_idle.start();
    m_doc->setLightValues(rows, LightProperty::Direction, values);
}

DirectionAnglesEdit* addDirectionAngles(QFormLayout* form, QWidget* directionField, Document* document) {
    int row = -1;
    QFormLayout::ItemRole role;
    form->getWidgetPosition(directionField, &row, &role);
    auto* edit = new DirectionAnglesEdit(document, form, directionField->parentWidget());
    auto* label = new QLabel(QObject::tr("Azimuth, ele&vation"), directionField->parentWidget());
    label->setBuddy(edit->azimuth());
    if (row >= 0)
        form->insertRow(row + 1, label, edit);
    else
        form->addRow(label, edit);
    edit->refresh();
    return edit;
}

} // namespace lr
