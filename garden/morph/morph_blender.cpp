// MorphBlender: the budgeted partial update of morph_blend.h.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "garden/morph/blend_block_vdb.h"
#include "garden/morph/morph_blend.h"

namespace hg::garden {

using namespace blend;

namespace {

using Clock = std::chrono::steady_clock;

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

    Impl(const MorphSources& s, voxel::Volume& r) : sources(s), result(r) {}

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

    // Calls visit(i, j, k, leafOffset) for samples [s0, s1) of the lattice.
    template <class Visit>
    static void forSamples(const Lattice& l, const std::array<int, 3>& o, std::uint32_t s0, std::uint32_t s1,
                           Visit&& visit) {
        const std::uint32_t nx = static_cast<std::uint32_t>(l.count[0]), ny = static_cast<std::uint32_t>(l.count[1]);
        for (std::uint32_t r = s0; r < s1; ++r) {
            const int i = l.start[0] + l.stride * static_cast<int>(r % nx);
            const int j = l.start[1] + l.stride * static_cast<int>((r / nx) % ny);
            const int k = l.start[2] + l.stride * static_cast<int>(r / (nx * ny));
            visit(i, j, k, blockOffset(i - o[0], j - o[1], k - o[2]));
        }
    }

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
        BlockValues values;
        blendBlock(o, in, values);
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

    // Part of a block, or the coarse lattice: sample by sample. The coarse
    // lattice reads the sources' compact copies (the same floats).
    void blendSamples(Segment& s, const BlendInputs& in) const {
        const BlendItem& item = items[s.item];
        const auto& o = item.origin;
        const Lattice l = itemLattice(o, item.pass, in.box);
        const float* src[3];
        for (std::size_t f = 0; f < 3; ++f)
            src[f] = item.pass == BlendPass::Coarse ? in.f[f]->coarse(o) : in.f[f]->block(o);
        forSamples(l, o, s.s0, s.s1, [&](int i, int j, int k, int off) {
            const int at = item.pass == BlendPass::Coarse ? coarseOffset(i - o[0], j - o[1], k - o[2]) : off;
            const float v = blendValue(src[0][at], src[1][at], src[2][at], in.w[0], in.w[1], in.w[2], in.band);
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
            BlockValues values;
            blendBlock(o, in, values);
            storeBlock(*s.leaf, values);
            return;
        }
        const Lattice l = itemLattice(o, item.pass, in.box);
        const float* a = in.f[0]->block(o);
        const float* b = in.f[1]->block(o);
        const float* c = in.f[2]->block(o);
        forSamples(l, o, s.s0, s.s1, [&](int, int, int, int off) {
            const float v = blendValue(a[off], b[off], c[off], in.w[0], in.w[1], in.w[2], in.band);
            s.leaf->setValueOnly(static_cast<openvdb::Index>(off), v);
            s.leaf->setActiveState(static_cast<openvdb::Index>(off), std::fabs(v) < in.band);
        });
    }

    // Blends `samples` samples from the cursor on, never past the end of the
    // coarse pass (so that no block appears twice in one batch).
    void runBatch(std::uint64_t samples, BlendStep& report) {
        std::vector<Segment> segs;
        const std::size_t passEnd = next < coarseItems ? coarseItems : items.size();
        std::uint64_t batchSamples = 0;
        while (samples > 0 && next < passEnd) {
            const BlendItem& item = items[next];
            Segment s;
            s.item = next;
            s.s0 = nextDone;
            s.s1 = static_cast<std::uint32_t>(std::min<std::uint64_t>(item.samples, nextDone + samples));
            s.finishes = s.s1 == item.samples;
            samples -= s.s1 - s.s0;
            batchSamples += s.s1 - s.s0;
            if (s.finishes) {
                ++next;
                nextDone = 0;
            } else {
                nextDone = s.s1;
            }
            segs.push_back(std::move(s));
        }
        if (segs.empty()) return;
        report.samples += batchSamples;
        consumed += batchSamples;

        const BlendInputs in = inputs(sources, weights);
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
constexpr std::uint64_t kFirstTimedBatch = 4096;
}  // namespace

BlendStep MorphBlender::step(const BlendBudget& budget) {
    Impl& m = *impl_;
    const auto start = Clock::now();
    BlendStep report;
    const double limit = budget.maxMilliseconds * 1e-3;
    while (m.next < m.items.size()) {
        std::uint64_t batch = kBlendBatch;
        if (budget.maxSamples > 0) batch = std::min(batch, budget.maxSamples - report.samples);
        if (limit > 0.0) {
            double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
            if (elapsed >= limit) break;
            if (report.samples > 0) {
                // What the rate measured so far fits into the time left.
                double fits = static_cast<double>(report.samples) / std::max(elapsed, 1e-9) * (limit - elapsed);
                batch = std::min<std::uint64_t>(batch, static_cast<std::uint64_t>(fits));
            } else {
                // The first batch of a step: half of what the last step's
                // rate fits (the rate changes from region to region: blocks
                // near the surface cost more than empty ones), or a small
                // one to measure it (a whole batch can take several
                // milliseconds, more than a frame's share).
                const double fits = m.samplesPerSecond > 0.0 ? 0.5 * m.samplesPerSecond * (limit - elapsed)
                                                              : static_cast<double>(kFirstTimedBatch);
                batch = std::min<std::uint64_t>(batch, std::max<std::uint64_t>(1, static_cast<std::uint64_t>(fits)));
            }
        }
        if (batch == 0) break;
        const std::size_t reported = report.changed.size();
        m.runBatch(batch, report);
        if (budget.commit && report.changed.size() > reported)
            budget.commit(std::vector<voxel::IndexBox>(report.changed.begin() + static_cast<std::ptrdiff_t>(reported),
                                                       report.changed.end()));
    }
    report.coarseDone = coarseDone();
    report.done = done();
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (limit > 0.0 && report.samples > 0 && report.seconds > 0.0)
        m.samplesPerSecond = static_cast<double>(report.samples) / report.seconds;
    return report;
}

bool MorphBlender::done() const { return impl_->next >= impl_->items.size(); }
bool MorphBlender::coarseDone() const { return impl_->next >= impl_->coarseItems; }
std::uint64_t MorphBlender::totalSamples() const { return impl_->total; }
std::uint64_t MorphBlender::remainingSamples() const { return impl_->total - impl_->consumed; }
const MorphWeights& MorphBlender::weights() const { return impl_->weights; }
const std::vector<BlendItem>& MorphBlender::workList() const { return impl_->items; }
std::size_t MorphBlender::cursor() const { return impl_->next; }

}  // namespace hg::garden
