// GPU time of whole frames (GL_TIME_ELAPSED), read without stalling: up to four queries in flight, each
// harvested a frame or two later; a frame is not timed while all four are pending.
#pragma once

#include <QOpenGLFunctions_3_3_Core>

namespace lr::render {

class GpuTimer {
  public:
    void initialize(QOpenGLFunctions_3_3_Core* gl);
    void release(QOpenGLFunctions_3_3_Core* gl);
    // Harvests finished queries into *lastMs (unchanged when none finished), then starts one.
    void begin(QOpenGLFunctions_3_3_Core* gl, double* lastMs);
    void end(QOpenGLFunctions_3_3_Core* gl);

  private:
    static constexpr int kQueries = 4;
    GLuint m_queries[kQueries] = {};
    int m_next = 0, m_pending = 0;
};

} // namespace lr::render
