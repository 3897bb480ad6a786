#include "benchchart.h"

#include <QFontMetrics>
#include <QPen>

namespace lr::chart {

QColor tierColor(Quality quality) {
    switch (quality) {
    case Quality::Exact:
        return QColor(40, 100, 200);
    case Quality::Balanced:
        return QColor(230, 130, 20);
    case Quality::Fast:
        return QColor(40, 160, 70);
    }
    return Qt::black;
}

Canvas::Canvas(QSize size)
    : m_image(size, QImage::Format_ARGB32_Premultiplied),
      m_plot(80, 50, size.width() - 110 - 150, size.height() - 110) {
    m_image.fill(Qt::white);
    m_painter.begin(&m_image);
    m_painter.setRenderHint(QPainter::Antialiasing);
    m_font = m_painter.font();
    m_font.setPixelSize(13);
    m_painter.setFont(m_font);
}

void Canvas::title(const QString& title, const QString& subtitle) {
    QPainter& p = m_painter;
    p.setPen(Qt::black);
    QFont bold = m_font;
    bold.setBold(true);
    bold.setPixelSize(15);
    p.setFont(bold);
    p.drawText(QRectF(0, 8, m_image.width(), 24), Qt::AlignHCenter, title);
    p.setFont(m_font);
    p.drawText(QRectF(0, 28, m_image.width(), 18), Qt::AlignHCenter, subtitle);
}

void Canvas::axes(const std::vector<double>& xTicks, const std::vector<double>& yTicks, const Map& mapX,
                  const Map& mapY, const Label& xLabel, const Label& yLabel, const QString& xCaption,
                  const QString& yCaption) {
    QPainter& p = m_painter;
    const QRectF& plot = m_plot;
    const QFontMetrics fm(m_font);
    p.setPen(QPen(QColor(225, 225, 225), 1));
    for (double t : xTicks)
        p.drawLine(QPointF(mapX(t), plot.top()), QPointF(mapX(t), plot.bottom()));
    for (double t : yTicks)
        p.drawLine(QPointF(plot.left(), mapY(t)), QPointF(plot.right(), mapY(t)));
    p.setPen(QPen(Qt::black, 1.2));
    p.drawRect(plot);
    for (double t : xTicks) {
        const QString label = xLabel(t);
        p.drawText(QPointF(mapX(t) - fm.horizontalAdvance(label) / 2.0, plot.bottom() + 18), label);
    }
    for (double t : yTicks) {
        const QString label = yLabel(t);
        p.drawText(QPointF(plot.left() - 8 - fm.horizontalAdvance(label), mapY(t) + 5), label);
    }
    p.drawText(QRectF(plot.left(), plot.bottom() + 26, plot.width(), 20), Qt::AlignHCenter, xCaption);
    p.save();
    p.translate(18, plot.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-plot.height() / 2, -10, plot.height(), 20), Qt::AlignHCenter, yCaption);
    p.restore();
}

void Canvas::legendEntry(int row, const QString& name, const QColor& color, bool square) {
    QPainter& p = m_painter;
    const QPointF at(m_plot.right() + 24, m_plot.top() + 12 + 22 * row);
    p.setPen(QPen(Qt::black, 0.8));
    p.setBrush(color);
    if (square)
        p.drawRect(QRectF(at.x() - 5, at.y() - 5, 10, 10));
    else
        p.drawEllipse(at, 5.5, 5.5);
    p.setPen(Qt::black);
    p.drawText(QPointF(at.x() + 14, at.y() + 5), name);
}

QImage Canvas::finish() {
    m_painter.end();
    return m_image;
}

} // namespace lr::chart
