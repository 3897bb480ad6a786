#include "editor/rigcommand.h"

#include <algorithm>

namespace lr {

LightId RigCommand::newLightId() {
    return m_doc->newLightId();
}

void RigCommand::setLights(const QList<LightId>& ids, const std::vector<Light>& lights,
                           LightProperty property) {
    Q_ASSERT(size_t(ids.size()) == lights.size());
    std::vector<std::pair<int, size_t>> order; // (row, index into lights)
    order.reserve(lights.size());
    for (int i = 0; i < ids.size(); ++i)
        if (const int row = m_doc->rowOf(ids[i]); row >= 0) order.emplace_back(row, size_t(i));
    std::sort(order.begin(), order.end());
    QList<int> rows;
    std::vector<Light> sorted;
    rows.reserve(qsizetype(order.size()));
    sorted.reserve(order.size());
    for (const auto& [row, i] : order) {
        rows.append(row);
        sorted.push_back(lights[i]);
    }
    if (!rows.isEmpty()) m_doc->setLightsAt(rows, sorted, property);
}

void RigCommand::insertLights(const QList<int>& rows, const std::vector<Light>& lights,
                              const QList<LightId>& ids) {
    m_doc->insertLightRows(rows, lights, ids);
}

void RigCommand::removeLights(const QList<LightId>& ids) {
    QList<int> rows;
    rows.reserve(ids.size());
    for (LightId id : ids)
        if (const int row = m_doc->rowOf(id); row >= 0) rows.append(row);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    if (!rows.isEmpty()) m_doc->removeLightRows(rows);
}

void RigCommand::moveLightBlock(int first, int count, int destination) {
    m_doc->moveLightBlock(first, count, destination);
}

void RigCommand::reorderLights(const QList<int>& order) {
    m_doc->reorderLights(order);
}

void RigCommand::setRigValue(RigProperty property, const QVariant& value) {
    m_doc->setRigValueNow(property, value);
}

void RigCommand::resetRig(const Rig& rig, const QList<LightId>& ids) {
    m_doc->resetRig(rig, ids);
}

void RigCommand::select(const QList<LightId>& ids) {
    m_doc->setSelection(QSet<LightId>(ids.begin(), ids.end()), ids.isEmpty() ? 0 : ids.front());
}

} // namespace lr
