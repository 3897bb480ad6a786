#include "colorbutton.h"

#include "core/colour.h"

#include <QColorDialog>
#include <QPainter>
#include <QPixmap>
#include <algorithm>

namespace lr {

ColorButton::ColorButton(QWidget* parent) : QToolButton(parent) {
    setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    connect(this, &QToolButton::clicked, this, &ColorButton::pick);
    updateSwatch();
}

void ColorButton::setColor(const glm::dvec3& linear) {
    m_color = linear;
    m_mixed = false;
    updateSwatch();
}

void ColorButton::setMixed(bool mixed) {
    m_mixed = mixed;
    updateSwatch();
}

double ColorButton::hdrScale(const glm::dvec3& c) {
    return std::max({1.0, c.r, c.g, c.b});
}

QColor ColorButton::toDisplay(const glm::dvec3& linear) {
    const double s = hdrScale(linear);
    auto channel = [s](double v) {
        const double x = std::isfinite(v) ? std::clamp(v / s, 0.0, 1.0) : 0.0;
        return int(std::lround(colour::linearToSrgb(x) * 255.0));
    };
    return QColor(channel(linear.r), channel(linear.g), channel(linear.b));
}

glm::dvec3 ColorButton::fromDisplay(const QColor& srgb, double scale) {
    return glm::dvec3(colour::srgbToLinear(srgb.redF()), colour::srgbToLinear(srgb.greenF()),
                      colour::srgbToLinear(srgb.blueF())) *
           scale;
}

void ColorButton::pick() {
    const QColor initial = toDisplay(m_color);
    const double scale = m_mixed ? 1.0 : hdrScale(m_color);
    QColorDialog dialog(initial, this);
    dialog.setObjectName(QStringLiteral("colorDialog"));
    // The dialog's numbers and hex are sRGB; the rig's (and this button's) are linear: both say which.
    dialog.setWindowTitle(tr("Colour (sRGB; the rig stores linear RGB)"));
    // Live preview: every colour the dialog shows is announced, so the viewport can follow it.
    emit previewStarted();
    connect(&dialog, &QColorDialog::currentColorChanged, this, [this, scale](const QColor& c) {
        if (c.isValid()) emit colorPreviewed(fromDisplay(c, scale));
    });
    const bool accepted = dialog.exec() == QDialog::Accepted;
    const QColor chosen = dialog.selectedColor();
    emit previewFinished(accepted);
    if (!accepted || !chosen.isValid() || (chosen.rgb() == initial.rgb() && !m_mixed)) return;
    const glm::dvec3 picked = fromDisplay(chosen, scale);
    setColor(picked);
    emit colorPicked(picked);
}

void ColorButton::updateSwatch() {
    QPixmap pm(28, 16);
    pm.fill(m_mixed ? palette().color(QPalette::Button) : toDisplay(m_color));
    QPainter p(&pm);
    p.setPen(palette().color(QPalette::Dark));
    p.drawRect(pm.rect().adjusted(0, 0, -1, -1));
    if (m_mixed) p.drawText(pm.rect(), Qt::AlignCenter, QStringLiteral("…"));
    p.end();
    setIcon(QIcon(pm));
    setIconSize(pm.size());
    if (m_mixed) {
        setText(tr("(mixed)"));
        setToolTip(tr("The selected lights have different colours"));
    } else {
        const QString linear = QStringLiteral("%1, %2, %3")
                                   .arg(m_color.r, 0, 'g', 3)
                                   .arg(m_color.g, 0, 'g', 3)
                                   .arg(m_color.b, 0, 'g', 3);
        setText(tr("linear %1").arg(linear));
        setToolTip(tr("Linear RGB %1 (sRGB %2 in the colour dialog). Click to choose a colour%3")
                       .arg(linear, toDisplay(m_color).name(),
                            hdrScale(m_color) > 1.0 ? tr(" (its HDR brightness is kept)") : QString()));
    }
}

} // namespace lr
