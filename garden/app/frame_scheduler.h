// One budget per frame (docs/design.md §6; default 11.1 ms for 90 Hz, in XR the
// runtime's predicted display period) shared by the stages in their order:
// input, level selection, morph updates, remeshing, uploads, rendering.
// The scheduler times every stage and tells a budgeted stage how long it may
// take: what is left of the frame minus a reserve for the stages after it
// (their recent cost), with the morph getting at most a share of the work
// time so that remeshing what it changed fits in the same frame.
#pragma once

#include <chrono>

#include "garden/app/frame_stats.h"

namespace hg::garden {

struct SchedulerSettings {
    double budgetMs = 11.1;
    double morphShare = 0.5;  // of the work time left when the morph stage starts
    // Of the work time left when the input stage computes the edits whose
    // grid updates are spread over frames (SessionSettings::spreadEdits).
    double editShare = 0.5;
    // Kept free at the end of every frame: the budgeted stages stop between
    // batches, and a batch's length is a guess.
    double marginMs = 0.5;
    // A budgeted stage always gets this much, even in a frame already over
    // budget (a slow GPU, a software renderer): updates still progress.
    double minimumMs = 1.0;
};

class FrameScheduler {
public:
    explicit FrameScheduler(SchedulerSettings s = {}) : settings_(s) {}

    void beginFrame();
    void beginStage(Stage s);
    void endStage();
    // Milliseconds since beginFrame.
    double elapsedMs() const;
    // How long stage `s` (Input's spread edits, Morph, Remesh or Upload) may run from now.
    double allowanceMs(Stage s) const;
    FrameStats& stats() { return stats_; }
    // Closes the frame: total time, pushed to the history.
    const FrameStats& endFrame();
    const FrameHistory& history() const { return history_; }
    const SchedulerSettings& settings() const { return settings_; }
    void setBudgetMs(double ms) { settings_.budgetMs = ms; }

private:
    using Clock = std::chrono::steady_clock;
    double reserveAfter(Stage s) const;

    SchedulerSettings settings_;
    FrameStats stats_;
    FrameHistory history_;
    Clock::time_point frameStart_{}, stageStart_{};
    int stage_ = -1;
    std::uint64_t frames_ = 0;
    std::array<double, kStageCount> recentMs_{};  // smoothed cost per stage
};

}  // namespace hg::garden
