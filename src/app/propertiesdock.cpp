#include "propertiesdock.h"

#include "colorbutton.h"
#include "colorpreview.h"
#include "directionangles.h"
#include "logslider.h"
#include "modeltooltips.h"
#include "numberedit.h"
#include "propertyfields.h"
#include "vec3edit.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace lr {

namespace {
using P = LightProperty;

template <typename E> QComboBox* enumCombo(QWidget* parent) {
    auto* combo = new QComboBox(parent);
    for (int i = 0; i < enumCount<E>(); ++i)
        combo->addItem(toString(E(i)));
    return combo;
}

QWidget* hbox(QWidget* parent, std::initializer_list<QWidget*> widgets) {
    auto* w = new QWidget(parent);
    auto* l = new QHBoxLayout(w);
    l->setContentsMargins(0, 0, 0, 0);
    for (QWidget* child : widgets)
        l->addWidget(child, child->inherits("QCheckBox") ? 0 : 1);
    return w;
}

void setCombo(QComboBox* combo, int index) {
    const QSignalBlocker block(combo);
    combo->setCurrentIndex(index);
}

void setCheck(QCheckBox* box, bool on) {
    const QSignalBlocker block(box);
    box->setChecked(on);
}
} // namespace

PropertiesDock::PropertiesDock(Document* document, QWidget* parent)
    : QDockWidget(tr("Properties"), parent), m_doc(document) {
    setObjectName(QStringLiteral("PropertiesDock"));
    m_idle.setSingleShot(true);
    m_idle.setInterval(1000);
    connect(&m_idle, &QTimer::timeout, this, &PropertiesDock::finishGesture);
    build();
    connect(m_doc, &Document::rigChanged, this, &PropertiesDock::refresh);
    connect(m_doc, &Document::selectionChanged, this, [this] {
        finishGesture();
        showMessage(QString());
        refresh();
    });
    refresh();
}

PropertiesDock::~PropertiesDock() {
    finishGesture();
}

QString PropertiesDock::message() const {
    return m_message->text();
}

void PropertiesDock::addRow(LightProperty property, const QString& label, QWidget* field) {
    field->setObjectName(propertyFieldName(property));
    m_form->addRow(label, field);
    m_fields.insert(property, field);
}

NumberEdit* PropertiesDock::addNumber(LightProperty property, const QString& label, double min, double max,
                                      bool minExclusive, const QString& suffix) {
    auto* e = new NumberEdit(m_panel);
    e->setLimits(min, max, minExclusive);
    e->setWhat(lightPropertyName(property));
    e->setSuffix(suffix);
    addRow(property, label, e);
    m_numbers.insert(property, e);
    connect(e, &NumberEdit::valueEdited, this, [this, property](double v) { apply(property, v, true); });
    connect(e, &QAbstractSpinBox::editingFinished, this, &PropertiesDock::finishGesture);
    connect(e, &NumberEdit::rejected, this, &PropertiesDock::showMessage);
    return e;
}

void PropertiesDock::build() {
    m_panel = new QWidget;
    auto* outer = new QVBoxLayout(m_panel);
    m_header = new QLabel(m_panel);
    m_header->setObjectName(QStringLiteral("header"));
    m_header->setWordWrap(true);
    outer->addWidget(m_header);
    m_form = new QFormLayout;
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    outer->addLayout(m_form);
    m_message = new QLabel(m_panel);
    m_message->setObjectName(QStringLiteral("message"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->setStyleSheet(QStringLiteral("color: #d04030"));
    outer->addWidget(m_message);
    outer->addStretch(1);

    m_name = new QLineEdit(m_panel);
    m_name->setMaxLength(kMaxLightNameLength);
    addRow(P::Name, tr("&Name"), m_name);
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const QList<int> rows = m_doc->selectedRows();
        if (rows.size() != 1 || m_name->text() == m_doc->light(rows.first()).name) return;
        QString error;
        if (!m_doc->renameLight(rows.first(), m_name->text().trimmed(), &error)) showMessage(error);
        refresh();
    });

    m_type = enumCombo<LightType>(m_panel);
    addRow(P::Type, tr("&Type"), m_type);
    connect(m_type, &QComboBox::activated, this,
            [this](int i) { apply(P::Type, toString(LightType(i)), false); });

    m_enabled = new QCheckBox(tr("On"), m_panel);
    addRow(P::Enabled, tr("&Enabled"), m_enabled);
    connect(m_enabled, &QCheckBox::clicked, this, [this](bool on) {
        QString error;
        if (!m_doc->setLightsEnabled(m_doc->selectedRows(), on, &error)) showMessage(error);
    });

    m_color = new ColorButton(m_panel);
    previewColorEdits(m_color, m_doc, P::Color); // live preview while the dialog is open
    addRow(P::Color, tr("&Colour"), m_color);
    connect(m_color, &ColorButton::colorPicked, this,
            [this](const glm::dvec3& c) { apply(P::Color, QVariant::fromValue(c), false); });

    m_temperatureOn = new QCheckBox(m_panel);
    m_temperatureOn->setToolTip(tr("Tint the colour by a black body's temperature"));
    m_temperature = new NumberEdit(m_panel);
    m_temperature->setLimits(kMinTemperature, kMaxTemperature);
    m_temperature->setWhat(lightPropertyName(P::Temperature));
    m_temperature->setSuffix(QStringLiteral(" K"));
    m_temperature->setValueQuietly(6500.0);
    addRow(P::Temperature, tr("Te&mperature"), hbox(m_panel, {m_temperatureOn, m_temperature}));
    connect(m_temperatureOn, &QCheckBox::clicked, this, [this](bool on) {
        apply(P::Temperature, on ? QVariant(m_temperature->value()) : QVariant(), false);
    });
    connect(m_temperature, &NumberEdit::valueEdited, this,
            [this](double v) { apply(P::Temperature, v, true); });
    connect(m_temperature, &QAbstractSpinBox::editingFinished, this, &PropertiesDock::finishGesture);
    connect(m_temperature, &NumberEdit::rejected, this, &PropertiesDock::showMessage);

    m_intensity = new LogSliderEdit(m_panel);
    m_intensity->setLimits(1e-3, kMaxIntensity);
    m_intensity->spinBox()->setWhat(lightPropertyName(P::Intensity));
    addRow(P::Intensity, tr("&Intensity"), m_intensity);
    connect(m_intensity, &LogSliderEdit::valueEdited, this,
            [this](double v) { apply(P::Intensity, v, true); });
    connect(m_intensity, &LogSliderEdit::editFinished, this, &PropertiesDock::finishGesture);
    connect(m_intensity->spinBox(), &NumberEdit::rejected, this, &PropertiesDock::showMessage);

    auto vec3Row = [this](LightProperty property, const QString& label) {
        auto* v = new Vec3Edit(m_panel);
        v->setLimits(-kMaxCoordinate, kMaxCoordinate);
        v->setWhat(lightPropertyName(property));
        addRow(property, label, v);
        connect(v, &Vec3Edit::componentEdited, this,
                [this, property](int axis, double value) { applyComponent(property, axis, value); });
        connect(v, &Vec3Edit::editFinished, this, &PropertiesDock::finishGesture);
        connect(v, &Vec3Edit::rejected, this, &PropertiesDock::showMessage);
        return v;
    };
    m_position = vec3Row(P::Position, tr("&Position"));
    m_direction = vec3Row(P::Direction, tr("&Direction"));
    addDirectionAngles(m_form, m_direction, m_doc); // azimuth/elevation below x, y, z (directionangles.h)

    m_falloff = enumCombo<FalloffModel>(m_panel);
    installModelTooltips<FalloffModel>(m_falloff);
    addRow(P::FalloffModel, tr("&Falloff"), m_falloff);
    connect(m_falloff, &QComboBox::activated, this,
            [this](int i) { apply(P::FalloffModel, toString(FalloffModel(i)), false); });

    m_rangeOn = new QCheckBox(m_panel);
    m_rangeOn->setToolTip(tr("Limit the light to a range (optional for this falloff model)"));
    m_range = new NumberEdit(m_panel);
    m_range->setLimits(0.0, kMaxCoordinate, true);
    m_range->setWhat(lightPropertyName(P::FalloffRange));
    m_range->setValueQuietly(10.0);
    addRow(P::FalloffRange, tr("&Range"), hbox(m_panel, {m_rangeOn, m_range}));
    connect(m_rangeOn, &QCheckBox::clicked, this,
            [this](bool on) { apply(P::FalloffRange, on ? QVariant(m_range->value()) : QVariant(), false); });
    connect(m_range, &NumberEdit::valueEdited, this, [this](double v) { apply(P::FalloffRange, v, true); });
    connect(m_range, &QAbstractSpinBox::editingFinished, this, &PropertiesDock::finishGesture);
    connect(m_range, &NumberEdit::rejected, this, &PropertiesDock::showMessage);

    addNumber(P::FalloffExponent, tr("Falloff e&xponent"), 0.0, kMaxExponent, true);
    addNumber(P::FalloffConstant, tr("Consta&nt"), 0.0, kMaxPolynomialCoefficient, false);
    addNumber(P::FalloffLinear, tr("&Linear"), 0.0, kMaxPolynomialCoefficient, false);
    addNumber(P::FalloffQuadratic, tr("&Quadratic"), 0.0, kMaxPolynomialCoefficient, false);

    m_cone = enumCombo<ConeModel>(m_panel);
    installModelTooltips<ConeModel>(m_cone);
    addRow(P::ConeModel, tr("C&one"), m_cone);
    connect(m_cone, &QComboBox::activated, this,
            [this](int i) { apply(P::ConeModel, toString(ConeModel(i)), false); });
    addNumber(P::ConeInner, tr("Inner an&gle"), 0.0, 90.0, true, QStringLiteral("°"));
    addNumber(P::ConeOuter, tr("O&uter angle"), 0.0, 90.0, true, QStringLiteral("°"));
    addNumber(P::ConeExponent, tr("Cone exponen&t"), 0.0, kMaxExponent, true);

    m_diffuse = enumCombo<DiffuseModel>(m_panel);
    installModelTooltips<DiffuseModel>(m_diffuse);
    addRow(P::Diffuse, tr("Di&ffuse"), m_diffuse);
    connect(m_diffuse, &QComboBox::activated, this,
            [this](int i) { apply(P::Diffuse, toString(DiffuseModel(i)), false); });

    m_specularKind = new QComboBox(m_panel);
    m_specularKind->addItems({tr("factor"), tr("colour")});
    m_specularFactor = new NumberEdit(m_panel);
    m_specularFactor->setLimits(0.0, kMaxColorComponent);
    m_specularFactor->setWhat(lightPropertyName(P::Specular));
    m_specularColor = new ColorButton(m_panel);
    previewColorEdits(m_specularColor, m_doc, P::Specular);
    addRow(P::Specular, tr("&Specular"), hbox(m_panel, {m_specularKind, m_specularFactor, m_specularColor}));
    connect(m_specularKind, &QComboBox::activated, this, [this](int kind) {
        apply(P::Specular,
              kind == 0 ? QVariant(m_specularFactor->value()) : QVariant::fromValue(m_specularColor->color()),
              false);
    });
    connect(m_specularFactor, &NumberEdit::valueEdited, this,
            [this](double v) { apply(P::Specular, v, true); });
    connect(m_specularFactor, &QAbstractSpinBox::editingFinished, this, &PropertiesDock::finishGesture);
    connect(m_specularFactor, &NumberEdit::rejected, this, &PropertiesDock::showMessage);
    connect(m_specularColor, &ColorButton::colorPicked, this,
            [this](const glm::dvec3& c) { apply(P::Specular, QVariant::fromValue(c), false); });

    m_ambientOn = new QCheckBox(m_panel);
    m_ambientOn->setToolTip(tr("The light's own ambient term (attenuated like the rest of the light)"));
    m_ambient = new ColorButton(m_panel);
    previewColorEdits(m_ambient, m_doc, P::Ambient);
    addRow(P::Ambient, tr("&Ambient"), hbox(m_panel, {m_ambientOn, m_ambient}));
    connect(m_ambientOn, &QCheckBox::clicked, this, [this](bool on) {
        apply(P::Ambient, on ? QVariant::fromValue(m_ambient->color()) : QVariant(), false);
    });
    connect(m_ambient, &ColorButton::colorPicked, this,
            [this](const glm::dvec3& c) { apply(P::Ambient, QVariant::fromValue(c), false); });

    addNumber(P::RimExponent, tr("Rim e&xponent"), 0.0, kMaxExponent, true);

    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setWidget(m_panel);
    setWidget(scroll);
}

void PropertiesDock::apply(LightProperty property, const QVariant& value, bool continuous) {
    const QList<int> rows = m_doc->selectedRows();
    if (rows.isEmpty()) return;
    if (continuous && !m_editToken) m_editToken = m_doc->beginContinuousEdit();
    if (continuous) m_idle.start();
    QString error;
    if (m_doc->setLightValue(rows, property, value, &error)) {
        showMessage(QString());
    } else {
        showMessage(error);
        refresh(); // show the stored values again: the refused one was never applied
    }
    if (!continuous) finishGesture();
}

void PropertiesDock::applyComponent(LightProperty property, int axis, double value) {
    const QList<int> rows = m_doc->selectedRows();
    if (rows.isEmpty()) return;
    if (!m_editToken) m_editToken = m_doc->beginContinuousEdit();
    m_idle.start();
    QVariantList values;
    QList<int> applied;
    for (int row : rows) {
        const Light& l = m_doc->light(row);
        if (!lightPropertyApplies(l, property)) continue;
        glm::dvec3 v = property == P::Position ? l.position : l.direction;
        v[axis] = value;
        values.append(QVariant::fromValue(v));
        applied.append(row);
    }
    QString error;
    if (!applied.isEmpty() && m_doc->setLightValues(applied, property, values, &error)) {
        showMessage(QString());
    } else {
        showMessage(error);
        refresh();
    }
}

void PropertiesDock::finishGesture() {
    m_idle.stop();
    if (m_editToken) m_doc->endContinuousEdit(*std::exchange(m_editToken, std::nullopt));
}

void PropertiesDock::showMessage(const QString& text) {
    m_message->setText(text);
}

void PropertiesDock::refresh() {
    const QList<int> rows = m_doc->selectedRows();
    int current = m_doc->currentRow();
    if (current < 0 && !rows.isEmpty()) current = rows.first();
    if (rows.isEmpty() || current < 0) {
        m_header->setText(m_doc->lightCount() ? tr("Select a light to edit it.")
                                              : tr("Add a light to edit it."));
        for (QWidget* f : std::as_const(m_fields))
            m_form->setRowVisible(f, false);
        return;
    }
    const Light& light = m_doc->light(current);
    m_header->setText(rows.size() == 1
                          ? tr("<b>%1</b> (%2 light)").arg(light.name.toHtmlEscaped(), toString(light.type))
                          : tr("<b>%1 lights</b> selected: edits apply to all of them. Showing %2's values.")
                                .arg(rows.size())
                                .arg(light.name.toHtmlEscaped()));
    updateVisibility(rows);
    loadValues(light);
    m_name->setEnabled(rows.size() == 1);
    bool mixedColor = false;
    for (int row : rows)
        mixedColor = mixedColor || m_doc->light(row).color != light.color;
    if (mixedColor) m_color->setMixed(true);
}

void PropertiesDock::updateVisibility(const QList<int>& rows) {
    for (LightProperty property : propertyRows()) {
        bool shown = true;
        for (int row : rows) {
            if (!propertyShown(m_doc->light(row), property)) {
                shown = false;
                break;
            }
        }
        m_form->setRowVisible(m_fields.value(property), shown);
    }
}

void PropertiesDock::loadValues(const Light& light) {
    if (!m_name->hasFocus() || m_name->text() != light.name) m_name->setText(light.name);
    setCombo(m_type, int(light.type));
    setCheck(m_enabled, light.enabled);
    m_color->setColor(light.color);
    setCheck(m_temperatureOn, light.temperature.has_value());
    if (light.temperature) m_temperature->setValueQuietly(*light.temperature);
    m_temperature->setEnabled(light.temperature.has_value());
    m_intensity->setValue(light.intensity);
    m_position->setValue(light.position);
    m_direction->setValue(light.direction);
    const Falloff& f = light.falloff;
    setCombo(m_falloff, int(f.model));
    const bool rangeOptional =
        f.model == FalloffModel::InversePolynomial || f.model == FalloffModel::InverseSquare;
    m_rangeOn->setVisible(rangeOptional);
    setCheck(m_rangeOn, f.hasRange());
    if (f.hasRange()) m_range->setValueQuietly(f.range);
    m_range->setEnabled(f.hasRange() || !rangeOptional);
    m_numbers[P::FalloffExponent]->setValueQuietly(f.exponent);
    m_numbers[P::FalloffConstant]->setValueQuietly(f.constant);
    m_numbers[P::FalloffLinear]->setValueQuietly(f.linear);
    m_numbers[P::FalloffQuadratic]->setValueQuietly(f.quadratic);
    setCombo(m_cone, int(light.cone.model));
    m_numbers[P::ConeInner]->setValueQuietly(light.cone.inner);
    m_numbers[P::ConeOuter]->setValueQuietly(light.cone.outer);
    m_numbers[P::ConeExponent]->setValueQuietly(light.cone.exponent);
    setCombo(m_diffuse, int(light.diffuse));
    setCombo(m_specularKind, light.specularIsColor ? 1 : 0);
    m_specularFactor->setVisible(!light.specularIsColor);
    m_specularColor->setVisible(light.specularIsColor);
    if (light.specularIsColor)
        m_specularColor->setColor(light.specular);
    else
        m_specularFactor->setValueQuietly(light.specular.x);
    if (!light.specularIsColor) m_specularColor->setColor(light.specular);
    setCheck(m_ambientOn, light.ambient.has_value());
    m_ambient->setColor(light.ambient.value_or(glm::dvec3(0.05)));
    m_ambient->setEnabled(light.ambient.has_value());
    m_numbers[P::RimExponent]->setValueQuietly(light.rimExponent);
}

} // namespace lr
