// The sampler's recursion over boxes of voxels, shared by the full sampler
// and region resampling so that both make the same decision for every
// voxel: a box aligned to the OpenVDB node hierarchy (128, 64, 32, 16, 8
// voxels) is interval-evaluated over the part of it inside the frame; if the
// stored value is certainly clamped there (inside or outside the band) the
// box becomes a fill, otherwise it splits, down to 8^3 leaves whose voxels
// are batch-evaluated. A voxel's value depends only on its own position and
// the boxes above it, never on which part of the grid is being sampled:
// that is what makes a region resample bit-identical to a full one.
//
// Each box's interval pass also specializes the tape to the box
// (frep/eval/tape_specializer.h): its children are tested and its leaves
// evaluated with the shorter tape, which computes the same values bit for
// bit, so the grids are the same with or without it, only faster where
// many bounded pieces (a sculpture's edits) each reach a few boxes.
#pragma once

#include <algorithm>
#include <array>
#include <bitset>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "frep/eval/eval_batch.h"
#include "frep/eval/eval_interval.h"
#include "frep/eval/model.h"
#include "frep/eval/tape_specializer.h"
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
    // The tape each evaluated leaf ran: lengths summed, the longest.
    std::uint64_t leafTapeSum = 0, leafTapeMax = 0, leafTapes = 0;
    // With HG_PROBE_POINT_TAPES=1 (a measurement, bench_export --stages):
    // the leaf's tape specialized further to single voxels of it (four per
    // leaf), the floor no box, however small, could go below.
    std::uint64_t pointTapeSum = 0, pointTapes = 0;

    void add(const WalkCounters& o) {
        boxesTested += o.boxesTested; boxesInside += o.boxesInside; boxesOutside += o.boxesOutside;
        samples += o.samples; leaves += o.leaves;
        leafTapeSum += o.leafTapeSum; leafTapes += o.leafTapes;
        leafTapeMax = std::max(leafTapeMax, o.leafTapeMax);
        pointTapeSum += o.pointTapeSum; pointTapes += o.pointTapes;
    }
};

struct WalkOutput {
    std::vector<BoxFill> fills;
    std::vector<LeafSamples> leaves;
    WalkCounters counters;
    frep::ErrorReport errors;
};

// A box left for later, with the tape its parent specialized to (none:
// the model's), so that its walk starts where the parent's left off.
struct DeferredBox {
    std::array<int, 3> origin;
    std::shared_ptr<const frep::SpecializedTape> tape;
};

// One per thread.
class BoxWalker {
public:
    BoxWalker(const frep::Model& model, const VolumeFrame& frame, double scale);

    // Walks the aligned box at `origin` of edge `size`, restricted to `clip`,
    // with `tape` (a specialization of the model's to a box holding this
    // one; none: the model's own). Boxes of edge `deferSize` met below it
    // are appended to `deferred` instead of walked (pass deferSize 0 to
    // walk everything).
    void walk(const int origin[3], int size, const IndexBox& clip, WalkOutput& out, int deferSize = 0,
              std::vector<DeferredBox>* deferred = nullptr, std::shared_ptr<const frep::SpecializedTape> tape = {});

private:
    enum class Verdict { Inside, Outside, Unknown };
    // The tape in force at one depth of the recursion (0: the model's) and
    // an interval evaluator bound to it.
    struct Level {
        const frep::Tape* tape = nullptr;
        const std::vector<frep::IntervalEvaluator::Affine>* affine = nullptr;
        frep::SpecializedTape own;  // this depth's specialization, when it has one
        std::unique_ptr<frep::IntervalEvaluator> interval;
        std::uint64_t bound = 0;    // the generation `interval` is bound to
        std::uint64_t generation = 0;
    };
    static constexpr int kDepths = 8;  // 128 down to 8, and the leaf's own

    void walkAt(const int origin[3], int size, const IndexBox& clip, WalkOutput& out, int deferSize,
                std::vector<DeferredBox>* deferred, int depth);
    Verdict classify(const IndexBox& domain, WalkCounters& counters, int depth);
    // The tape for the boxes below one at `depth` just classified (from its trace).
    void descend(int depth);
    void evaluateLeaf(const int origin[3], const IndexBox& target, WalkOutput& out, int depth);
    // The point-tape probe (WalkCounters::pointTapeSum) on a few of the leaf's n points.
    void probePointTapes(const Level& leaf, std::size_t n, WalkCounters& counters);

    const VolumeFrame& frame_;
    double scale_;
    float scalef_;
    bool specialize_ = false;  // the tape has min or max to prune, and specialization is on
    std::array<Level, kDepths> levels_;
    const frep::Tape* modelTape_ = nullptr;
    std::vector<frep::IntervalEvaluator::Affine> modelAffine_;
    std::shared_ptr<const frep::SpecializedTape> start_;  // the tape this walk started with
    std::shared_ptr<const frep::SpecializedTape> deferredShare_;  // a copy of the tape handed to deferred boxes
    std::uint64_t deferredGeneration_ = 0;
    frep::IntervalTrace trace_;
    frep::TapeSpecializer specializer_;
    bool probe_ = false;  // HG_PROBE_POINT_TAPES
    frep::IntervalTrace probeTrace_;
    frep::SpecializedTape probeOwn_;
    std::unique_ptr<frep::BatchEvaluator<float>> batch_;  // the tape's path
    const frep::Tape* batchTape_ = nullptr;
    std::uint64_t batchGeneration_ = 0;
    std::unique_ptr<frep::PointSampler<float>> sampler_;  // the interpreter's path
    std::vector<float> x_, y_, z_, f_;
};

}  // namespace hg::voxel
