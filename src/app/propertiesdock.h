// The Properties dock: edits the selected light(s) with a control suited to each value, showing only the
// fields the light's type and models use (propertyShown). With several lights selected it shows the fields
// they all use and an edit applies to all of them as one undo step. Values are validated as typed (limits
// from editor/lightproperty.h) and again by the Document; a refused value is never stored and the reason
// is shown under the fields. Spin-box steps, slider drags and typing within one gesture merge into one step.
#pragma once

#include "editor/document.h"

#include <QDockWidget>
#include <QHash>
#include <QTimer>
#include <optional>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;

namespace lr {

class ColorButton;
class LogSliderEdit;
class NumberEdit;
class Vec3Edit;

class PropertiesDock : public QDockWidget {
    Q_OBJECT
  public:
    explicit PropertiesDock(Document* document, QWidget* parent = nullptr);
    ~PropertiesDock() override;

    // The row widget of a property (its objectName is propertyFieldName()); visible iff the row is shown.
    QWidget* field(LightProperty property) const { return m_fields.value(property); }
    QString message() const; // the last refusal reason ("" when none)

  public slots:
    void refresh(); // re-reads the document (called on rig and selection changes)

  private:
    void build();
    void addRow(LightProperty property, const QString& label, QWidget* field);
    NumberEdit* addNumber(LightProperty property, const QString& label, double min, double max,
                          bool minExclusive, const QString& suffix = QString());
    // Push one value for every selected light. continuous: part of a gesture that merges into one step.
    void apply(LightProperty property, const QVariant& value, bool continuous);
    void applyComponent(LightProperty property, int axis, double value);
    void finishGesture();
    void showMessage(const QString& text);
    void updateVisibility(const QList<int>& rows);
    void loadValues(const Light& light);

    Document* m_doc;
    QWidget* m_panel = nullptr;
    QLabel* m_header = nullptr;
    QLabel* m_message = nullptr;
    QFormLayout* m_form = nullptr;
    QHash<LightProperty, QWidget*> m_fields;
    QHash<LightProperty, NumberEdit*> m_numbers;
    QLineEdit* m_name = nullptr;
    QComboBox *m_type = nullptr, *m_falloff = nullptr, *m_cone = nullptr, *m_diffuse = nullptr,
              *m_specularKind = nullptr;
    QCheckBox *m_enabled = nullptr, *m_temperatureOn = nullptr, *m_rangeOn = nullptr, *m_ambientOn = nullptr;
    ColorButton *m_color = nullptr, *m_specularColor = nullptr, *m_ambient = nullptr;
    NumberEdit *m_temperature = nullptr, *m_range = nullptr, *m_specularFactor = nullptr;
    LogSliderEdit* m_intensity = nullptr;
    Vec3Edit *m_position = nullptr, *m_direction = nullptr;
    std::optional<int> m_editToken;
    QTimer m_idle; // ends a merging gesture after a pause even if the field never lost focus
};

} // namespace lr
