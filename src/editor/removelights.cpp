#include "editor/removelights.h"

#include <QCoreApplication>
#include <algorithm>

namespace lr {

std::unique_ptr<RemoveLights> RemoveLights::create(Document* doc, const QList<int>& rows, QString* error) {
    QList<int> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    if (sorted.isEmpty() || sorted.front() < 0 || sorted.back() >= doc->lightCount()) {
        if (error) *error = QCoreApplication::translate("lr::RemoveLights", "no light selected");
        return nullptr;
    }
    return std::unique_ptr<RemoveLights>(new RemoveLights(doc, std::move(sorted)));
}

RemoveLights::RemoveLights(Document* doc, QList<int> rows) : RigCommand(doc), m_rows(std::move(rows)) {
    m_lights.reserve(size_t(m_rows.size()));
    for (int r : m_rows) {
        m_lights.push_back(doc->light(r));
        m_ids.append(doc->lightId(r));
    }
    setText(m_rows.size() == 1
                ? QCoreApplication::translate("lr::RemoveLights", "Delete %1").arg(m_lights.front().name)
                : QCoreApplication::translate("lr::RemoveLights", "Delete %1 lights").arg(m_rows.size()));
}

void RemoveLights::redo() {
    removeLights(m_ids);
}

void RemoveLights::undo() {
    insertLights(m_rows, m_lights, m_ids);
    select(m_ids);
}

} // namespace lr
