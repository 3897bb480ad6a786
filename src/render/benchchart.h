// The frame both bench charts draw in (benchreport.h's time against error, benchscaling.h's scaling curve):
// a white canvas, 13 px text, a plot rectangle with room for a legend on its right, title and subtitle,
// grid lines at the ticks, the plot's frame, tick labels and the two axis captions, legend entries.
#pragma once

#include "core/quality.h"

#include <QColor>
#include <QFont>
#include <QImage>
#include <QPainter>
#include <QRectF>
#include <QSize>
#include <QString>
#include <functional>
#include <vector>

namespace lr::chart {

QColor tierColor(Quality quality); // exact blue, balanced orange, fast green

class Canvas {
  public:
    explicit Canvas(QSize size);
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;

    QPainter& painter() { return m_painter; }
    QRectF plot() const { return m_plot; }

    void title(const QString& title, const QString& subtitle);
    using Map = std::function<double(double)>;    // data -> pixel
    using Label = std::function<QString(double)>; // tick value -> its label
    void axes(const std::vector<double>& xTicks, const std::vector<double>& yTicks, const Map& mapX,
              const Map& mapY, const Label& xLabel, const Label& yLabel, const QString& xCaption,
              const QString& yCaption);
    // Row `row` of the legend beside the plot: a dot (or a square) in `color` and the name.
    void legendEntry(int row, const QString& name, const QColor& color, bool square = false);
    QImage finish(); // ends painting

  private:
    QImage m_image;
    QPainter m_painter;
    QFont m_font;
    QRectF m_plot;
};

} // namespace lr::chart
