// GL timer queries (GL_TIME_ELAPSED, core since 3.3) around each render
// pass. Results are read a few views later, only once the GPU has them, so
// measuring never waits for the GPU.
#pragma once

#include <array>

#include "garden/render/gl_objects.h"

namespace hg::garden {

enum class GpuPass { Shadow, Scene, Occlusion, Post };
constexpr int kGpuPasses = 4;

class GpuTimers {
public:
    // Before a view's passes: collects a finished older view's results and
    // takes a fresh set of queries for this one. A view not `reported` is
    // measured but its results are dropped (latest() keeps the view before).
    void nextView(bool reported = true);
    void begin(GpuPass pass);
    void end();  // the pass begun last
    // Milliseconds per pass of the latest view the GPU has finished; -1
    // for a pass not run or not measured yet.
    const std::array<float, kGpuPasses>& latest() const { return latest_; }

private:
    static constexpr int kRing = 4;
    struct Set {
        std::array<gl::Query, kGpuPasses> queries;
        std::array<bool, kGpuPasses> used{};
        bool pending = false;
        bool reported = true;
    };
    bool collect(Set& set);

    std::array<Set, kRing> ring_;
    int current_ = -1;
    int active_ = -1;
    std::array<float, kGpuPasses> latest_{-1.0f, -1.0f, -1.0f, -1.0f};
};

}  // namespace hg::garden
