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

RemoveLights::RemoveLights(Document* doc, QList<int> rows) : m_doc(doc), m_rows(std::move(rows)) {
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
    // Contiguous runs, last first, so earlier indices stay valid.
    for (int j = int(m_rows.size()) - 1; j >= 0;) {
        int i = j;
        while (i > 0 && m_rows[i - 1] == m_rows[i] - 1) --i;
        m_doc->removeLightsAt(m_rows[i], j - i + 1);
        j = i - 1;
    }
}

void RemoveLights::undo() {
    // Runs in ascending order: each run's first row is its final index once the earlier runs are back.
    for (int i = 0; i < m_rows.size();) {
        int j = i;
        while (j + 1 < m_rows.size() && m_rows[j + 1] == m_rows[j] + 1) ++j;
        const std::vector<Light> run(m_lights.begin() + i, m_lights.begin() + j + 1);
        m_doc->insertLightsAt(m_rows[i], run, m_ids.mid(i, j - i + 1));
        i = j + 1;
    }
    m_doc->setSelection(QSet<LightId>(m_ids.begin(), m_ids.end()), m_ids.front());
}

}  // namespace lr
