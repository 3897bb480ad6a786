// The Mixer dock's image (issue 37): the mixed layers shown as the viewport shows a render (exposure, tone
// map and sRGB through core/colour.h displayColour, as the Path traced view's PathTracer::display), and the
// widget that draws it scaled to fit.
//
// Mixing is Σ factor × group image per pixel (scene/renderlayers.h mixGroupImages). The dock mixes group
// images reduced once to the preview's size (downscaleImage, a box filter: linear, so reducing then mixing is
// mixing then reducing), which keeps a redraw per control change within a frame at any render size.
#pragma once

#include "core/types.h"
#include "scene/floatimage.h"

#include <QImage>
#include <QSize>
#include <QWidget>

namespace lr {

// `source` scaled to fit within `bounds`, aspect kept, never larger than `source` (and at least 1×1).
QSize fitSize(QSize source, QSize bounds);
// Each pixel of a `size` image the mean of the source pixels it covers (a box filter); `image` itself when
// it already has that size.
FloatImage downscaleImage(const FloatImage& image, QSize size);
// The display image (QImage::Format_RGB888): each pixel's rgb × 2^exposureEV, tone mapped, sRGB, the bytes
// of colour::displayColour (to a level where a value falls on a step's edge). Opaque: a split render's
// background group holds what is behind the model.
QImage displayImage(const FloatImage& image, double exposureEV, ToneMap toneMap);

class MixerPreview : public QWidget {
    Q_OBJECT
  public:
    explicit MixerPreview(QWidget* parent = nullptr);
    void setImage(const QImage& image); // drawn scaled to fit, centred; a null image shows the text
    void setText(const QString& text);
    const QImage& image() const { return m_image; }
    // The largest image worth making for this widget: its size in device pixels.
    QSize pixelSize() const;
    QSize sizeHint() const override { return {320, 180}; }
    int heightForWidth(int width) const override { return width * 9 / 16; }
    bool hasHeightForWidth() const override { return true; }

  signals:
    void held(bool down); // the left button went down on the image (true) or up (false): A/B while held
    void resized();

  protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

  private:
    QImage m_image;
    QString m_text;
};

} // namespace lr
