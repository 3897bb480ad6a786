#include "editor/enablelights.h"

#include <QCoreApplication>
#include <algorithm>

namespace lr {

std::unique_ptr<EnableLights> EnableLights::create(Document* doc, const QList<int>& rows, bool enabled,
                                                   QString* error) {
    QList<int> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    if (sorted.isEmpty() || sorted.front() < 0 || sorted.back() >= doc->lightCount()) {
        if (error) *error = QCoreApplication::translate("lr::EnableLights", "no light selected");
        return nullptr;
    }
    QList<int> changing;
    QList<bool> before;
    for (int r : sorted)
        if (doc->light(r).enabled != enabled) {
            changing.append(r);
            before.append(doc->light(r).enabled);
        }
    if (changing.isEmpty()) {
        if (error) error->clear();
        return nullptr;
    }
    return std::unique_ptr<EnableLights>(
        new EnableLights(doc, std::move(changing), std::move(before), enabled));
}

EnableLights::EnableLights(Document* doc, QList<int> rows, QList<bool> before, bool enabled)
    : m_doc(doc), m_rows(std::move(rows)), m_before(std::move(before)), m_enabled(enabled) {
    const QString what =
        m_rows.size() == 1 ? doc->light(m_rows.front()).name
                           : QCoreApplication::translate("lr::EnableLights", "%1 lights").arg(m_rows.size());
    setText(enabled ? QCoreApplication::translate("lr::EnableLights", "Switch on %1").arg(what)
                    : QCoreApplication::translate("lr::EnableLights", "Switch off %1").arg(what));
}

void EnableLights::apply(bool undo) {
    std::vector<Light> lights;
    lights.reserve(size_t(m_rows.size()));
    for (int i = 0; i < m_rows.size(); ++i) {
        Light l = m_doc->light(m_rows[i]);
        l.enabled = undo ? m_before[i] : m_enabled;
        lights.push_back(std::move(l));
    }
    m_doc->setLightsAt(m_rows, lights, LightProperty::Enabled);
}

void EnableLights::undo() {
    apply(true);
}
void EnableLights::redo() {
    apply(false);
}

} // namespace lr
