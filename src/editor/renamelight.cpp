#include "editor/renamelight.h"

#include <QCoreApplication>

namespace lr {

std::unique_ptr<RenameLight> RenameLight::create(Document* doc, int row, const QString& name,
                                                 QString* error) {
    if (row < 0 || row >= doc->lightCount()) {
        if (error) *error = QCoreApplication::translate("lr::RenameLight", "no light at row %1").arg(row);
        return nullptr;
    }
    if (const QString e = validateLightValue(LightProperty::Name, name); !e.isEmpty()) {
        if (error) *error = e;
        return nullptr;
    }
    if (doc->light(row).name == name) {
        if (error) error->clear();
        return nullptr;
    }
    return std::unique_ptr<RenameLight>(new RenameLight(doc, row, doc->light(row).name, name));
}

RenameLight::RenameLight(Document* doc, int row, QString before, QString after)
    : m_doc(doc), m_row(row), m_before(std::move(before)), m_after(std::move(after)) {
    setText(QCoreApplication::translate("lr::RenameLight", "Rename %1 to %2").arg(m_before, m_after));
}

void RenameLight::undo() {
    Light l = m_doc->light(m_row);
    l.name = m_before;
    m_doc->setLightsAt({m_row}, {l}, LightProperty::Name);
}

void RenameLight::redo() {
    Light l = m_doc->light(m_row);
    l.name = m_after;
    m_doc->setLightsAt({m_row}, {l}, LightProperty::Name);
}

} // namespace lr
