#include "voxel/edit_region.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "frep/eval/eval_batch.h"
#include "frep/eval/eval_interval.h"
#include "frep/eval/tape_specializer.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {

namespace {

// Tapes shorter than this run as they are: specializing costs about an
// evaluation of a few points, and a short tape has little to prune.
constexpr std::size_t kSpecializeFrom = 96;

struct Worker {
    explicit Worker(const frep::Tape& t, const openvdb::FloatTree& base, float band)
        : tape(t), eval(t), interval(t), acc(base), specialize(frep::specializationEnabled() && t.size() >= kSpecializeFrom) {
        // The base grid's values lie in [-band, band], both float constants.
        interval.setBaseBounds(frep::Interval(-static_cast<double>(band), static_cast<double>(band)), true);
    }
    const frep::Tape& tape;
    frep::BatchEvaluator<float> eval;
    frep::IntervalEvaluator interval;
    frep::TapeSpecializer specializer;
    frep::IntervalTrace trace;
    frep::SpecializedTape shorter;
    openvdb::tree::ValueAccessor<const openvdb::FloatTree> acc;
    bool specialize;
    bool boundFull = true;  // `eval` runs the full tape (else the last specialized one)
    std::vector<float> x, y, z, w, out;
    std::vector<openvdb::Index> offsets;
    frep::ErrorReport errors;
};

// The tape for the voxels of `box`: specialized to it (frep/eval/tape_specializer.h,
// the same values bit for bit) when that shortens it.
void bindTapeFor(Worker& wk, const VolumeFrame& frame, const IndexBox& box) {
    // Rebinding fills every constant's registers: the full tape only when
    // it is not bound already, a specialized one each time (new contents).
    const auto useFull = [&wk] {
        if (wk.boundFull) return;
        wk.eval.rebind(wk.tape);
        wk.boundFull = true;
    };
    if (!wk.specialize) return useFull();
    frep::Interval axis[3];
    for (int a = 0; a < 3; ++a)  // rounded as the points are (monotone)
        axis[a] = frep::Interval(static_cast<double>(static_cast<float>(frame.coordinate(a, box.lo[a]))),
                                 static_cast<double>(static_cast<float>(frame.coordinate(a, box.hi[a]))));
    wk.interval.evaluate(axis[0], axis[1], axis[2], &wk.trace);
    if (!wk.specializer.specialize(wk.tape, wk.interval.affine(), wk.trace, frep::Precision::Float, wk.shorter))
        return useFull();
    wk.eval.rebind(wk.shorter.tape);
    wk.boundFull = false;
}

// The voxels of the leaf at `o` inside `clip`: base values and positions
// through the worker's tape, clamped to the band, stored active inside it.
void fillLeaf(Worker& wk, const VolumeFrame& frame, const IndexBox& clip, const std::array<int, 3>& o, FloatLeaf& leaf) {
    wk.x.clear(); wk.y.clear(); wk.z.clear(); wk.w.clear(); wk.offsets.clear();
    const int dim = static_cast<int>(FloatLeaf::DIM);
    for (int i = std::max(o[0], clip.lo[0]); i <= std::min(o[0] + dim - 1, clip.hi[0]); ++i)
        for (int j = std::max(o[1], clip.lo[1]); j <= std::min(o[1] + dim - 1, clip.hi[1]); ++j)
            for (int k = std::max(o[2], clip.lo[2]); k <= std::min(o[2] + dim - 1, clip.hi[2]); ++k) {
                const openvdb::Coord c(i, j, k);
                // Rounded like the sampler's points (box_walker.cpp).
                wk.x.push_back(static_cast<float>(frame.coordinate(0, i)));
                wk.y.push_back(static_cast<float>(frame.coordinate(1, j)));
                wk.z.push_back(static_cast<float>(frame.coordinate(2, k)));
                wk.w.push_back(wk.acc.getValue(c));
                wk.offsets.push_back(FloatLeaf::coordToOffset(c));
            }
    wk.out.resize(wk.x.size());
    bindTapeFor(wk, frame,
                IndexBox::fromCorners(std::max(o[0], clip.lo[0]), std::max(o[1], clip.lo[1]), std::max(o[2], clip.lo[2]),
                                      std::min(o[0] + dim - 1, clip.hi[0]), std::min(o[1] + dim - 1, clip.hi[1]),
                                      std::min(o[2] + dim - 1, clip.hi[2])));
    wk.eval.evaluate(wk.x.data(), wk.y.data(), wk.z.data(), wk.w.data(), wk.out.data(), wk.x.size(), wk.errors);
    const float band = frame.band;
    for (std::size_t n = 0; n < wk.out.size(); ++n) {
        const float v = std::clamp(wk.out[n], -band, band);
        if (std::fabs(v) < band) leaf.setValueOn(wk.offsets[n], v);
        else leaf.setValueOff(wk.offsets[n], v);
    }
}

}  // namespace

EditRegionStats applyEditTape(const Volume& base, Volume& target, const IndexBox& region, const frep::Tape& tape) {
    const auto start = std::chrono::steady_clock::now();
    EditRegionStats stats;
    const VolumeFrame& frame = target.frame;
    const IndexBox clip = intersect(region, frame.indexBox);
    if (clip.empty()) return stats;

    // Leaves first, serially (touching the tree is not thread-safe), then
    // each leaf filled on its own.
    openvdb::FloatTree& tree = vdb(target).tree();
    const auto origins = alignedBoxes(clip, static_cast<int>(FloatLeaf::DIM));
    std::vector<FloatLeaf*> leaves(origins.size());
    for (std::size_t i = 0; i < origins.size(); ++i)
        leaves[i] = tree.touchLeaf(openvdb::Coord(origins[i][0], origins[i][1], origins[i][2]));

    const openvdb::FloatTree& baseTree = vdb(base).tree();
    tbb::enumerable_thread_specific<std::unique_ptr<Worker>> workers(
        [&] { return std::make_unique<Worker>(tape, baseTree, frame.band); });
    tbb::parallel_for(std::size_t{0}, origins.size(), [&](std::size_t b) {
        Worker& wk = *workers.local();
        fillLeaf(wk, frame, clip, origins[b], *leaves[b]);
    });
    for (const auto& wk : workers) stats.errors.merge(wk->errors);
    stats.voxels = clip.volume();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

EditRegionStats applyEditTapes(const Volume& base, Volume& target, const std::vector<IndexBox>& regions,
                               const std::function<frep::Tape(std::size_t)>& tapeOf) {
    const auto start = std::chrono::steady_clock::now();
    EditRegionStats stats;
    const VolumeFrame& frame = target.frame;
    openvdb::FloatTree& tree = vdb(target).tree();
    // Every region's leaves first (touching the tree is not thread-safe).
    std::vector<IndexBox> clips(regions.size());
    std::vector<std::vector<FloatLeaf*>> leaves(regions.size());
    std::vector<std::vector<std::array<int, 3>>> origins(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r) {
        clips[r] = intersect(regions[r], frame.indexBox);
        origins[r] = alignedBoxes(clips[r], static_cast<int>(FloatLeaf::DIM));
        for (const auto& o : origins[r]) leaves[r].push_back(tree.touchLeaf(openvdb::Coord(o[0], o[1], o[2])));
        stats.voxels += clips[r].volume();
    }
    const openvdb::FloatTree& baseTree = vdb(base).tree();
    tbb::enumerable_thread_specific<frep::ErrorReport> errors;
    tbb::parallel_for(std::size_t{0}, regions.size(), [&](std::size_t r) {
        if (clips[r].empty()) return;
        const frep::Tape tape = tapeOf(r);
        Worker wk(tape, baseTree, frame.band);
        for (std::size_t b = 0; b < origins[r].size(); ++b) fillLeaf(wk, frame, clips[r], origins[r][b], *leaves[r][b]);
        errors.local().merge(wk.errors);
    });
    for (const auto& e : errors) stats.errors.merge(e);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace hg::voxel
