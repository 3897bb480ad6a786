#include "abcompareframe.h"

#include "abcompare.h"
#include "render/renderer.h"
#include "scene/environmentloader.h"

#include <QEvent>
#include <QLabel>
#include <algorithm>
#include <cmath>

namespace lr {

bool CompareFrame::ensureTarget(QSize size, QString* error) {
    if (m_fbo && m_size == size) return true;
    if (!m_fbo) {
        glGenFramebuffers(1, &m_fbo);
        glGenRenderbuffers(1, &m_color);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, m_color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.width(), size.height());
    glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_color);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    m_size = size;
    if (status == GL_FRAMEBUFFER_COMPLETE) return true;
    *error = QStringLiteral("the compare view's framebuffer (%1x%2) is incomplete (0x%3)")
                 .arg(size.width())
                 .arg(size.height())
                 .arg(status, 0, 16);
    release();
    return false;
}

void CompareFrame::release() {
    if (!m_initialized || !m_fbo) return;
    glDeleteFramebuffers(1, &m_fbo);
    glDeleteRenderbuffers(1, &m_color);
    m_fbo = m_color = 0;
    m_size = QSize();
}

bool CompareFrame::render(Renderer& renderer, const AbCompare& compare, const Side& a, const Side& b,
                          const ViewCamera& camera, QSize size, double dpr, GLuint targetFbo,
                          QString* error) {
    if (!m_initialized && !(m_initialized = initializeOpenGLFunctions())) {
        *error = QStringLiteral("cannot resolve the OpenGL 3.3 core functions for the compare view");
        return false;
    }
    const Side& left = compare.swapped() ? b : a;
    const Side& right = compare.swapped() ? a : b;
    const bool wipe = compare.layout() == CompareLayout::Wipe;
    const int w = size.width(), h = size.height();
    const int half = std::max(1, w / 2);
    // Wipe: both whole-size images, the right one shown from x = split on. Side by side: two halves.
    const int split = wipe ? int(std::lround(compare.split() * w)) : w - half;
    const QSize imageSize = wipe ? size : QSize(half, h);
    auto draw = [&](const Side& side, GLuint fbo) {
        renderer.setRig(*side.rig);
        renderer.setEnvironment(side.environment);
        const bool ok = renderer.render(camera, imageSize, side.settings, fbo);
        if (!ok) *error = renderer.lastError();
        return ok;
    };
    auto restoreA = [&] {
        renderer.setRig(*a.rig);
        renderer.setEnvironment(a.environment);
    };
    bool ok = true;
    if (wipe && split <= 0) {
        ok = draw(right, targetFbo);
    } else if (wipe && split >= w) {
        ok = draw(left, targetFbo);
    } else {
        ok = draw(left, targetFbo) && ensureTarget(imageSize, error) && draw(right, m_fbo);
        if (ok) {
            const int from = wipe ? split : 0;
            glBindFramebuffer(GL_READ_FRAMEBUFFER, m_fbo);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targetFbo);
            glBlitFramebuffer(from, 0, imageSize.width(), h, split, 0, split + imageSize.width() - from, h,
                              GL_COLOR_BUFFER_BIT, GL_NEAREST);
        }
    }
    restoreA();
    if (!ok || (wipe && (split <= 0 || split >= w))) return ok; // one image: no line
    // The divider: a light line two pixels wide centred on the split (covers an odd width's middle column).
    const int line = std::max(2, int(std::lround(2.0 * dpr)));
    glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
    glEnable(GL_SCISSOR_TEST);
    const int centre = wipe ? split : w / 2;
    glScissor(std::clamp(centre - line / 2, 0, std::max(0, w - line)), 0, line, h);
    glClearColor(0.92f, 0.92f, 0.92f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    return true;
}

CompareLabels::CompareLabels(const AbCompare* compare, QWidget* viewport)
    : QObject(const_cast<AbCompare*>(compare)), m_compare(compare), m_viewport(viewport),
      m_left(new QLabel(viewport)), m_right(new QLabel(viewport)) {
    for (QLabel* l : {m_left, m_right}) {
        l->setObjectName(l == m_left ? QStringLiteral("compareLabelLeft")
                                     : QStringLiteral("compareLabelRight"));
        l->setAttribute(Qt::WA_TransparentForMouseEvents); // presses reach the viewport (the wipe line)
        l->setStyleSheet(QStringLiteral("background: rgba(0, 0, 0, 150); color: #f0f0f0; padding: 3px;"));
        l->hide();
    }
    viewport->installEventFilter(this);
    connect(compare, &AbCompare::changed, this, &CompareLabels::place);
    place();
}

bool CompareLabels::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_viewport && event->type() == QEvent::Resize) place();
    return QObject::eventFilter(watched, event);
}

void CompareLabels::place() {
    if (!m_viewport) return;
    const QString a = tr("A · the rig"), b = tr("B · %1").arg(m_compare->nameB());
    m_left->setText(m_compare->swapped() ? b : a);
    m_right->setText(m_compare->swapped() ? a : b);
    const int w = m_viewport->width(), margin = 6;
    const int x = m_compare->layout() == CompareLayout::Wipe ? int(std::lround(m_compare->splitX(w))) : w / 2;
    for (QLabel* l : {m_left, m_right}) {
        l->adjustSize();
        const bool isLeft = l == m_left;
        // Shown while comparing, where its side is wide enough for it.
        const bool fits = (isLeft ? x : w - x) >= l->width() + 2 * margin;
        l->move(isLeft ? margin : w - margin - l->width(), margin);
        l->setVisible(m_compare->isActive() && fits);
        l->raise();
    }
}

} // namespace lr
