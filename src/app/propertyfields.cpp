#include "propertyfields.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace lr {

namespace {

// Rows whose editor is not the default of their kind, or that need an editor setting. A new editor widget
// for a property (an azimuth/elevation editor for the direction, say) is one line here and one case in
// PropertiesDock::createField.
const PropertyField kFieldEditors[] = {
    {LightProperty::Intensity, PropertyEditor::LogSlider, 0.0, 1e-3},
    {LightProperty::Temperature, PropertyEditor::OptionalNumber, 6500.0},
    {LightProperty::FalloffRange, PropertyEditor::OptionalNumber, 10.0},
    {LightProperty::ShadowResolution, PropertyEditor::PowerOfTwo}, // a spin box would step to 1025
    {LightProperty::IesFile, PropertyEditor::File, 0.0, 0.0,
     QT_TRANSLATE_NOOP("lr::PropertiesDock", "IES profiles (*.ies *.IES);;All files (*)")},
    {LightProperty::GoboFile, PropertyEditor::File, 0.0, 0.0,
     QT_TRANSLATE_NOOP("lr::PropertiesDock", "Gobo images (*.png *.exr *.PNG *.EXR);;All files (*)")},
};

PropertyEditor defaultEditor(LightValueKind kind) {
    switch (kind) {
    case LightValueKind::Text:
        return PropertyEditor::LineEdit;
    case LightValueKind::Enum:
        return PropertyEditor::ComboBox;
    case LightValueKind::Bool:
        return PropertyEditor::CheckBox;
    case LightValueKind::Number:
        return PropertyEditor::Number;
    case LightValueKind::OptionalNumber:
        return PropertyEditor::OptionalNumber;
    case LightValueKind::Color:
        return PropertyEditor::ColorButton;
    case LightValueKind::OptionalColor:
        return PropertyEditor::OptionalColor;
    case LightValueKind::Vector:
        return PropertyEditor::Vector;
    case LightValueKind::FactorOrColor:
        return PropertyEditor::FactorOrColor;
    case LightValueKind::Link: // not a field: the dock's Linking section (linkingsection.h)
        break;
    }
    return PropertyEditor::LineEdit;
}

} // namespace

const QList<LightProperty>& propertyRows() {
    static const QList<LightProperty> rows = [] {
        QList<LightProperty> out;
        for (const LightPropertyInfo& row : lightProperties())
            if (row.kind != LightValueKind::Link) out << row.id;
        return out;
    }();
    return rows;
}

PropertyField propertyField(LightProperty property) {
    for (const PropertyField& f : kFieldEditors)
        if (f.property == property) return f;
    const LightPropertyInfo* row = lightPropertyInfo(property);
    return {property, row ? defaultEditor(row->kind) : PropertyEditor::LineEdit};
}

QString propertyFieldName(LightProperty property) {
    const LightPropertyInfo* row = lightPropertyInfo(property);
    return row ? QString::fromLatin1(row->key) : QString();
}

QString intensitySuffix(LightType type, ShadingModel shading) {
    const auto tr = [](const char* t) { return QCoreApplication::translate("lr::PropertiesDock", t); };
    const char* unit = traitsOf(type).pbrUnit;
    if (shading == ShadingModel::Pbr && unit) return QLatin1Char(' ') + QString::fromLatin1(unit);
    return tr(" (classic)");
}

QString fileFieldValue(const QString& chosen, const QString& rigPath) {
    const QString file = QDir::cleanPath(QFileInfo(chosen).absoluteFilePath());
    if (rigPath.isEmpty()) return file;
    const QString relative = QFileInfo(rigPath).absoluteDir().relativeFilePath(file);
    return relative.startsWith(QLatin1String("..")) || QDir::isAbsolutePath(relative) ? file : relative;
}

bool propertyShown(const Light& light, LightProperty property) {
    const LightPropertyInfo* row = lightPropertyInfo(property);
    return row && row->isShown(light);
}

} // namespace lr
