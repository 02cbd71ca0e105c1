#include "garden/app/frame_scheduler.h"

#include <algorithm>

namespace hg::garden {

namespace {
double ms(std::chrono::steady_clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }
}  // namespace

void FrameScheduler::beginFrame() {
    stats_ = FrameStats{};
    stats_.frame = frames_++;
    stats_.budgetMs = settings_.budgetMs;
    frameStart_ = Clock::now();
    stage_ = -1;
}

void FrameScheduler::beginStage(Stage s) {
    if (stage_ >= 0) endStage();
    stage_ = static_cast<int>(s);
    stageStart_ = Clock::now();
}

void FrameScheduler::endStage() {
    if (stage_ < 0) return;
    const double t = ms(Clock::now() - stageStart_);
    stats_.stageMs[static_cast<std::size_t>(stage_)] += t;
    stage_ = -1;
}

double FrameScheduler::elapsedMs() const { return ms(Clock::now() - frameStart_); }

// The recent cost of the stages after `s` that are not budgeted themselves
// (rendering), plus the uploads' when s comes before them.
double FrameScheduler::reserveAfter(Stage s) const {
    double r = recentMs_[static_cast<std::size_t>(Stage::Render)];
    if (s == Stage::Morph || s == Stage::Remesh) r += std::min(recentMs_[static_cast<std::size_t>(Stage::Upload)], 1.0);
    return r;
}

double FrameScheduler::allowanceMs(Stage s) const {
    double left = settings_.budgetMs - settings_.marginMs - elapsedMs() - reserveAfter(s);
    if (s == Stage::Morph) left *= settings_.morphShare;
    if (s == Stage::Input) left *= settings_.editShare;
    return std::max(left, settings_.minimumMs);
}

const FrameStats& FrameScheduler::endFrame() {
    endStage();
    stats_.totalMs = elapsedMs();
    // Exponential smoothing: a reserve that follows changes within ~10 frames.
    for (std::size_t i = 0; i < recentMs_.size(); ++i)
        recentMs_[i] = stats_.frame == 0 ? stats_.stageMs[i] : 0.9 * recentMs_[i] + 0.1 * stats_.stageMs[i];
    history_.push(stats_);
    return stats_;
}

}  // namespace hg::garden
