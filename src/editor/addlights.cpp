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
    // Copies of shadow casters (duplicate, paste) count against kMaxShadowCasters like any other.
    if (const int added = shadowCasterCount(lights); added > 0)
        if (const QString e = checkShadowCasterCount(shadowCasterCount(doc->rig().lights) + added);
            !e.isEmpty())
            return fail(e);
    if (row < 0 || row > doc->lightCount()) row = doc->lightCount();
    return std::unique_ptr<AddLights>(new AddLights(doc, row, std::move(lights), text));
}

AddLights::AddLights(Document* doc, int row, std::vector<Light> lights, const QString& text)
    : RigCommand(doc), m_row(row), m_lights(std::move(lights)) {
    setText(text);
}

void AddLights::undo() {
    removeLights(m_ids);
}

void AddLights::redo() {
    if (m_ids.isEmpty())
        for (size_t i = 0; i < m_lights.size(); ++i)
            m_ids.append(newLightId());
    QList<int> rows;
    for (int i = 0; i < count(); ++i)
        rows.append(m_row + i);
    insertLights(rows, m_lights, m_ids);
    select(m_ids);
}

} // namespace lr
