#include "benchscaling.h"
#include "benchchart.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace lr {

namespace {

// Decades around [lo, hi] (both > 0), at least one.
std::pair<double, double> decades(double lo, double hi) {
    const double a = std::pow(10.0, std::floor(std::log10(lo)));
    double b = std::pow(10.0, std::ceil(std::log10(hi)));
    if (!(b > a)) b = a * 10.0;
    return {a, b};
}

} // namespace

QImage benchScalingChart(const BenchReport& report, QSize size) {
    std::vector<const BenchResult*> points;
    std::set<qint64> lightCounts, triangleCounts;
    for (const BenchResult& r : report.results) {
        if (r.uberShader || !(r.msMedian > 0.0)) continue;
        points.push_back(&r);
        lightCounts.insert(r.lightsUploaded);
        triangleCounts.insert(r.triangles);
    }
    const bool byTriangles = lightCounts.size() <= 1 && triangleCounts.size() > 1;
    auto xOf = [&](const BenchResult* r) { return double(byTriangles ? r->triangles : r->lightsUploaded); };
    points.erase(
        std::remove_if(points.begin(), points.end(), [&](const BenchResult* r) { return !(xOf(r) > 0.0); }),
        points.end());

    chart::Canvas canvas(size);
    QPainter& p = canvas.painter();
    const QRectF plot = canvas.plot();
    double xLo = 1e300, xHi = 0.0, yLo = 1e300, yHi = 0.0;
    for (const BenchResult* r : points) {
        xLo = std::min(xLo, xOf(r)), xHi = std::max(xHi, xOf(r));
        yLo = std::min(yLo, r->msMedian), yHi = std::max(yHi, r->msMedian);
    }
    if (points.empty()) xLo = yLo = 1.0, xHi = yHi = 10.0;
    const auto [x0, x1] = decades(xLo, xHi);
    const auto [y0, y1] = decades(yLo, yHi);
    auto mapX = [&](double x) {
        return plot.left() +
               (std::log10(x) - std::log10(x0)) / (std::log10(x1) - std::log10(x0)) * plot.width();
    };
    auto mapY = [&](double y) {
        return plot.bottom() -
               (std::log10(y) - std::log10(y0)) / (std::log10(y1) - std::log10(y0)) * plot.height();
    };

    canvas.title(QStringLiteral("Frame time against %1 (%2×%3)")
                     .arg(byTriangles ? QStringLiteral("triangles") : QStringLiteral("lights"))
                     .arg(report.options.size.width())
                     .arg(report.options.size.height()),
                 report.glDescription);
    // Grid and ticks at 1, 2, 5 of each decade.
    auto ticks = [](double a, double b) {
        std::vector<double> t;
        for (double d = a; d <= b * 1.0001; d *= 10.0)
            for (double m : {1.0, 2.0, 5.0})
                if (d * m <= b * 1.0001) t.push_back(d * m);
        return t;
    };
    const auto label = [](double t) {
        return t >= 1.0 ? QString::number(qint64(std::llround(t))) : QString::number(t, 'g', 3);
    };
    canvas.axes(ticks(x0, x1), ticks(y0, y1), mapX, mapY, label, label,
                byTriangles ? QStringLiteral("triangles, log scale") : QStringLiteral("lights, log scale"),
                QStringLiteral("median ms/frame (wall, glFinish), log scale"));

    // One line per tier through its scenes in order of x.
    std::map<Quality, std::vector<const BenchResult*>> byTier;
    for (const BenchResult* r : points)
        byTier[r->quality].push_back(r);
    int row = 0;
    for (auto& [tier, rs] : byTier) {
        std::sort(rs.begin(), rs.end(),
                  [&](const BenchResult* a, const BenchResult* b) { return xOf(a) < xOf(b); });
        QPainterPath path;
        for (size_t i = 0; i < rs.size(); ++i) {
            const QPointF at(mapX(xOf(rs[i])), mapY(rs[i]->msMedian));
            i ? path.lineTo(at) : path.moveTo(at);
        }
        p.setPen(QPen(chart::tierColor(tier), 2));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
        p.setPen(QPen(Qt::black, 0.8));
        p.setBrush(chart::tierColor(tier));
        for (const BenchResult* r : rs)
            p.drawEllipse(QPointF(mapX(xOf(r)), mapY(r->msMedian)), 4.5, 4.5);
        canvas.legendEntry(row++, toString(tier), chart::tierColor(tier));
    }
    return canvas.finish();
}

} // namespace lr
