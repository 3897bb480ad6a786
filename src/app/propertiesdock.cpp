#include "propertiesdock.h"

#include "colorbutton.h"
#include "colorpreview.h"
#include "core/lightgroups.h"
#include "directionangles.h"
#include "iessummary.h"
#include "linkingsection.h"
#include "logslider.h"
#include "modeltooltips.h"
#include "numberedit.h"
#include "propertyfields.h"
#include "vec3edit.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>

namespace lr {

namespace {
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
    askOpenFile = [this](const QString& title, const QString& folder, const QString& filter) {
        return QFileDialog::getOpenFileName(this, title, folder, filter);
    };
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

void PropertiesDock::connectNumber(LightProperty property, NumberEdit* e) {
    connect(e, &NumberEdit::valueEdited, this, [this, property](double v) { apply(property, v, true); });
    connect(e, &QAbstractSpinBox::editingFinished, this, &PropertiesDock::finishGesture);
    connect(e, &NumberEdit::rejected, this, &PropertiesDock::showMessage);
}

// A File row: its line edit and a "…" button that chooses the file (starting in the current file's folder,
// else the rig's), stored relative to the rig's folder when it lies there (fileFieldValue).
QWidget* PropertiesDock::fileField(const LightPropertyInfo& row, QLineEdit* line, const char* filter) {
    auto* browse = new QToolButton(m_panel);
    browse->setText(QStringLiteral("…"));
    browse->setObjectName(QString::fromLatin1(row.key) + QStringLiteral("Browse"));
    browse->setToolTip(tr("Choose the %1 file").arg(row.displayName()));
    const LightProperty p = row.id;
    connect(browse, &QToolButton::clicked, this, [this, p, line, filter, name = row.displayName()] {
        if (m_doc->selectedRows().isEmpty()) return;
        const QString rigFolder =
            m_doc->filePath().isEmpty() ? QDir::currentPath() : QFileInfo(m_doc->filePath()).absolutePath();
        const QString current = line->text().trimmed();
        const QString folder = current.isEmpty()
                                   ? rigFolder
                                   : QFileInfo(QDir(rigFolder).absoluteFilePath(current)).absolutePath();
        const QString chosen = askOpenFile(tr("Choose the %1").arg(name), folder, tr(filter ? filter : ""));
        if (chosen.isEmpty()) return;
        apply(p, fileFieldValue(chosen, m_doc->filePath()), false);
        refresh();
    });
    auto* w = new QWidget(m_panel);
    auto* l = new QHBoxLayout(w);
    l->setContentsMargins(0, 0, 0, 0);
    l->addWidget(line, 1);
    l->addWidget(browse, 0);
    return w;
}

PropertiesDock::Field PropertiesDock::createField(const LightPropertyInfo& row) {
    const LightProperty p = row.id;
    const PropertyField how = propertyField(p);
    Field f;
    auto number = [&] {
        auto* e = new NumberEdit(m_panel);
        e->setLimits(row.min, row.max, row.minExclusive);
        e->setWhat(row.displayName());
        if (row.suffix) e->setSuffix(QString::fromUtf8(row.suffix));
        return e;
    };
    auto toggle = [&] {
        auto* box = new QCheckBox(m_panel);
        box->setToolTip(tr("Whether the light has a %1").arg(row.displayName()));
        return box;
    };
    switch (how.editor) {
    case PropertyEditor::LineEdit:
    case PropertyEditor::File:
        f.widget = f.line = new QLineEdit(m_panel);
        f.line->setMaxLength(kMaxLightNameLength);
        connect(f.line, &QLineEdit::editingFinished, this,
                [this, p, unique = row.uniquePerLight, line = f.line] {
                    const QList<int> rows = m_doc->selectedRows();
                    if (rows.isEmpty() || (unique && rows.size() != 1)) return;
                    const QString text = line->text().trimmed();
                    bool same = true;
                    for (int r : rows)
                        same = same && lightValue(m_doc->light(r), p).toString() == text;
                    // Lights with different values show none: leaving the field untouched changes nothing.
                    if (same || (rows.size() > 1 && !line->isModified())) return;
                    apply(p, text, false);
                    line->setModified(false);
                    refresh();
                });
        if (how.editor == PropertyEditor::File) f.widget = fileField(row, f.line, how.fileFilter);
        break;
    case PropertyEditor::ComboBox:
        f.widget = f.combo = new QComboBox(m_panel);
        f.combo->addItems(row.choices());
        connect(f.combo, &QComboBox::activated, this, [this, p](int i) { apply(p, i, false); });
        break;
    case PropertyEditor::CheckBox:
        f.widget = f.check = new QCheckBox(tr("On"), m_panel);
        connect(f.check, &QCheckBox::clicked, this, [this, p](bool on) { apply(p, on, false); });
        break;
    case PropertyEditor::ColorButton:
        f.widget = f.color = new ColorButton(m_panel);
        connect(f.color, &ColorButton::colorPicked, this,
                [this, p](const glm::dvec3& c) { apply(p, QVariant::fromValue(c), false); });
        break;
    case PropertyEditor::Number:
        f.widget = f.number = number();
        connectNumber(p, f.number);
        break;
    case PropertyEditor::LogSlider:
        f.widget = f.slider = new LogSliderEdit(m_panel);
        f.slider->setLimits(how.sliderMin, row.max);
        f.slider->spinBox()->setWhat(row.displayName());
        f.number = f.slider->spinBox();
        connect(f.slider, &LogSliderEdit::valueEdited, this, [this, p](double v) { apply(p, v, true); });
        connect(f.slider, &LogSliderEdit::editFinished, this, &PropertiesDock::finishGesture);
        connect(f.number, &NumberEdit::rejected, this, &PropertiesDock::showMessage);
        break;
    case PropertyEditor::OptionalNumber:
        f.check = toggle();
        f.number = number();
        f.number->setValueQuietly(how.initial);
        f.widget = hbox(m_panel, {f.check, f.number});
        connect(f.check, &QCheckBox::clicked, this, [this, p, e = f.number](bool on) {
            apply(p, on ? QVariant(e->value()) : QVariant(), false);
        });
        connectNumber(p, f.number);
        break;
    case PropertyEditor::OptionalColor:
        f.check = toggle();
        f.color = new ColorButton(m_panel);
        f.widget = hbox(m_panel, {f.check, f.color});
        connect(f.check, &QCheckBox::clicked, this, [this, p, c = f.color](bool on) {
            apply(p, on ? QVariant::fromValue(c->color()) : QVariant(), false);
        });
        connect(f.color, &ColorButton::colorPicked, this,
                [this, p](const glm::dvec3& c) { apply(p, QVariant::fromValue(c), false); });
        break;
    case PropertyEditor::Vector:
        f.widget = f.vector = new Vec3Edit(m_panel);
        f.vector->setLimits(row.min, row.max);
        f.vector->setWhat(row.displayName());
        connect(f.vector, &Vec3Edit::componentEdited, this,
                [this, p](int axis, double value) { applyComponent(p, axis, value); });
        connect(f.vector, &Vec3Edit::editFinished, this, &PropertiesDock::finishGesture);
        connect(f.vector, &Vec3Edit::rejected, this, &PropertiesDock::showMessage);
        break;
    case PropertyEditor::PowerOfTwo:
        f.widget = f.combo = new QComboBox(m_panel);
        for (double v = std::max(1.0, row.min); v <= row.max; v *= 2.0)
            f.combo->addItem(QString::number(v) + QString::fromUtf8(row.suffix ? row.suffix : ""), v);
        connect(f.combo, &QComboBox::activated, this,
                [this, p, c = f.combo](int i) { apply(p, c->itemData(i), false); });
        break;
    case PropertyEditor::FactorOrColor:
        f.combo = new QComboBox(m_panel);
        f.combo->addItems({tr("factor"), tr("colour")});
        f.number = new NumberEdit(m_panel);
        f.number->setLimits(row.min, row.max);
        f.number->setWhat(row.displayName());
        f.color = new ColorButton(m_panel);
        f.widget = hbox(m_panel, {f.combo, f.number, f.color});
        connect(f.combo, &QComboBox::activated, this, [this, p, e = f.number, c = f.color](int kind) {
            apply(p, kind == 0 ? QVariant(e->value()) : QVariant::fromValue(c->color()), false);
        });
        connectNumber(p, f.number);
        connect(f.color, &ColorButton::colorPicked, this,
                [this, p](const glm::dvec3& c) { apply(p, QVariant::fromValue(c), false); });
        break;
    }
    return f;
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
    m_linking = new LinkingSection(m_doc, m_panel); // issue 38: a section of its own, not a form row
    connect(m_linking, &LinkingSection::refused, this, &PropertiesDock::showMessage);
    outer->addWidget(m_linking);
    m_message = new QLabel(m_panel);
    m_message->setObjectName(QStringLiteral("message"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->setStyleSheet(QStringLiteral("color: #d04030"));
    outer->addWidget(m_message);
    outer->addStretch(1);

    for (const LightPropertyInfo& row : lightProperties()) {
        if (row.kind == LightValueKind::Link) continue; // the Linking section
        const Field f = createField(row);
        f.widget->setObjectName(propertyFieldName(row.id));
        m_form->addRow(row.displayLabel(), f.widget);
        m_fields.insert(row.id, f.widget);
        m_parts.insert(row.id, f);
        // Hooks of their own files: live colour preview (colorpreview.h), the models' tooltips
        // (modeltooltips.h) and azimuth/elevation below a direction's x, y, z (directionangles.h).
        if (f.color && (row.id == LightProperty::Color || row.id == LightProperty::Specular ||
                        row.id == LightProperty::Ambient))
            previewColorEdits(f.color, m_doc, row.id);
        if (f.combo && row.id == LightProperty::FalloffModel) installModelTooltips<FalloffModel>(f.combo);
        if (f.combo && row.id == LightProperty::ConeModel) installModelTooltips<ConeModel>(f.combo);
        if (f.combo && row.id == LightProperty::Diffuse) installModelTooltips<DiffuseModel>(f.combo);
        if (row.id == LightProperty::Direction) addDirectionAngles(m_form, f.widget, m_doc);
        if (row.id == LightProperty::IesFile) addIesSummary(m_form, f.widget, m_doc); // peak, beam angle
    }

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
    // Typing x, y and z is one step: the gesture lasts until focus leaves the vector
    // (Vec3Edit::editFinished), however long the pauses between the components.
    if (!m_editToken) m_editToken = m_doc->beginContinuousEdit();
    m_idle.stop();
    QVariantList values;
    QList<int> applied;
    for (int row : rows) {
        const Light& l = m_doc->light(row);
        if (!lightPropertyApplies(l, property)) continue;
        glm::dvec3 v = lightValue(l, property).value<glm::dvec3>();
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
        m_linking->setVisible(false);
        m_linking->refresh();
        return;
    }
    const Light& light = m_doc->light(current);
    m_header->setText(rows.size() == 1
                          ? tr("<b>%1</b> (%2 light)").arg(light.name.toHtmlEscaped(), toString(light.type))
                          : tr("<b>%1 lights</b> selected: edits apply to all of them. Showing %2's values.")
                                .arg(rows.size())
                                .arg(light.name.toHtmlEscaped()));
    updateVisibility(rows);
    // The intensity's unit (issue 41): the one all selected lights share, none when they differ.
    QString unit = intensitySuffix(light.type, m_doc->rig().shading.model);
    for (int r : rows)
        if (intensitySuffix(m_doc->light(r).type, m_doc->rig().shading.model) != unit) unit.clear();
    if (NumberEdit* e = m_parts[LightProperty::Intensity].number) e->setSuffix(unit);
    m_linking->setVisible(true);
    m_linking->refresh();
    for (const LightPropertyInfo& row : lightProperties()) {
        if (row.kind == LightValueKind::Link) continue;
        const Field& f = m_parts[row.id];
        loadValue(row, f, light);
        // A value each light has for itself (the name) is edited with one light selected.
        if (row.uniquePerLight) f.widget->setEnabled(rows.size() == 1);
        if (f.line && !row.uniquePerLight) loadSharedText(row, f.line, rows, current);
        if (f.color && row.kind == LightValueKind::Color) {
            bool mixed = false;
            for (int r : rows)
                mixed = mixed || row.get(m_doc->light(r)) != row.get(light);
            if (mixed) f.color->setMixed(true);
        }
    }
}

void PropertiesDock::loadSharedText(const LightPropertyInfo& row, QLineEdit* line, const QList<int>& rows,
                                    int current) {
    const QVariant value = row.get(m_doc->light(current));
    bool mixed = false;
    for (int r : rows)
        mixed = mixed || row.get(m_doc->light(r)) != value;
    if (mixed && !line->hasFocus()) line->setText(QString()); // not modified: leaving it edits nothing
    QString placeholder;
    if (mixed)
        placeholder = tr("(several values)");
    else if (row.id == LightProperty::Group) // issue 37: without a group, a light is a group of its own
        placeholder = rows.size() == 1 ? lightGroupName(m_doc->light(current), current)
                                       : tr("(each light its own group)");
    line->setPlaceholderText(placeholder);
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

void PropertiesDock::loadValue(const LightPropertyInfo& row, const Field& f, const Light& light) {
    const QVariant value = row.get(light);
    switch (propertyField(row.id).editor) {
    case PropertyEditor::LineEdit:
    case PropertyEditor::File:
        if (!f.line->hasFocus() || f.line->text() != value.toString()) f.line->setText(value.toString());
        break;
    case PropertyEditor::ComboBox:
        setCombo(f.combo, value.toInt());
        break;
    case PropertyEditor::CheckBox:
        setCheck(f.check, value.toBool());
        break;
    case PropertyEditor::PowerOfTwo:
        setCombo(f.combo, f.combo->findData(value.toDouble()));
        break;
    case PropertyEditor::ColorButton:
        f.color->setColor(value.value<glm::dvec3>());
        break;
    case PropertyEditor::Number:
        f.number->setValueQuietly(value.toDouble());
        break;
    case PropertyEditor::LogSlider:
        f.slider->setValue(value.toDouble());
        break;
    case PropertyEditor::OptionalNumber: {
        // The "has a value" box only where "none" is allowed for this light (a range-power falloff needs
        // its range; an inverse-square one may have none).
        const bool noneAllowed = validateLightValue(light, row.id, QVariant()).isEmpty();
        f.check->setVisible(noneAllowed);
        setCheck(f.check, value.isValid());
        // Without a value the field is blank (not the previous light's number); switching it on offers
        // the row's initial value.
        f.number->setBlank(!value.isValid());
        f.number->setValueQuietly(value.isValid() ? value.toDouble() : propertyField(row.id).initial);
        f.number->setEnabled(value.isValid() || !noneAllowed);
        break;
    }
    case PropertyEditor::OptionalColor:
        setCheck(f.check, value.isValid());
        f.color->setColor(value.isValid() ? value.value<glm::dvec3>() : glm::dvec3(0.05));
        f.color->setEnabled(value.isValid());
        break;
    case PropertyEditor::Vector:
        f.vector->setValue(value.value<glm::dvec3>());
        break;
    case PropertyEditor::FactorOrColor: {
        const bool isColor = value.metaType() == QMetaType::fromType<glm::dvec3>();
        setCombo(f.combo, isColor ? 1 : 0);
        f.number->setVisible(!isColor);
        f.color->setVisible(isColor);
        if (isColor) {
            f.color->setColor(value.value<glm::dvec3>());
        } else {
            f.number->setValueQuietly(value.toDouble());
            f.color->setColor(glm::dvec3(value.toDouble()));
        }
        break;
    }
    }
}

} // namespace lr
