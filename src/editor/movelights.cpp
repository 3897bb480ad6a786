#include "editor/movelights.h"

#include <QCoreApplication>
#include <algorithm>

namespace lr {

std::unique_ptr<MoveLights> MoveLights::create(Document* doc, const QList<int>& rows, int destination,
                                               QString* error) {
    const int n = doc->lightCount();
    QList<int> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    if (sorted.isEmpty() || sorted.front() < 0 || sorted.back() >= n || destination < 0 || destination > n) {
        if (error) *error = QCoreApplication::translate("lr::MoveLights", "nothing to move there");
        return nullptr;
    }
    // Runs of contiguous rows, split at destination.
    struct Run {
        int first, count;
    };
    QList<Run> before, after; // runs above destination (move down) and at/below it (move up)
    for (int i = 0; i < sorted.size();) {
        int j = i;
        while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1 &&
               (sorted[j + 1] < destination) == (sorted[i] < destination))
            ++j;
        (sorted[i] < destination ? before : after).append({sorted[i], j - i + 1});
        i = j + 1;
    }
    QList<BlockMove> moves;
    // Runs above: last first, each placed right before the block that grows up from destination. Moves only
    // touch rows above destination, so the lower runs keep their indices.
    int anchor = destination;
    for (int k = int(before.size()) - 1; k >= 0; --k) {
        const Run r = before[k];
        if (r.first + r.count != anchor) moves.append({r.first, r.count, anchor});
        anchor -= r.count;
    }
    // Runs below: first first, each placed right after the block that grows down from destination.
    int end = destination;
    for (const Run& r : after) {
        if (r.first != end) moves.append({r.first, r.count, end});
        end += r.count;
    }
    if (moves.isEmpty()) {
        if (error) error->clear();
        return nullptr;
    }
    return std::unique_ptr<MoveLights>(new MoveLights(doc, std::move(moves), int(sorted.size())));
}

MoveLights::MoveLights(Document* doc, QList<BlockMove> moves, int count)
    : RigCommand(doc), m_moves(std::move(moves)) {
    if (m_moves.size() > 1) {
        // The same moves as one permutation: simulate them on the identity order.
        std::vector<int> order(size_t(doc->lightCount()));
        for (size_t i = 0; i < order.size(); ++i)
            order[i] = int(i);
        for (const BlockMove& m : std::as_const(m_moves)) {
            auto b = order.begin();
            if (m.destination > m.first)
                std::rotate(b + m.first, b + m.first + m.count, b + m.destination);
            else
                std::rotate(b + m.destination, b + m.first, b + m.first + m.count);
        }
        m_order = QList<int>(order.begin(), order.end());
        m_inverse.resize(m_order.size());
        for (int i = 0; i < m_order.size(); ++i)
            m_inverse[m_order[i]] = i;
    }
    setText(count == 1 ? QCoreApplication::translate("lr::MoveLights", "Move light")
                       : QCoreApplication::translate("lr::MoveLights", "Move %1 lights").arg(count));
}

void MoveLights::redo() {
    if (!m_order.isEmpty()) return reorderLights(m_order);
    for (const BlockMove& m : std::as_const(m_moves))
        moveLightBlock(m.first, m.count, m.destination);
}

void MoveLights::undo() {
    if (!m_order.isEmpty()) return reorderLights(m_inverse);
    for (auto it = m_moves.crbegin(); it != m_moves.crend(); ++it) {
        const BlockMove& m = *it;
        const bool down = m.destination > m.first;
        const int now = down ? m.destination - m.count : m.destination;
        moveLightBlock(now, m.count, down ? m.first : m.first + m.count);
    }
}

} // namespace lr
