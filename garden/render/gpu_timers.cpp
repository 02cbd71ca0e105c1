#include "garden/render/gpu_timers.h"

namespace hg::garden {

bool GpuTimers::collect(Set& set) {
    for (int p = 0; p < kGpuPasses; ++p) {
        if (!set.used[static_cast<std::size_t>(p)]) continue;
        GLint ready = 0;
        glGetQueryObjectiv(set.queries[static_cast<std::size_t>(p)].get(), GL_QUERY_RESULT_AVAILABLE, &ready);
        if (!ready) return false;
    }
    if (!set.reported) return true;
    for (int p = 0; p < kGpuPasses; ++p) {
        const auto i = static_cast<std::size_t>(p);
        latest_[i] = -1.0f;
        if (!set.used[i]) continue;
        GLuint64 ns = 0;
        glGetQueryObjectui64v(set.queries[i].get(), GL_QUERY_RESULT, &ns);
        latest_[i] = static_cast<float>(static_cast<double>(ns) * 1e-6);
    }
    return true;
}

void GpuTimers::nextView(bool reported) {
    // The oldest sets first, so latest_ ends with the newest finished view.
    for (int k = 1; k <= kRing; ++k) {
        Set& s = ring_[static_cast<std::size_t>((current_ + k + kRing) % kRing)];
        if (s.pending && collect(s)) s.pending = false;
    }
    current_ = (current_ + 1) % kRing;
    Set& set = ring_[static_cast<std::size_t>(current_)];
    set.used.fill(false);
    set.pending = false;  // not collected in time: its results are dropped
    set.reported = reported;
    if (!set.queries[0])
        for (gl::Query& q : set.queries) q = gl::Query::create();
}

void GpuTimers::begin(GpuPass pass) {
    if (current_ < 0 || active_ >= 0) return;
    active_ = static_cast<int>(pass);
    Set& set = ring_[static_cast<std::size_t>(current_)];
    glBeginQuery(GL_TIME_ELAPSED, set.queries[static_cast<std::size_t>(active_)].get());
    set.used[static_cast<std::size_t>(active_)] = true;
    set.pending = true;
}

void GpuTimers::end() {
    if (active_ < 0) return;
    glEndQuery(GL_TIME_ELAPSED);
    active_ = -1;
}

}  // namespace hg::garden
