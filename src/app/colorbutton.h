// A button showing a linear-RGB colour swatch; clicking opens QColorDialog. HDR colours (components > 1,
// e.g. the book's red light of 15) keep their brightness: the dialog edits the colour divided by its
// largest component (when > 1) and the result is scaled back, so OK without a change changes nothing.
// While the dialog is open every colour it shows is announced (colorPreviewed) for a live preview. The
// button reads "linear 1, 0.9, 0.8" and the dialog's title says its values are sRGB (issue 41).
#pragma once

#include <QToolButton>
#include <glm/vec3.hpp>

namespace lr {

class ColorButton : public QToolButton {
    Q_OBJECT
  public:
    explicit ColorButton(QWidget* parent = nullptr);

    glm::dvec3 color() const { return m_color; }
    void setColor(const glm::dvec3& linear); // no signal
    void setMixed(bool mixed);               // several lights with different colours selected

    // Conversions between linear RGB (any scale >= 0) and the 8-bit sRGB QColor shown/picked.
    static QColor toDisplay(const glm::dvec3& linear);
    static glm::dvec3 fromDisplay(const QColor& srgb, double scale);
    static double hdrScale(const glm::dvec3& linear); // max(1, largest component)

  signals:
    void colorPicked(const glm::dvec3& linear); // user chose a different colour
    // While the dialog is open (live preview, see colorpreview.h): started, each colour it shows, and
    // finished (accepted: OK, colorPicked follows when the colour changed; else Cancel: take it back).
    void previewStarted();
    void colorPreviewed(const glm::dvec3& linear);
    void previewFinished(bool accepted);

  private:
    void pick();
    void updateSwatch();

    glm::dvec3 m_color{1.0};
    bool m_mixed = false;
};

} // namespace lr
