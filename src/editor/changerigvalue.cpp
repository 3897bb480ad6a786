#include "editor/changerigvalue.h"

#include "editor/environmentvalue.h"

#include <QCoreApplication>

namespace lr {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("lr::ChangeRigValue", text);
}

// Rig-wide values only (no lights; the environment's few softboxes and spots are cheap too): cheap to copy,
// compares values of any QVariant type exactly.
Rig settingsWith(const Rig& rig, RigProperty property, const QVariant& value) {
    Rig r;
    r.name = rig.name;
    r.space = rig.space;
    r.ambient = rig.ambient;
    r.shading = rig.shading;
    r.ground = rig.ground;
    r.environment = rig.environment;
    applyRigValue(r, property, value);
    return r;
}
} // namespace

std::unique_ptr<ChangeRigValue> ChangeRigValue::create(Document* doc, RigProperty property,
                                                       const QVariant& value, QString* error) {
    if (int(property) < 0 || int(property) >= kRigPropertyCount) {
        if (error) *error = tr("not an editable rig value");
        return nullptr;
    }
    if (const QString e = validateRigValue(property, value); !e.isEmpty()) {
        if (error) *error = e;
        return nullptr;
    }
    // Store the value in its canonical type (e.g. a QColor becomes linear glm::dvec3).
    const QVariant after = rigValue(settingsWith(doc->rig(), property, value), property);
    return std::unique_ptr<ChangeRigValue>(
        new ChangeRigValue(doc, property, rigValue(doc->rig(), property), after));
}

ChangeRigValue::ChangeRigValue(Document* doc, RigProperty property, QVariant before, QVariant after)
    : RigCommand(doc), m_property(property), m_before(std::move(before)), m_after(std::move(after)),
      m_session(doc->continuousEditSession()) {
    setText(describe());
}

QString ChangeRigValue::describe() const {
    // The environment's fields each name themselves in the history ("Change environment intensity").
    if (m_property == RigProperty::Environment && m_before.canConvert<Environment>() &&
        m_after.canConvert<Environment>())
        return environmentChangeText(m_before.value<Environment>(), m_after.value<Environment>());
    return tr("Change %1").arg(rigPropertyName(m_property));
}

void ChangeRigValue::undo() {
    setRigValue(m_property, m_before);
}

void ChangeRigValue::redo() {
    setRigValue(m_property, m_after);
    setObsolete(settingsWith(Rig{}, m_property, m_before) == settingsWith(Rig{}, m_property, m_after));
}

bool ChangeRigValue::mergeWith(const QUndoCommand* other) {
    const auto* o = static_cast<const ChangeRigValue*>(other);
    if (m_session == 0 || o->m_session != m_session || o->m_property != m_property) return false;
    m_after = o->m_after;
    setText(describe());
    setObsolete(settingsWith(Rig{}, m_property, m_before) == settingsWith(Rig{}, m_property, m_after));
    return true;
}

} // namespace lr
