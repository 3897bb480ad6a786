// The scaling chart of `lightrig bench --scaling-chart OUT.png`: median ms/frame against the number of
// lights (when the scenes differ in lights) or of triangles (when they differ in triangles), log–log, one
// line per quality tier. Run it over `--lights 1,8,64,...` on one model for the curve in lights, or over
// models of growing size for the curve in triangles (docs/performance.md shows both).
#pragma once

#include "qualitybench.h"

#include <QImage>
#include <QSize>

namespace lr {

QImage benchScalingChart(const BenchReport& report, QSize size = QSize(1000, 640));

} // namespace lr
