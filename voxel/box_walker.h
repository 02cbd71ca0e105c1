// The sampler's recursion over boxes of voxels, shared by the full sampler
// and region resampling so that both make the same decision for every
// voxel: a box aligned to the OpenVDB node hierarchy (128, 64, 32, 16, 8
// voxels) is interval-evaluated over the part of it inside the frame; if the
// stored value is certainly clamped there (inside or outside the band) the
// box becomes a fill, otherwise it splits, down to 8^3 leaves whose voxels
// are batch-evaluated. A voxel's value depends only on its own position and
// the boxes above it, never on which part of the grid is being sampled:
// that is what makes a region resample bit-identical to a full one.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <memory>
#include <vector>

#include "frep/eval_interval.h"
#include "frep/model.h"
#include "voxel/volume_frame.h"

namespace hg::voxel {

constexpr int kLeafSize = 8;       // OpenVDB FloatTree leaf
constexpr int kTopBoxSize = 128;   // an internal node of the first level above the leaves
constexpr int kTaskBoxSize = 32;   // unit of parallel work

// Voxels of one 8^3 leaf that were evaluated (x fastest, then y, then z:
// offset = (x * 8 + y) * 8 + z, OpenVDB's leaf order).
struct LeafSamples {
    int origin[3];
    std::array<float, 512> values;
    std::bitset<512> evaluated;
};

struct BoxFill {
    IndexBox box;
    float value;
};

struct WalkCounters {
    std::uint64_t boxesTested = 0;   // interval evaluations
    std::uint64_t boxesInside = 0;   // proven beyond +band
    std::uint64_t boxesOutside = 0;  // proven beyond -band
    std::uint64_t samples = 0;       // points batch-evaluated
    std::uint64_t leaves = 0;        // leaves with evaluated points

    void add(const WalkCounters& o) {
        boxesTested += o.boxesTested; boxesInside += o.boxesInside; boxesOutside += o.boxesOutside;
        samples += o.samples; leaves += o.leaves;
    }
};

struct WalkOutput {
    std::vector<BoxFill> fills;
    std::vector<LeafSamples> leaves;
    WalkCounters counters;
    frep::ErrorReport errors;
};

// One per thread.
class BoxWalker {
public:
    BoxWalker(const frep::Model& model, const VolumeFrame& frame, double scale);

    // Walks the aligned box at `origin` of edge `size`, restricted to `clip`.
    // Boxes of edge `deferSize` met below it are appended to `deferred`
    // instead of walked (pass deferSize 0 to walk everything).
    void walk(const int origin[3], int size, const IndexBox& clip, WalkOutput& out, int deferSize = 0,
              std::vector<std::array<int, 3>>* deferred = nullptr);

private:
    enum class Verdict { Inside, Outside, Unknown };
    Verdict classify(const IndexBox& domain, WalkCounters& counters);
    void evaluateLeaf(const int origin[3], const IndexBox& target, WalkOutput& out);

    const VolumeFrame& frame_;
    double scale_;
    float scalef_;
    std::unique_ptr<frep::IntervalEvaluator> interval_;
    frep::PointSampler<float> sampler_;
    std::vector<float> x_, y_, z_, f_;
};

}  // namespace hg::voxel
