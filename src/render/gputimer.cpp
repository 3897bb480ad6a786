#include "gputimer.h"

namespace lr::render {

void GpuTimer::initialize(QOpenGLFunctions_3_3_Core* gl) {
    gl->glGenQueries(kQueries, m_queries);
    m_next = m_pending = 0;
}

void GpuTimer::release(QOpenGLFunctions_3_3_Core* gl) {
    gl->glDeleteQueries(kQueries, m_queries);
    for (GLuint& q : m_queries)
        q = 0;
    m_next = m_pending = 0;
}

void GpuTimer::begin(QOpenGLFunctions_3_3_Core* gl, double* lastMs) {
    // Harvest finished queries (oldest first) without waiting for any.
    while (m_pending > 0) {
        const int oldest = (m_next - m_pending + kQueries) % kQueries;
        GLint available = 0;
        gl->glGetQueryObjectiv(m_queries[oldest], GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) break;
        GLuint64 ns = 0;
        gl->glGetQueryObjectui64v(m_queries[oldest], GL_QUERY_RESULT, &ns);
        *lastMs = double(ns) * 1e-6;
        --m_pending;
    }
    if (m_pending >= kQueries) return; // all in flight: skip timing this frame
    gl->glBeginQuery(GL_TIME_ELAPSED, m_queries[m_next]);
}

void GpuTimer::end(QOpenGLFunctions_3_3_Core* gl) {
    if (m_pending >= kQueries) return;
    gl->glEndQuery(GL_TIME_ELAPSED);
    m_next = (m_next + 1) % kQueries;
    ++m_pending;
}

} // namespace lr::render
