// MorphBlender: the budgeted partial update of morph_blend.h.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "garden/morph/blend_block_vdb.h"
#include "garden/morph/blend_job.h"
#include "garden/morph/morph_blend.h"

namespace hg::garden {

using namespace blend;

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::uint64_t kFirstTimedBatch = 4096;
// A job is sized to take the thread about this long, at the rate its last
// job measured: about a frame, so that the frame writes one job while the
// thread computes the next.
constexpr double kJobSeconds = 0.008;
constexpr std::uint64_t kMostJobSamples = 16 * kBlendBatch;
// A job's values are written in slices of at most this many samples (16
// blocks), the time checked between them: writing a block that did not
// change is a compare, one that did costs its commit too (the LOD pyramid,
// the remesh queue), so the rate swings from slice to slice and large
// slices would overshoot the stage's share.
constexpr std::uint64_t kWriteSlice = 8192;

std::string checkResult(const MorphSources& s, const voxel::Volume& result) {
    const voxel::VolumeFrame& a = s.frame;
    const voxel::VolumeFrame& b = result.frame;
    bool same = a.indexBox == b.indexBox && a.voxelSize == b.voxelSize && a.band == b.band && a.resolution == b.resolution;
    for (int i = 0; i < 3; ++i) same = same && a.modelBox.lo[i] == b.modelBox.lo[i] && a.modelBox.hi[i] == b.modelBox.hi[i];
    if (!same) return "the morph result is not in the sources' frame";
    return checkSources(s);
}

// Lookups only, one per worker: not registered with the tree (registration
// is a concurrent map insert per accessor).
using Accessor = openvdb::tree::ValueAccessor<openvdb::FloatTree, false>;

}  // namespace

struct MorphBlender::Impl {
    const MorphSources& sources;
    voxel::Volume& result;
    MorphWeights weights;
    std::array<double, 3> viewer{};  // index space
    std::vector<BlendItem> items;
    std::size_t coarseItems = 0;     // items [0, coarseItems) are the coarse pass
    std::size_t next = 0;            // the item in progress or next
    std::uint32_t nextDone = 0;      // samples of items[next] already blended
    std::uint64_t total = 0;
    std::uint64_t consumed = 0;
    double samplesPerSecond = 0.0;   // measured by the last timed step (0: none yet)
    std::array<double, 3> sortedFor{};  // the viewer the list is sorted for
    bool wholeListSorted = false;       // ... all of it, not only what was left
    // Off the frame thread: the job a thread computes, and the one whose
    // values are being written (pieces [written, ...) left). A restart
    // bumps the generation: a job of an older one is dropped.
    std::shared_ptr<BlendJob> computing;
    std::shared_ptr<BlendJob> writing;
    std::size_t written = 0;
    std::uint64_t generation = 0;
    double jobSamplesPerSecond = 0.0;   // the thread's rate, from the last job
    double writeSamplesPerSecond = 0.0; // the frame's rate writing jobs' values

    Impl(const MorphSources& s, voxel::Volume& r) : sources(s), result(r) {}
    // A job under way reads the sources, which go with the blender: the
    // only place the frame thread waits for one (it stops at its next
    // range of pieces once abandoned).
    ~Impl() {
        if (!computing) return;
        computing->abandon();
        computing->wait();
    }

    std::array<double, 3> toIndex(const std::array<double, 3>& model) const {
        const voxel::VolumeFrame& f = sources.frame;
        return {(model[0] - f.modelBox.lo[0]) / f.voxelSize, (model[1] - f.modelBox.lo[1]) / f.voxelSize,
                (model[2] - f.modelBox.lo[2]) / f.voxelSize};
    }

    // Nearest first: by the distance from the viewer to the centre of the
    // `region`-aligned cube holding the block (the block itself for the
    // fine pass; kCoarseRegion for the coarse pass, whose items are tiny:
    // inside a region they go in memory order, so that tree lookups and the
    // sources' reads stay coherent). Ties by z, y, x of the origin.
    void sortRange(std::size_t first, std::size_t last, int region) {
        if (first >= last) return;
        struct Keyed {
            double d;
            std::array<int, 3> zyx;
            BlendItem item;
        };
        std::vector<Keyed> keyed;
        keyed.reserve(last - first);
        for (std::size_t i = first; i < last; ++i) {
            const BlendItem& it = items[i];
            double d = 0.0;
            for (std::size_t a = 0; a < 3; ++a) {
                double c = floorMultiple(it.origin[a], region) + 0.5 * (region - 1) - viewer[a];
                d += c * c;
            }
            keyed.push_back({d, {it.origin[2], it.origin[1], it.origin[0]}, it});
        }
        std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
            return a.d != b.d ? a.d < b.d : a.zyx < b.zyx;
        });
        for (std::size_t i = first; i < last; ++i) items[i] = keyed[i - first].item;
    }

    // Sorts what is left of each pass for the current viewer.
    void sortFrom(std::size_t first) {
        if (first < coarseItems) {
            sortRange(first, coarseItems, kCoarseRegion);
            sortRange(coarseItems, items.size(), kBlendBlock);
        } else {
            sortRange(first, items.size(), kBlendBlock);
        }
        sortedFor = viewer;
        wholeListSorted = first == 0;
    }

    // The items depend on the frame only; their order on the viewer.
    void build() {
        const voxel::IndexBox& box = sources.frame.indexBox;
        std::vector<std::array<int, 3>> origins = voxel::alignedBoxes(box, kBlendBlock);
        for (const auto& o : origins) {
            std::uint32_t n = itemLattice(o, BlendPass::Coarse, box).size();
            if (n > 0) items.push_back({o, BlendPass::Coarse, n});
        }
        coarseItems = items.size();
        for (const auto& o : origins) items.push_back({o, BlendPass::Fine, itemLattice(o, BlendPass::Fine, box).size()});
        for (const auto& it : items) total += it.samples;
        sortFrom(0);
    }

    void restart() {
        ++generation;
        if (computing) computing->abandon();  // dropped once the thread lets go of it
        writing.reset();
        written = 0;
        if (items.empty()) build();
        else if (!wholeListSorted || viewer != sortedFor) sortFrom(0);
        next = 0;
        nextDone = 0;
        consumed = 0;
    }

    // One item's share of a batch.
    struct Segment {
        std::size_t item = 0;
        std::uint32_t s0 = 0, s1 = 0;   // sample range of the item
        bool finishes = false;          // s1 is the item's end
        FloatLeaf* leaf = nullptr;
        float tileValue = 0.0f;         // the block's value when it has no leaf
        bool tileActive = false;
        bool whole = false;             // blended as a whole block
        bool fresh = false;             // its leaf was made in this batch
        std::uint64_t changed = 0;
        int lo[3] = {0, 0, 0}, hi[3] = {-1, -1, -1};
        bool collapse = false;
        float collapseValue = 0.0f;
        // Values computed off the frame thread (null: blend them here): the
        // whole block's, or samples s0..s1's in order.
        const BlockValues* block = nullptr;
        const float* values = nullptr;

        void noteChange(int i, int j, int k) {
            if (changed++ == 0) {
                lo[0] = hi[0] = i; lo[1] = hi[1] = j; lo[2] = hi[2] = k;
                return;
            }
            lo[0] = std::min(lo[0], i); hi[0] = std::max(hi[0], i);
            lo[1] = std::min(lo[1], j); hi[1] = std::max(hi[1], j);
            lo[2] = std::min(lo[2], k); hi[2] = std::max(hi[2], k);
        }
    };

    // Blends the segment's samples; writes them straight into the block's
    // leaf when it has one (each block appears once per batch, so workers
    // never share a leaf), else only notes whether the tile changes (the
    // leaf is made afterwards, on one thread). `acc` is the worker's own
    // (unregistered) accessor: lookups only.
    void blendSegment(Segment& s, const BlendInputs& in, Accessor& acc) const {
        const BlendItem& item = items[s.item];
        const openvdb::Coord origin(item.origin[0], item.origin[1], item.origin[2]);
        s.leaf = acc.probeLeaf(origin);  // the leaf is written by this segment only
        if (!s.leaf) s.tileActive = acc.probeValue(origin, s.tileValue);
        s.whole = item.pass == BlendPass::Fine && s.s0 == 0 && s.finishes;
        if (s.whole) blendWholeBlock(s, in);
        else blendSamples(s, in);
    }

    // Most of the work: a whole block at once, compared and stored as 512
    // values and one mask.
    void blendWholeBlock(Segment& s, const BlendInputs& in) const {
        const auto& o = items[s.item].origin;
        BlockValues local;
        if (!s.block) blendBlock(o, in, local);
        const BlockValues& values = s.block ? *s.block : local;
        std::uint8_t diff[kBlockVoxels];
        if (s.leaf) {
            const float* old = s.leaf->buffer().data();
            if (std::memcmp(old, values.v, sizeof values.v) == 0 && s.leaf->getValueMask() == values.mask) return;
            std::uint32_t oldBits[kBlockVoxels], newBits[kBlockVoxels];
            std::uint8_t oldOn[kBlockVoxels];
            std::memcpy(oldBits, old, sizeof oldBits);
            std::memcpy(newBits, values.v, sizeof newBits);
            const auto& mask = s.leaf->getValueMask();
            for (openvdb::Index w = 0; w < FloatLeaf::NodeMaskType::WORD_COUNT; ++w)
                for (openvdb::Index byte = 0; byte < 8; ++byte)
                    unpackBits((mask.getWord<std::uint64_t>(w) >> (8 * byte)) & 0xff, oldOn + 64 * w + 8 * byte);
            diffBytes(oldBits, newBits, oldOn, values.on, diff);
        } else {
            std::uint32_t oldBits[kBlockVoxels], newBits[kBlockVoxels];
            std::uint8_t oldOn[kBlockVoxels];
            std::fill(oldBits, oldBits + kBlockVoxels, bits(s.tileValue));
            std::fill(oldOn, oldOn + kBlockVoxels, static_cast<std::uint8_t>(s.tileActive));
            std::memcpy(newBits, values.v, sizeof newBits);
            diffBytes(oldBits, newBits, oldOn, values.on, diff);
        }
        const BlockChange c = summarize(diff, o);
        if (c.count == 0) return;
        s.changed = c.count;
        std::copy(c.lo, c.lo + 3, s.lo);
        std::copy(c.hi, c.hi + 3, s.hi);
        if (s.leaf) storeBlock(*s.leaf, values);  // else writeNewLeaf() blends it again
    }

    // The segment's sample values: computed off the frame thread, or here
    // into `local` (a block's worth).
    const float* segmentValues(const Segment& s, const BlendInputs& in, float* local) const {
        if (s.values) return s.values;
        sampleValues(items[s.item], s.s0, s.s1, in, local);
        return local;
    }

    // Part of a block, or the coarse lattice: sample by sample.
    void blendSamples(Segment& s, const BlendInputs& in) const {
        const BlendItem& item = items[s.item];
        const auto& o = item.origin;
        float local[kBlockVoxels];
        const float* values = segmentValues(s, in, local);
        std::size_t n = 0;
        forSamples(itemLattice(o, item.pass, in.box), o, s.s0, s.s1, [&](int i, int j, int k, int off) {
            const float v = values[n++];
            const bool on = std::fabs(v) < in.band;
            const auto index = static_cast<openvdb::Index>(off);
            if (s.leaf) {
                if (bits(s.leaf->getValue(index)) == bits(v) && s.leaf->isValueOn(index) == on) return;
                s.leaf->setValueOnly(index, v);
                s.leaf->setActiveState(index, on);
                s.noteChange(i, j, k);
            } else if (bits(s.tileValue) != bits(v) || s.tileActive != on) {
                s.noteChange(i, j, k);  // writeNewLeaf() blends it again
            }
        });
    }

    // A block that was a tile and changed, into its new leaf. It is blended
    // again rather than kept: most tiles do not change (far inside or
    // outside), and keeping every tile's values would cost an allocation each.
    void writeNewLeaf(Segment& s, const BlendInputs& in) const {
        const BlendItem& item = items[s.item];
        const auto& o = item.origin;
        if (s.whole) {
            if (s.block) {
                storeBlock(*s.leaf, *s.block);
                return;
            }
            BlockValues values;
            blendBlock(o, in, values);
            storeBlock(*s.leaf, values);
            return;
        }
        float local[kBlockVoxels];
        const float* values = segmentValues(s, in, local);
        std::size_t n = 0;
        forSamples(itemLattice(o, item.pass, in.box), o, s.s0, s.s1, [&](int, int, int, int off) {
            const float v = values[n++];
            s.leaf->setValueOnly(static_cast<openvdb::Index>(off), v);
            s.leaf->setActiveState(static_cast<openvdb::Index>(off), std::fabs(v) < in.band);
        });
    }

    // The next `samples` samples from the cursor on, never past the end of
    // the coarse pass (so that no block appears twice in one batch); the
    // cursor moves past them.
    std::vector<Segment> take(std::uint64_t samples) {
        std::vector<Segment> segs;
        const std::size_t passEnd = next < coarseItems ? coarseItems : items.size();
        while (samples > 0 && next < passEnd) {
            const BlendItem& item = items[next];
            Segment s;
            s.item = next;
            s.s0 = nextDone;
            s.s1 = static_cast<std::uint32_t>(std::min<std::uint64_t>(item.samples, nextDone + samples));
            s.finishes = s.s1 == item.samples;
            samples -= s.s1 - s.s0;
            consumed += s.s1 - s.s0;
            if (s.finishes) {
                ++next;
                nextDone = 0;
            } else {
                nextDone = s.s1;
            }
            segs.push_back(std::move(s));
        }
        return segs;
    }

    // Blends `samples` samples from the cursor on, in the frame.
    void runBatch(std::uint64_t samples, BlendStep& report) {
        std::vector<Segment> segs = take(samples);
        if (!segs.empty()) write(segs, inputs(sources, weights), report);
    }

    // --- Off the frame thread (stepInBackground) ---

    bool current(const std::shared_ptr<BlendJob>& job) const { return job && job->generation() == generation; }
    static bool holdsCoarse(const std::shared_ptr<BlendJob>& job) {
        return job && !job->pieces().empty() && job->pieces().front().item.pass == BlendPass::Coarse;
    }
    // Samples handed to jobs of these weights and not yet written.
    std::uint64_t inJobs() const {
        std::uint64_t n = current(computing) ? computing->samples() : 0;
        if (writing)
            for (std::size_t i = written; i < writing->pieces().size(); ++i)
                n += writing->pieces()[i].s1 - writing->pieces()[i].s0;
        return n;
    }

    // The next items from the cursor on, as a job for `thread`.
    void submit(jobs::JobThread& thread) {
        const double want = jobSamplesPerSecond > 0.0 ? jobSamplesPerSecond * kJobSeconds
                                                      : static_cast<double>(kBlendBatch);
        const auto samples = static_cast<std::uint64_t>(std::clamp(want, static_cast<double>(kFirstTimedBatch),
                                                                   static_cast<double>(kMostJobSamples)));
        auto job = std::make_shared<BlendJob>(inputs(sources, weights), generation);
        for (const Segment& s : take(samples)) job->add(s.item, items[s.item], s.s0, s.s1);
        computing = job;
        thread.submit(std::move(job));
    }

    // The job the thread finished becomes the one to write, unless it is
    // for older weights (dropped). Never waits.
    void takeFinishedJob() {
        if (writing || !computing || !computing->done()) return;
        const std::shared_ptr<BlendJob> job = std::move(computing);
        computing.reset();
        if (job->generation() != generation) return;
        if (job->error) std::rethrow_exception(job->error);
        if (!job->ran()) {
            // Dropped by a thread that stopped: its items were taken from
            // the list, so the list starts again (what is blended already
            // comes out the same and changes nothing).
            restart();
            return;
        }
        if (job->seconds() > 0.0) jobSamplesPerSecond = static_cast<double>(job->samples()) / job->seconds();
        writing = job;
        written = 0;
    }

    // The written job's next pieces, about `samples` of them (at least one
    // piece), as segments carrying their computed values.
    std::vector<Segment> jobSegments(std::uint64_t samples) {
        std::vector<Segment> segs;
        std::uint64_t n = 0;
        const auto& pieces = writing->pieces();
        while (written < pieces.size() && (segs.empty() || n < samples)) {
            const BlendPiece& p = pieces[written++];
            Segment s;
            s.item = p.index;
            s.s0 = p.s0;
            s.s1 = p.s1;
            s.finishes = p.finishes;
            if (p.whole) s.block = &writing->block(p);
            else s.values = writing->values(p);
            n += p.s1 - p.s0;
            segs.push_back(s);
        }
        return segs;
    }

    // Blends the segments (with the values a job computed, where it did)
    // and stores them in the result grid; the report gains their samples
    // and changes.
    void write(std::vector<Segment>& segs, const BlendInputs& in, BlendStep& report) {
        std::uint64_t batchSamples = 0;
        for (const Segment& s : segs) batchSamples += s.s1 - s.s0;
        report.samples += batchSamples;
        openvdb::FloatTree& tree = voxel::vdb(result).tree();
        // About 4096 samples per task.
        const std::size_t grain = std::max<std::size_t>(1, 4096 / (1 + batchSamples / segs.size()));
        // 1. Blend (in place where the block has a leaf).
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, segs.size(), grain),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              Accessor acc(tree);
                              for (std::size_t i = r.begin(); i != r.end(); ++i) blendSegment(segs[i], in, acc);
                          });
        // 2. Leaves for blocks that were tiles and changed (this changes the
        //    tree: one thread). touchLeaf keeps the tile's value elsewhere.
        bool any = false;
        for (Segment& s : segs) {
            any = any || (s.finishes && items[s.item].pass == BlendPass::Fine);
            if (s.leaf || s.changed == 0) continue;
            const auto& o = items[s.item].origin;
            s.leaf = tree.touchLeaf(openvdb::Coord(o[0], o[1], o[2]));
            s.fresh = true;
            any = true;
        }
        // 3. Fill the new leaves; decide which finished blocks become tiles.
        if (any)
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, segs.size(), grain),
                              [&](const tbb::blocked_range<std::size_t>& r) {
                                  for (std::size_t i = r.begin(); i != r.end(); ++i) {
                                      Segment& s = segs[i];
                                      if (s.fresh) writeNewLeaf(s, in);
                                      if (s.leaf && s.finishes && items[s.item].pass == BlendPass::Fine)
                                          s.collapse = uniformClamped(*s.leaf, in.band, s.collapseValue);
                                  }
                              });
        // 4. Tiles for uniform blocks (one thread), and the report.
        for (Segment& s : segs) {
            const auto& o = items[s.item].origin;
            if (s.collapse) tree.addTile(1, openvdb::Coord(o[0], o[1], o[2]), s.collapseValue, false);
            if (s.finishes && items[s.item].pass == BlendPass::Fine) ++report.blocksFinished;
            if (s.changed == 0) continue;
            report.changedVoxels += s.changed;
            report.changed.push_back(voxel::IndexBox::fromCorners(s.lo[0], s.lo[1], s.lo[2], s.hi[0], s.hi[1], s.hi[2]));
        }
    }
};

MorphBlender::MorphBlender(const MorphSources& sources, voxel::Volume& result)
    : impl_(std::make_unique<Impl>(sources, result)) {
    std::string why = checkResult(sources, result);
    if (!why.empty()) throw std::invalid_argument(why);
}

MorphBlender::~MorphBlender() = default;

void MorphBlender::restart(const MorphWeights& weights, const std::array<double, 3>& viewer) {
    impl_->weights = weights;
    impl_->viewer = impl_->toIndex(viewer);
    impl_->restart();
}

void MorphBlender::setViewer(const std::array<double, 3>& viewer) {
    Impl& m = *impl_;
    m.viewer = m.toIndex(viewer);
    // Called every frame: a viewer that has not moved keeps the order (the
    // re-sort was most of the morph stage at small budgets).
    if (m.viewer == m.sortedFor) return;
    // The item in progress stays first; the rest of its pass and the whole
    // of a later pass are sorted again.
    m.sortFrom(m.next + (m.nextDone > 0 ? 1 : 0));
}

namespace {

// How many samples the next batch of a step may take (0: stop): what the
// budget's count leaves, and under a time limit what the rate fits.
std::uint64_t nextBatch(const BlendBudget& budget, const BlendStep& report, Clock::time_point start, double lastRate,
                        std::uint64_t most = kBlendBatch) {
    std::uint64_t batch = most;
    if (budget.maxSamples > 0) {
        // (A job's values are written a whole piece at a time, so a step may
        // pass the count by less than a block.)
        if (report.samples >= budget.maxSamples) return 0;
        batch = std::min(batch, budget.maxSamples - report.samples);
    }
    const double limit = budget.maxMilliseconds * 1e-3;
    if (limit <= 0.0) return batch;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    if (elapsed >= limit) return 0;
    if (report.samples > 0) {
        // What the rate measured so far fits into the time left.
        const double fits = static_cast<double>(report.samples) / std::max(elapsed, 1e-9) * (limit - elapsed);
        return std::min<std::uint64_t>(batch, static_cast<std::uint64_t>(fits));
    }
    // The first batch of a step: half of what the last step's rate fits
    // (the rate changes from region to region: blocks near the surface cost
    // more than empty ones), or a small one to measure it (a whole batch
    // can take several milliseconds, more than a frame's share).
    const double fits = lastRate > 0.0 ? 0.5 * lastRate * (limit - elapsed) : static_cast<double>(kFirstTimedBatch);
    return std::min<std::uint64_t>(batch, std::max<std::uint64_t>(1, static_cast<std::uint64_t>(fits)));
}

// Hands each batch's changed boxes to the caller, within the step.
void commitNew(const BlendBudget& budget, const BlendStep& report, std::size_t reported) {
    if (budget.commit && report.changed.size() > reported)
        budget.commit(std::vector<voxel::IndexBox>(report.changed.begin() + static_cast<std::ptrdiff_t>(reported),
                                                   report.changed.end()));
}

void finishReport(const MorphBlender& blender, const BlendBudget& budget, Clock::time_point start, BlendStep& report,
                  double& rate) {
    report.coarseDone = blender.coarseDone();
    report.done = blender.done();
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (budget.maxMilliseconds > 0.0 && report.samples > 0 && report.seconds > 0.0)
        rate = static_cast<double>(report.samples) / report.seconds;
}

}  // namespace

BlendStep MorphBlender::step(const BlendBudget& budget) {
    Impl& m = *impl_;
    // The frame blends itself from here on; what the jobs held was taken
    // from the list, so it starts again (a job under way is abandoned, not
    // waited for).
    if (m.writing || m.current(m.computing)) m.restart();
    const auto start = Clock::now();
    BlendStep report;
    while (m.next < m.items.size()) {
        const std::uint64_t batch = nextBatch(budget, report, start, m.samplesPerSecond);
        if (batch == 0) break;
        const std::size_t reported = report.changed.size();
        m.runBatch(batch, report);
        commitNew(budget, report, reported);
    }
    finishReport(*this, budget, start, report, m.samplesPerSecond);
    return report;
}

BlendStep MorphBlender::stepInBackground(const BlendBudget& budget, jobs::JobThread& thread) {
    Impl& m = *impl_;
    const auto start = Clock::now();
    BlendStep report;
    for (;;) {
        m.takeFinishedJob();
        if (!m.writing) break;
        const std::uint64_t most = budget.maxMilliseconds > 0.0 ? kWriteSlice : kBlendBatch;
        const std::uint64_t batch = nextBatch(budget, report, start, m.writeSamplesPerSecond, most);
        if (batch == 0) break;
        std::vector<Impl::Segment> segs = m.jobSegments(batch);
        const std::size_t reported = report.changed.size();
        m.write(segs, m.writing->inputs(), report);
        commitNew(budget, report, reported);
        if (m.written == m.writing->pieces().size()) {
            m.writing.reset();
            m.written = 0;
        }
    }
    if (!m.computing && m.next < m.items.size()) m.submit(thread);
    finishReport(*this, budget, start, report, m.writeSamplesPerSecond);
    return report;
}

bool MorphBlender::done() const {
    const Impl& m = *impl_;
    return m.next >= m.items.size() && !m.writing && !m.current(m.computing);
}

bool MorphBlender::coarseDone() const {
    const Impl& m = *impl_;
    return m.next >= m.coarseItems && !m.holdsCoarse(m.writing) && !(m.current(m.computing) && m.holdsCoarse(m.computing));
}

bool MorphBlender::inBackground() const { return impl_->writing || impl_->current(impl_->computing); }
std::uint64_t MorphBlender::totalSamples() const { return impl_->total; }
std::uint64_t MorphBlender::remainingSamples() const { return impl_->total - impl_->consumed + impl_->inJobs(); }
const MorphWeights& MorphBlender::weights() const { return impl_->weights; }
const std::vector<BlendItem>& MorphBlender::workList() const { return impl_->items; }
std::size_t MorphBlender::cursor() const { return impl_->next; }

}  // namespace hg::garden
