// Reading render targets back to the CPU (tests, the accuracy reference, radiance read-backs): float
// colour attachments in image order (top row first) and depth in GL order (bottom row first).
#pragma once

#include "floatimage.h"

#include <QOpenGLFunctions_3_3_Core>
#include <QSize>
#include <vector>

namespace lr::render {

// False when GL reported an error.
bool readFloatAttachment(QOpenGLFunctions_3_3_Core* gl, GLuint fbo, GLenum attachment, QSize size,
                         FloatImage* out);
std::vector<float> readDepth(QOpenGLFunctions_3_3_Core* gl, GLuint fbo, QSize size);

} // namespace lr::render
