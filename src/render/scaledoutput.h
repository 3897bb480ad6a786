// The output of a frame drawn at a fraction of its size (RenderSettings::renderScale): an RGBA8 framebuffer
// the passes present into, stretched over the caller's framebuffer with bilinear filtering by one blit.
// Kept between frames while its size holds, so a moving view at a steady scale allocates nothing.
#pragma once

#include <QOpenGLFunctions_3_3_Core>
#include <QSize>
#include <QString>

namespace lr::render {

// The size a frame of `size` is drawn at under `scale` (clamped to [kMinRenderScale, 1]): each side
// rounded, at least one pixel. `size` itself at scale 1.
QSize scaledDrawSize(QSize size, double scale);

struct ScaledOutput {
    QSize size;
    GLuint fbo = 0, color = 0;
    // A framebuffer of `drawSize` (made again only when the size changes). False with error if it is
    // incomplete.
    bool ensure(QOpenGLFunctions_3_3_Core* gl, QSize drawSize, QString* error);
    // Stretches the drawn image over targetFbo's (0, 0, outputSize) with GL_LINEAR; leaves targetFbo bound.
    void present(QOpenGLFunctions_3_3_Core* gl, GLuint targetFbo, QSize outputSize) const;
    void release(QOpenGLFunctions_3_3_Core* gl);
};

} // namespace lr::render
