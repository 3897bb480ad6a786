#include "progressive.h"

#include <QElapsedTimer>
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace lr::trace {

const char* stopReasonName(StopReason reason) {
    switch (reason) {
    case StopReason::Samples:
        return "samples";
    case StopReason::Time:
        return "time";
    case StopReason::Noise:
        return "noise";
    case StopReason::Cancelled:
        return "cancelled";
    }
    return "samples";
}

namespace {

// Cancels the tracer when `seconds` pass, unless stopped first.
class Deadline {
  public:
    Deadline(PathTracer& tracer, double seconds) {
        if (!(seconds > 0.0)) return;
        m_thread = std::thread([this, &tracer, seconds] {
            std::unique_lock lock(m_mutex);
            const auto wait = std::chrono::duration<double>(seconds);
            if (!m_wake.wait_for(lock, wait, [this] { return m_stop; })) {
                m_fired = true;
                tracer.cancel();
            }
        });
    }
    ~Deadline() {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_wake.notify_all();
        if (m_thread.joinable()) m_thread.join();
    }
    bool fired() {
        std::lock_guard lock(m_mutex);
        return m_fired;
    }

  private:
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_stop = false, m_fired = false;
    std::thread m_thread;
};

} // namespace

RenderOutcome renderToTarget(PathTracer& tracer, const RenderTarget& target) {
    RenderOutcome outcome;
    QElapsedTimer clock;
    clock.start();
    const bool passes = target.seconds > 0.0 || target.noiseThreshold > 0.0 || target.afterPass;
    {
        Deadline deadline(tracer, target.seconds);
        while (tracer.samplesDone() < target.samples) {
            const int done = tracer.samplesDone();
            const int pass = passes ? std::clamp(done, 1, kMaxPass) : target.samples - done;
            if (!tracer.render(std::min(pass, target.samples - done))) {
                outcome.reason = deadline.fired() ? StopReason::Time : StopReason::Cancelled;
                break;
            }
            if (target.afterPass) target.afterPass(tracer.samplesDone());
            if (target.noiseThreshold > 0.0 && tracer.noiseEstimate() <= target.noiseThreshold) {
                outcome.reason = StopReason::Noise;
                break;
            }
        }
    }
    outcome.seconds = clock.nsecsElapsed() * 1e-9;
    outcome.samples = tracer.samplesDone();
    outcome.noise = tracer.noiseEstimate();
    return outcome;
}

} // namespace lr::trace
