#include "garden/render/quality_governor.h"

#include <algorithm>
#include <numeric>

namespace hg::garden {
namespace {

constexpr double kDownShare = 0.85;  // of the budget: step down above this
constexpr double kUpShare = 0.5;     // step up only while every frame stays under this

// From `top` down to the low preset, each step giving up the least visible
// thing that costs the most (bench_look's columns: full-resolution occlusion
// is the dearest pass on a GPU, then the shadow lookups).
std::vector<RenderQuality> ladderFrom(QualityPreset top) {
    std::vector<RenderQuality> ladder;
    RenderQuality q = qualityOf(top);
    ladder.push_back(q);
    // Last, whatever the top: fewer pixels (the scene drawn smaller and
    // stretched), then coarser meshes for them, which is what keeps a
    // software renderer interactive (docs/benchmarks.md, "The software
    // renderer's frame").
    const auto smaller = [&ladder] {
        RenderQuality low = qualityOf(QualityPreset::Low);
        for (float scale : {0.75f, 0.5f}) {
            low.renderScale = scale;
            ladder.push_back(low);
        }
        low.detailScale = 0.5f;
        ladder.push_back(low);
        return ladder;
    };
    if (top == QualityPreset::Low) return smaller();
    if (q.ambientOcclusion && (!q.aoHalfResolution || q.aoSamples > 8)) {
        q.aoHalfResolution = true;
        q.aoSamples = 8;
        ladder.push_back(q);
    }
    if (q.shadows && q.shadowMapSize > 1024) {
        q.shadowMapSize = 1024;
        ladder.push_back(q);
    }
    if (q.msaaSamples > 2) {
        q.msaaSamples = 2;
        ladder.push_back(q);
    }
    q.ambientOcclusion = false;
    ladder.push_back(q);
    q.shadows = false;
    ladder.push_back(q);
    ladder.push_back(qualityOf(QualityPreset::Low));
    return smaller();
}

}  // namespace

QualityGovernor::QualityGovernor(QualityPreset ceiling, double budgetMs)
    : ladder_(ladderFrom(ceiling)), budgetMs_(budgetMs > 0.0 ? budgetMs : 1000.0 / 60.0) {}

std::optional<RenderQuality> QualityGovernor::observe(double gpuMs) {
    if (gpuMs < 0.0) return std::nullopt;
    recent_.push_back(gpuMs);
    if (recent_.size() > kUpWindow) recent_.pop_front();
    ++sinceChange_;
    msSinceChange_ += gpuMs;
    // Settled: enough frames, or fewer that took long enough.
    const bool slowFrames = sinceChange_ >= kMinFrames && msSinceChange_ >= kJudgeMs;
    if (sinceChange_ < kSettle && !slowFrames) return std::nullopt;

    const auto change = [&](std::size_t to) {
        step_ = to;
        ++changes_;
        sinceChange_ = 0;
        msSinceChange_ = 0.0;
        recent_.clear();  // what was measured belongs to the old quality
        return std::optional<RenderQuality>(ladder_[step_]);
    };
    const std::size_t window = std::min(recent_.size(), kDownWindow);
    if ((window == kDownWindow || slowFrames) && step_ + 1 < ladder_.size()) {
        const double mean = std::accumulate(recent_.end() - static_cast<std::ptrdiff_t>(window), recent_.end(), 0.0) /
                            static_cast<double>(window);
        if (mean > kDownShare * budgetMs_) return change(step_ + 1);
    }
    if (recent_.size() >= kUpWindow && step_ > 0 &&
        *std::max_element(recent_.begin(), recent_.end()) < kUpShare * budgetMs_)
        return change(step_ - 1);
    return std::nullopt;
}

std::vector<RenderQuality> QualityGovernor::stillQualities() const {
    const RenderQuality& now = quality();
    const auto atFullSize = [&](RenderQuality q) {
        q.renderScale = 1.0f;
        q.detailScale = std::clamp(now.renderScale * now.detailScale, 0.25f, 1.0f);
        q.skyMapSize = now.skyMapSize;
        return q;
    };
    std::vector<RenderQuality> stills{atFullSize(ladder_.front())};
    const RenderQuality high = atFullSize(qualityOf(QualityPreset::High));
    if (!sameQuality(stills.front(), high)) stills.push_back(high);
    return stills;
}

}  // namespace hg::garden
