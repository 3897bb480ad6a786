#include "mixerpreview.h"

#include "core/colour.h"

#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/vec3.hpp>
#include <limits>

namespace lr {

QSize fitSize(QSize source, QSize bounds) {
    if (source.isEmpty()) return {};
    QSize out = source.scaled(bounds.expandedTo(QSize(1, 1)), Qt::KeepAspectRatio).boundedTo(source);
    return out.expandedTo(QSize(1, 1));
}

FloatImage downscaleImage(const FloatImage& image, QSize size) {
    if (image.isNull() || size.isEmpty() || (size.width() == image.width && size.height() == image.height))
        return image;
    const int sw = image.width, sh = image.height, dw = size.width(), dh = size.height();
    FloatImage out;
    out.width = dw;
    out.height = dh;
    out.pixels.assign(size_t(dw) * size_t(dh), glm::vec4(0.0f));
    // Destination pixel x covers source columns [x·sw/dw, (x+1)·sw/dw) (at least one), rows likewise.
    std::vector<int> x0(static_cast<size_t>(dw) + 1);
    for (int x = 0; x <= dw; ++x)
        x0[size_t(x)] = int(qint64(x) * sw / dw);
    std::vector<glm::vec4> row(static_cast<size_t>(dw));
    for (int y = 0; y < dh; ++y) {
        const int ya = int(qint64(y) * sh / dh), yb = std::max(ya + 1, int(qint64(y + 1) * sh / dh));
        std::fill(row.begin(), row.end(), glm::vec4(0.0f));
        for (int sy = ya; sy < yb; ++sy)
            for (int x = 0; x < dw; ++x) {
                const int xa = x0[size_t(x)], xb = std::max(xa + 1, x0[size_t(x) + 1]);
                for (int sx = xa; sx < xb; ++sx)
                    row[size_t(x)] += image.at(sx, sy);
            }
        for (int x = 0; x < dw; ++x) {
            const int xa = x0[size_t(x)], xb = std::max(xa + 1, x0[size_t(x) + 1]);
            out.at(x, y) = row[size_t(x)] / float((xb - xa) * (yb - ya));
        }
    }
    return out;
}

namespace {

// displayColour's sRGB step without a pow per channel: byte k + 1 begins where linearToSrgb reaches
// (k + 0.5) / 255, i.e. at the tone-mapped value srgbToLinear((k + 0.5) / 255) (the transfer function is
// monotonic), so a byte is the number of these 255 steps at or below the value: looked up in a table of
// the byte at the start of each of kBuckets equal buckets of [0, 1], then stepped over the (at most two)
// steps inside the bucket. 640×360 under ACES: 5-6 ms of processor time instead of 22-26 ms with a pow per
// channel (tst_app_mixerdock's redrawTimeIsReported prints both).
constexpr int kBuckets = 4096;

struct SrgbSteps {
    std::array<double, 256> step{}; // step[255] = +inf
    std::array<uchar, kBuckets + 1> first{};
    SrgbSteps() {
        for (int k = 0; k < 255; ++k)
            step[size_t(k)] = colour::srgbToLinear((k + 0.5) / 255.0);
        step[255] = std::numeric_limits<double>::infinity();
        int k = 0;
        for (int b = 0; b <= kBuckets; ++b) {
            while (step[size_t(k)] <= double(b) / kBuckets)
                ++k;
            first[size_t(b)] = uchar(k);
        }
    }
};

uchar srgbByte(double toneMapped) {
    static const SrgbSteps s;
    if (!(toneMapped > 0.0)) return 0; // NaN too
    if (toneMapped >= 1.0) return 255;
    int k = s.first[size_t(toneMapped * kBuckets)];
    while (s.step[size_t(k)] <= toneMapped)
        ++k;
    return uchar(k);
}

} // namespace

QImage displayImage(const FloatImage& image, double exposureEV, ToneMap toneMap) {
    if (image.isNull()) return {};
    QImage out(image.width, image.height, QImage::Format_RGB888);
    if (out.isNull()) return out;
    const double scale = colour::exposureScale(exposureEV);
    for (int y = 0; y < image.height; ++y) {
        uchar* line = out.scanLine(y);
        for (int x = 0; x < image.width; ++x) {
            // colour::displayColour's tone map; its sRGB transfer and rounding through srgbByte.
            const glm::dvec3 m = colour::toneMapRgb(toneMap, glm::dvec3(image.at(x, y)) * scale);
            for (int k = 0; k < 3; ++k)
                line[3 * x + k] = srgbByte(m[k]);
        }
    }
    return out;
}

MixerPreview::MixerPreview(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setMinimumSize(160, 90);
}

void MixerPreview::setImage(const QImage& image) {
    m_image = image;
    update();
}

void MixerPreview::setText(const QString& text) {
    m_text = text;
    update();
}

QSize MixerPreview::pixelSize() const {
    return size() * devicePixelRatioF();
}

void MixerPreview::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().color(QPalette::Window).darker(130));
    if (m_image.isNull()) {
        p.setPen(palette().color(QPalette::PlaceholderText));
        p.drawText(rect().adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap, m_text);
        return;
    }
    QSizeF shown = QSizeF(m_image.size()).scaled(QSizeF(size()), Qt::KeepAspectRatio);
    const QRectF target(QPointF((width() - shown.width()) / 2.0, (height() - shown.height()) / 2.0), shown);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.drawImage(target, m_image);
}

void MixerPreview::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    emit resized();
}

void MixerPreview::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton) emit held(true);
}

void MixerPreview::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton) emit held(false);
}

} // namespace lr
