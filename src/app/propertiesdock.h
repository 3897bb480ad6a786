// The Properties dock: edits the selected light(s) with a control suited to each value, showing only the
// fields the light's type and models use (propertyShown). Its rows, labels, limits and suffixes are the
// light-property table's (editor/lightproperty.h); the editor widget of each row is propertyfields.h's. With
// several lights selected it shows the fields they all use and an edit applies to all of them as one undo
// step. Values are validated as typed (limits from editor/lightproperty.h) and again by the Document; a
// refused value is never stored and the reason is shown under the fields. Spin-box steps, slider drags and
// typing within one gesture merge into one step.
#pragma once

#include <functional>

#include "editor/document.h"
#include "editor/lightproperty.h"

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
class LinkingSection;
class Vec3Edit;

class PropertiesDock : public QDockWidget {
    Q_OBJECT
  public:
    explicit PropertiesDock(Document* document, QWidget* parent = nullptr);
    ~PropertiesDock() override;

    // The row widget of a property (its objectName is propertyFieldName()); visible iff the row is shown.
    QWidget* field(LightProperty property) const { return m_fields.value(property); }
    QString message() const; // the last refusal reason ("" when none)
    // Issue 38: the Linking section under the fields (linkingsection.h); the main window gives it the parts.
    LinkingSection* linking() const { return m_linking; }
    // Asks for a file to open (a File field's "…" button): QFileDialog by default; tests replace it.
    std::function<QString(const QString& title, const QString& folder, const QString& filter)> askOpenFile;

  public slots:
    void refresh(); // re-reads the document (called on rig and selection changes)

  private:
    // The parts of one row's editor (only those its PropertyEditor has are set).
    struct Field {
        QWidget* widget = nullptr; // the row's field (objectName: propertyFieldName)
        QLineEdit* line = nullptr;
        QComboBox* combo = nullptr; // enum items, or factor/colour for FactorOrColor
        QCheckBox* check = nullptr; // the value (CheckBox) or "has a value" (Optional*)
        NumberEdit* number = nullptr;
        LogSliderEdit* slider = nullptr;
        ColorButton* color = nullptr;
        Vec3Edit* vector = nullptr;
    };

    void build();
    Field createField(const LightPropertyInfo& row);
    QWidget* fileField(const LightPropertyInfo& row, QLineEdit* line, const char* filter);
    void connectNumber(LightProperty property, NumberEdit* edit);
    // Push one value for every selected light. continuous: part of a gesture that merges into one step.
    void apply(LightProperty property, const QVariant& value, bool continuous);
    void applyComponent(LightProperty property, int axis, double value);
    void finishGesture();
    void showMessage(const QString& text);
    void updateVisibility(const QList<int>& rows);
    void loadValue(const LightPropertyInfo& row, const Field& field, const Light& light);
    // A text several lights may share (the group): blank with "(several values)" when they differ; a group
    // left empty shows the light's own group as the placeholder.
    void loadSharedText(const LightPropertyInfo& row, QLineEdit* line, const QList<int>& rows, int current);

    Document* m_doc;
    QWidget* m_panel = nullptr;
    QLabel* m_header = nullptr;
    QLabel* m_message = nullptr;
    QFormLayout* m_form = nullptr;
    LinkingSection* m_linking = nullptr;
    QHash<LightProperty, QWidget*> m_fields;
    QHash<LightProperty, Field> m_parts;
    std::optional<int> m_editToken;
    QTimer m_idle; // ends a merging gesture after a pause even if the field never lost focus
};

} // namespace lr
