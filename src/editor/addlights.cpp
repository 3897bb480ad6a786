#include "editor/addlights.h"

#include "core/rigjson.h"

#include <QCoreApplication>

namespace lr {

std::unique_ptr<AddLights> AddLights::create(Document* doc, int row, std::vector<Light> lights,
                                             const QString& text, QString* error) {
    auto fail = [&](const QString& reason) {
        if (error) *error = reason;
        return nullptr;
    };
    if (lights.empty()) return fail(QCoreApplication::translate("lr::AddLights", "no lights to add"));
    if (doc->lightCount() + qsizetype(lights.size()) > kMaxRigLights)
        return fail(
            QCoreApplication::translate("lr::AddLights", "a rig holds at most %1 lights").arg(kMaxRigLights));
    for (const Light& l : lights)
        if (const QString e = validateLight(l); !e.isEmpty()) return fail(e);
    if (row < 0 || row > doc->lightCount()) row = doc->lightCount();
    return std::unique_ptr<AddLights>(new AddLights(doc, row, std::move(lights), text));
}

AddLights::AddLights(Document* doc, int row, std::vector<Light> lights, const QString& text)
    : m_doc(doc), m_row(row), m_lights(std::move(lights)) {
    setText(text);
}

void AddLights::undo() {
    m_doc->removeLightsAt(m_row, count());
}

void AddLights::redo() {
    if (m_ids.isEmpty())
        for (size_t i = 0; i < m_lights.size(); ++i)
            m_ids.append(m_doc->newLightId());
    m_doc->insertLightsAt(m_row, m_lights, m_ids);
    m_doc->setSelection(QSet<LightId>(m_ids.begin(), m_ids.end()), m_ids.front());
}

} // namespace lr
