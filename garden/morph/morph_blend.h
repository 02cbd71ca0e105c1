// The morph result: at every voxel of the shared frame,
//
//     clamp(w0 * F0 + w1 * F1 + w2 * F2, -band, +band)
//
// where F_i are the sources' unclamped normalized fields (morph_sources.h)
// and w the morph weights (morph_weights.h). Blending the unclamped values
// and clamping only on the way into the grid keeps the result right away
// from the sources' bands.
//
// Two ways to get it: blendMorph() computes the whole result at once;
// MorphBlender spreads the same work over frames (docs/design.md §4, seed 004's
// partial updates). Its work list holds OpenVDB-leaf-aligned blocks of
// 8^3 voxels in two passes:
//
//   1. coarse: in each block, only the voxels whose three indices are
//      multiples of 4. Those are exactly the samples of LOD levels 2 and up
//      (polygonizer/realtime/lod_pyramid.h point-samples level L at multiples of
//      2^L), so once this 1/64 of the work is done every chunk drawn at
//      level 2 or coarser shows the new shape. It costs about 2 ms for a
//      256^3 result (bench_morph), so it lands in the first frame or two.
//   2. fine: every voxel of each block (the coarse ones again: they come out
//      bit-identical and are not reported as changed; it keeps each block's
//      last pass one contiguous loop), after which a block that is uniformly
//      outside or inside the band becomes a tile, as in blendMorph().
//
// The fine pass goes nearest block first (distance from the viewer to the
// block's centre). The coarse pass goes nearest 32^3 region first and,
// inside a region, in z, y, x order: its items are only 8 samples each,
// and visiting a region's blocks together keeps the tree lookups and the
// sources' reads coherent (3x faster than block by block). Ties go by
// z, y, x of the block. Each step() blends at most the budget's samples,
// resuming mid-block where the last one stopped, and reports the index
// boxes whose stored values changed. When the list drains the result
// equals blendMorph(sources, weights) bit for bit (values and active states
// at every voxel, and the same leaves).
//
// Off the frame thread (stepInBackground, what the window and the headset
// run): the next items of the list go to a thread as a job that computes
// their values from the sources alone (garden/morph/blend_job.h); a later
// step, at a frame boundary, writes them into the grid within its budget
// (a memcmp and a copy per block, and the caller's commit) and hands the
// thread the next items. The frame never waits for the thread. The values
// are the same kernel's, so a list drained this way gives the same grid
// bit for bit. A restart drops the job under way (it is for the old
// weights); a job is sized to about 8 ms of the thread's time, so the frame
// writes one job while the thread computes the next.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "garden/morph/morph_sources.h"
#include "garden/morph/morph_weights.h"
#include "voxel/index_box.h"
#include "voxel/volume.h"

namespace hg::jobs {
class JobThread;
}

namespace hg::garden {

constexpr int kBlendBlock = 8;     // block edge: one OpenVDB leaf
constexpr int kCoarseStride = 4;   // the coarse pass's lattice (LOD level 2)
constexpr int kCoarseRegion = 32;  // the coarse pass goes nearest region of 32^3 first

// An empty result (every voxel outside) in the sources' frame.
voxel::Volume makeMorphVolume(const MorphSources& sources);

// The whole result from scratch, on TBB workers.
voxel::Volume blendMorph(const MorphSources& sources, const MorphWeights& weights);

struct BlendBudget {
    std::uint64_t maxSamples = 1000000;  // voxels blended per step; 0: no limit
    // 0: no limit. Checked between batches of at most kBlendBatch samples;
    // after the first batch the next is cut to what the measured rate fits
    // into the time left, so a step overshoots by little.
    double maxMilliseconds = 0.0;
    // Called after each batch with the boxes it changed, within the step's
    // time: what the caller does with a change (the LOD pyramid's resample,
    // the remesh queue's marks) costs about as much as the blend itself in
    // the coarse pass, so it is counted in the rate the batches are sized by.
    std::function<void(const std::vector<voxel::IndexBox>&)> commit;
};

constexpr std::uint64_t kBlendBatch = 65536;

enum class BlendPass : std::uint8_t { Coarse, Fine };

struct BlendItem {
    std::array<int, 3> origin{};  // the block's low corner (multiples of 8)
    BlendPass pass = BlendPass::Fine;
    std::uint32_t samples = 0;    // voxels this item blends (inside the frame's index box)
};

struct BlendStep {
    std::uint64_t samples = 0;              // voxels blended by this step
    std::uint64_t changedVoxels = 0;        // of those, how many changed value or active state
    // One box per block whose stored voxels changed: the bounding box of the
    // voxels that changed (what the LOD pyramid and the remesh queue need).
    std::vector<voxel::IndexBox> changed;
    std::size_t blocksFinished = 0;         // fine items completed by this step
    bool coarseDone = false;                // the coarse pass is complete
    bool done = false;                      // the list is empty: the result is the blend
    double seconds = 0.0;
};

class MorphBlender {
public:
    // `sources` and `result` must outlive the blender. `result` must be in
    // the sources' frame with the background outside its index box (from
    // makeMorphVolume or blendMorph); throws std::invalid_argument otherwise.
    // Nothing is to do until restart().
    MorphBlender(const MorphSources& sources, voxel::Volume& result);
    ~MorphBlender();
    MorphBlender(const MorphBlender&) = delete;
    MorphBlender& operator=(const MorphBlender&) = delete;

    // Starts the list again with new weights (a new selector position),
    // ordered for `viewer` (model coordinates of the shared frame). Cheap
    // while the viewer stays where it was (the order is kept), so it can be
    // called on every move of the selector.
    void restart(const MorphWeights& weights, const std::array<double, 3>& viewer);
    // Re-orders the items not yet started for a viewer that moved; the work
    // done so far is kept.
    void setViewer(const std::array<double, 3>& viewer);
    // Blends the next items within `budget`. The result grid's tree may gain
    // or lose leaves: ValueAccessors on it must not be held across a step.
    BlendStep step(const BlendBudget& budget);
    // The same work with the blending done by `thread`: writes what the job
    // it finished computed (within `budget`, whose commit is called as in
    // step()), then hands it the next items. Never waits; the report counts
    // the samples written.
    BlendStep stepInBackground(const BlendBudget& budget, jobs::JobThread& thread);

    // Nothing left to blend or write (a job under way counts as work left).
    bool done() const;
    bool coarseDone() const;
    std::uint64_t totalSamples() const;
    std::uint64_t remainingSamples() const;
    // Items are with a thread or wait to be written.
    bool inBackground() const;
    const MorphWeights& weights() const;
    // The list in processing order, and the index of the next item.
    const std::vector<BlendItem>& workList() const;
    std::size_t cursor() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace hg::garden
