// The editor's moving frames (the camera orbits, pans or dollies, or a light is dragged) are drawn at a
// fraction of the viewport's size chosen so that each takes at most a frame budget (RenderSettings::
// renderScale): a frame that cannot finish in time is drawn cheaper, never waited for. When the view holds
// still the viewport draws at full size in the chosen tier. As Blender's and KeyShot's viewports do.
//
// The controller is told each moving frame's wall time and the scale it was drawn at, keeps a smoothed
// estimate of what a full-size frame would cost (time / scale², the per-pixel work that dominates a
// software rasteriser's frame) and picks the largest scale, in steps of kStep, whose predicted time fits
// 90 % of the budget. It steps down at once when a frame overruns and up by one step only when a frame took
// under 60 % of the budget, so it does not flicker between two sizes. No GL: tests drive it with numbers.
#pragma once

namespace lr {

class DynamicResolution {
  public:
    static constexpr double kStep = 0.125;    // scales are multiples of this
    static constexpr double kMinScale = 0.25; // a quarter of each side: 1280x720 moves at 320x180
    static constexpr double kHeadroom = 0.9;  // aim at this share of the budget
    static constexpr double kStepUpBelow = 0.6;

    // budgetMs <= 0 or not finite: off (every frame at full size).
    explicit DynamicResolution(double budgetMs = 1000.0 / 30.0) { setBudgetMs(budgetMs); }

    void setBudgetMs(double budgetMs);
    double budgetMs() const { return m_budgetMs; }
    bool enabled() const { return m_budgetMs > 0.0; }

    // The scale for the next moving frame: 1 when off.
    double scale() const { return enabled() ? m_scale : 1.0; }
    // A moving frame took `ms` (wall time until it was finished) at `scaleUsed`. Ignored unless both are
    // finite and positive.
    void frameDrawn(double ms, double scaleUsed);
    // The smoothed estimate of a full-size moving frame, ms (< 0: no frame measured yet).
    double fullFrameMs() const { return m_fullMs; }
    void reset();

  private:
    double m_budgetMs = 0.0;
    double m_scale = 1.0;
    double m_fullMs = -1.0;
};

} // namespace lr
