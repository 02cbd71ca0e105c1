// `--quality auto`: keeps the GPU's time for a frame inside the display's
// budget by stepping the render quality down and back up a ladder
// (docs/rendering.md, "Quality"). It reads the renderer's own timer
// queries (FrameStats::gpuMs), so it steers by what the GPU spends, not by
// the CPU's frame time. Steps are cheapest-first in picture lost: occlusion
// at half resolution with fewer samples, a smaller shadow map, the medium
// preset, no occlusion, no shadows, no multisampling, then the scene drawn
// at three quarters and at half the window's size (renderScale), and last
// coarser meshes for that half (detailScale). Hysteresis keeps it
// from flickering: down when the recent mean passes 85 % of the budget, up
// only after a long stretch under half of it, and never two changes close
// together. "Close" is counted in frames and in the GPU's milliseconds: a
// renderer that takes 150 ms a frame (llvmpipe on two cores) would
// otherwise sit at a few frames a second for half a minute before reaching
// the rung it can keep.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

#include "garden/render/render_quality.h"

namespace hg::garden {

class QualityGovernor {
public:
    // `ceiling`: the best it may use (rendererPreset's: high on a GPU, low
    // on a software renderer); `budgetMs`: the display's period.
    QualityGovernor(QualityPreset ceiling, double budgetMs);

    // One frame's GPU time (-1: not measured, ignored). The quality to use
    // from now on when it changes, else nothing.
    std::optional<RenderQuality> observe(double gpuMs);

    const RenderQuality& quality() const { return ladder_[step_]; }
    // What a still view is sharpened to, in turn (Renderer::setStillQualities):
    // the ceiling at the window's full size, then, below a high ceiling (a
    // software renderer), the high preset there too: a view looked at may
    // take one slow frame for shadows and occlusion. Each keeps the rung's
    // meshes (its render scale times its detail scale as the detail scale,
    // so the level of detail stays where it is when the visitor stops) and
    // its sky map (baking another costs more than the frame).
    std::vector<RenderQuality> stillQualities() const;
    std::size_t step() const { return step_; }          // 0: the ceiling
    std::size_t steps() const { return ladder_.size(); }
    std::size_t changes() const { return changes_; }  // steps taken, down or up, so far
    double budgetMs() const { return budgetMs_; }
    // The display's period changed (a headset's refresh rate): later frames
    // are judged against the new one.
    void setBudgetMs(double budgetMs) { budgetMs_ = budgetMs; }

    // Frames averaged before stepping down, frames under half the budget
    // before stepping up, and frames after any change before the next.
    static constexpr std::size_t kDownWindow = 30;
    static constexpr std::size_t kUpWindow = 180;
    static constexpr std::size_t kSettle = 60;
    // Or, stepping down, fewer frames when they add up to this much GPU
    // time: a second's worth judges a slow renderer as surely as 60 quick
    // frames judge a fast one. Never fewer than kMinFrames (the timer
    // queries report a few frames late, so the first ones after a change
    // may still be the old quality's).
    static constexpr double kJudgeMs = 1000.0;
    static constexpr std::size_t kMinFrames = 6;

private:
    std::vector<RenderQuality> ladder_;
    std::size_t step_ = 0;
    double budgetMs_;
    std::deque<double> recent_;  // the last kUpWindow measurements
    std::size_t sinceChange_ = 0;
    double msSinceChange_ = 0.0;  // GPU time measured since the last change
    std::size_t changes_ = 0;
};

}  // namespace hg::garden
