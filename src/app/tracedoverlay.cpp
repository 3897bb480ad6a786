#include "tracedoverlay.h"

#include "tracedview.h"

#include <QEvent>
#include <QPainter>

namespace lr {

TracedOverlay::TracedOverlay(TracedView* view, QWidget* viewport) : QWidget(viewport), m_view(view) {
    setObjectName(QStringLiteral("TracedOverlay"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setFocusPolicy(Qt::NoFocus);
    viewport->installEventFilter(this);
    setGeometry(viewport->rect());
    connect(m_view, &TracedView::updated, this, &TracedOverlay::sync);
    sync();
}

void TracedOverlay::sync() {
    setVisible(m_view->active());
    if (isVisible()) {
        raise();
        update();
    }
}

bool TracedOverlay::eventFilter(QObject* watched, QEvent* event) {
    if (watched == parent() && event->type() == QEvent::Resize) setGeometry(parentWidget()->rect());
    return QWidget::eventFilter(watched, event);
}

void TracedOverlay::paintEvent(QPaintEvent*) {
    QPainter p(this);
    const QImage& image = m_view->image();
    if (!image.isNull()) {
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.drawImage(QRectF(rect()), image); // device pixels onto the widget's logical rect
    }
    const QString text = m_view->readout();
    if (text.isEmpty()) return;
    const bool refused = m_view->state() == TracedView::State::Refused;
    const QRect bounds = rect().adjusted(8, 8, -8, -8);
    QRect box =
        p.fontMetrics().boundingRect(bounds, Qt::AlignLeft | Qt::AlignBottom | Qt::TextWordWrap, text);
    box.adjust(-6, -4, 6, 4);
    p.fillRect(box, refused ? QColor(120, 30, 30, 200) : QColor(0, 0, 0, 150));
    p.setPen(Qt::white);
    p.drawText(box.adjusted(6, 4, -6, -4), Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap, text);
}

} // namespace lr
