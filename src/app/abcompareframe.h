// Draws the viewport's A/B compare frame (abcompare.h) with the viewport's own Renderer, so B follows every
// camera move and view setting exactly as A does. The image on the left goes straight into the target
// framebuffer; the one on the right into a colour framebuffer of its own, of which the part right of the
// wipe line (Wipe) or the whole (Side by side: two halves of the same size, each the whole view) is
// blitted beside it; then a divider line. A wipe at an edge renders one image only. The renderer's rig and
// environment are B's only while B renders: A's when it returns, so the normal frame path is unaffected.
// CompareLabels names the two sides ("A · the rig", "B · snapshot 14:02:11") with two QLabels over the
// viewport: child widgets that Qt composites over the GL frame, so they are no part of it (grabFramebuffer
// and screenshots have none) and leave its GL state alone (a QPainter on the widget did not: the frames
// after one lost their anti-aliased edges).
#pragma once

#include "render/rendersettings.h"
#include "scene/camera.h"

#include <QObject>
#include <QOpenGLFunctions_3_3_Core>
#include <QPointer>
#include <QSize>
#include <memory>

class QLabel;
class QWidget;

namespace lr {

class AbCompare;
class Renderer;
struct LoadedEnvironment;
struct Rig;

class CompareFrame : protected QOpenGLFunctions_3_3_Core {
  public:
    struct Side {
        const Rig* rig = nullptr;
        std::shared_ptr<const LoadedEnvironment> environment;
        RenderSettings settings;
    };

    // `size` in device pixels; `dpr` scales the divider line. The context of `renderer` must be current.
    // False with *error when a render or the framebuffer failed.
    bool render(Renderer& renderer, const AbCompare& compare, const Side& a, const Side& b,
                const ViewCamera& camera, QSize size, double dpr, GLuint targetFbo, QString* error);
    void release(); // its context current

  private:
    bool ensureTarget(QSize size, QString* error);

    bool m_initialized = false;
    GLuint m_fbo = 0, m_color = 0;
    QSize m_size;
};

class CompareLabels : public QObject {
    Q_OBJECT
  public:
    CompareLabels(const AbCompare* compare, QWidget* viewport); // a child of compare
    QLabel* left() const { return m_left; }
    QLabel* right() const { return m_right; }

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void place();

    const AbCompare* m_compare;
    QPointer<QWidget> m_viewport;
    QLabel *m_left, *m_right;
};

} // namespace lr
