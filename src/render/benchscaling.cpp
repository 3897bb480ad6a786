#include "benchscaling.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace lr {

namespace {

QColor colorOf(Quality q) {
    switch (q) {
    case Quality::Exact:
        return QColor(40, 100, 200);
    case Quality::Balanced:
        return QColor(230, 130, 20);
    case Quality::Fast:
        return QColor(40, 160, 70);
    }
    return Qt::black;
}

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

    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    QFont font = p.font();
    font.setPixelSize(13);
    p.setFont(font);
    const QFontMetrics fm(font);
    const QRectF plot(80, 50, size.width() - 110 - 150, size.height() - 110);
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

    QFont bold = font;
    bold.setBold(true);
    bold.setPixelSize(15);
    p.setFont(bold);
    p.drawText(QRectF(0, 8, size.width(), 24), Qt::AlignHCenter,
               QStringLiteral("Frame time against %1 (%2×%3)")
                   .arg(byTriangles ? QStringLiteral("triangles") : QStringLiteral("lights"))
                   .arg(report.options.size.width())
                   .arg(report.options.size.height()));
    p.setFont(font);
    p.drawText(QRectF(0, 28, size.width(), 18), Qt::AlignHCenter, report.glDescription);
    // Grid and ticks at 1, 2, 5 of each decade.
    auto ticks = [](double a, double b) {
        std::vector<double> t;
        for (double d = a; d <= b * 1.0001; d *= 10.0)
            for (double m : {1.0, 2.0, 5.0})
                if (d * m <= b * 1.0001) t.push_back(d * m);
        return t;
    };
    const std::vector<double> xt = ticks(x0, x1), yt = ticks(y0, y1);
    p.setPen(QPen(QColor(225, 225, 225), 1));
    for (double t : xt)
        p.drawLine(QPointF(mapX(t), plot.top()), QPointF(mapX(t), plot.bottom()));
    for (double t : yt)
        p.drawLine(QPointF(plot.left(), mapY(t)), QPointF(plot.right(), mapY(t)));
    p.setPen(QPen(Qt::black, 1.2));
    p.drawRect(plot);
    for (double t : xt) {
        const QString label =
            t >= 1.0 ? QString::number(qint64(std::llround(t))) : QString::number(t, 'g', 3);
        p.drawText(QPointF(mapX(t) - fm.horizontalAdvance(label) / 2.0, plot.bottom() + 18), label);
    }
    for (double t : yt) {
        const QString label =
            t >= 1.0 ? QString::number(qint64(std::llround(t))) : QString::number(t, 'g', 3);
        p.drawText(QPointF(plot.left() - 8 - fm.horizontalAdvance(label), mapY(t) + 5), label);
    }
    p.drawText(QRectF(plot.left(), plot.bottom() + 26, plot.width(), 20), Qt::AlignHCenter,
               byTriangles ? QStringLiteral("triangles, log scale") : QStringLiteral("lights, log scale"));
    p.save();
    p.translate(18, plot.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-plot.height() / 2, -10, plot.height(), 20), Qt::AlignHCenter,
               QStringLiteral("median ms/frame (wall, glFinish), log scale"));
    p.restore();

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
        p.setPen(QPen(colorOf(tier), 2));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
        p.setPen(QPen(Qt::black, 0.8));
        p.setBrush(colorOf(tier));
        for (const BenchResult* r : rs)
            p.drawEllipse(QPointF(mapX(xOf(r)), mapY(r->msMedian)), 4.5, 4.5);
        const QPointF legend(plot.right() + 24, plot.top() + 12 + 22 * row++);
        p.drawEllipse(legend, 5.5, 5.5);
        p.setPen(Qt::black);
        p.drawText(QPointF(legend.x() + 14, legend.y() + 5), toString(tier));
    }
    p.end();
    return image;
}

} // namespace lr
