#include "dynamicresolution.h"

#include <algorithm>
#include <cmath>

namespace lr {

void DynamicResolution::setBudgetMs(double budgetMs) {
    m_budgetMs = std::isfinite(budgetMs) && budgetMs > 0.0 ? budgetMs : 0.0;
}

void DynamicResolution::reset() {
    m_scale = 1.0;
    m_fullMs = -1.0;
}

void DynamicResolution::frameDrawn(double ms, double scaleUsed) {
    if (!(std::isfinite(ms) && ms > 0.0 && std::isfinite(scaleUsed) && scaleUsed > 0.0) || !enabled()) return;
    scaleUsed = std::min(scaleUsed, 1.0);
    const double full = ms / (scaleUsed * scaleUsed);
    // Smoothed, but a frame much dearer than the estimate (a light now casting, a heavier tier) counts at
    // once: the next frame must not overrun too.
    m_fullMs = m_fullMs < 0.0 || full > 2.0 * m_fullMs ? full : 0.5 * (m_fullMs + full);
    const double fit = std::sqrt(kHeadroom * m_budgetMs / m_fullMs);
    const double stepped = std::clamp(std::floor(fit / kStep + 1e-9) * kStep, kMinScale, 1.0);
    if (stepped < m_scale)
        m_scale = stepped; // too slow: as small as needed, at once
    else if (stepped > m_scale && ms < kStepUpBelow * m_budgetMs && scaleUsed >= m_scale - 1e-9)
        m_scale = std::min(1.0, m_scale + kStep); // room to spare: one step up
}

} // namespace lr
