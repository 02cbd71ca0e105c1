#include "garden/morph/morph_blend.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "voxel/volume_vdb.h"

namespace hg::garden {

namespace {

using voxel::FloatLeaf;
using Clock = std::chrono::steady_clock;

// The one formula both paths use, so that they agree bit for bit (the build
// never contracts a*b+c into a fused multiply-add).
inline float blendValue(float a, float b, float c, const float w[3], float band) {
    float v = w[0] * a + w[1] * b + w[2] * c;
    return std::min(std::max(v, -band), band);
}

inline std::uint32_t bits(float v) {
    std::uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
}

inline int floorMultiple(int v, int m) { return v >= 0 ? v / m * m : -((-v + m - 1) / m) * m; }
inline int ceilMultiple(int v, int m) { return -floorMultiple(-v, m); }

// The voxels an item blends: start + stride * (x, y, z) for x < count[0], ...
// numbered x fastest (the dense fields' order).
struct Lattice {
    int start[3] = {0, 0, 0};
    int count[3] = {0, 0, 0};
    int stride = 1;
    std::uint32_t size() const {
        return static_cast<std::uint32_t>(count[0]) * static_cast<std::uint32_t>(count[1]) *
               static_cast<std::uint32_t>(count[2]);
    }
};

Lattice itemLattice(const std::array<int, 3>& origin, BlendPass pass, const voxel::IndexBox& indexBox) {
    Lattice l;
    l.stride = pass == BlendPass::Coarse ? kCoarseStride : 1;
    for (int a = 0; a < 3; ++a) {
        int lo = std::max(origin[static_cast<std::size_t>(a)], indexBox.lo[a]);
        int hi = std::min(origin[static_cast<std::size_t>(a)] + kBlendBlock - 1, indexBox.hi[a]);
        if (pass == BlendPass::Coarse) {
            lo = ceilMultiple(lo, kCoarseStride);
            hi = floorMultiple(hi, kCoarseStride);
        }
        l.start[a] = lo;
        l.count[a] = hi >= lo ? (hi - lo) / l.stride + 1 : 0;
    }
    return l;
}

// Every block origin that covers the index box, z outermost.
std::vector<std::array<int, 3>> blockOrigins(const voxel::IndexBox& box) {
    std::vector<std::array<int, 3>> out;
    if (box.empty()) return out;
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = floorMultiple(box.lo[a], kBlendBlock);
        hi[a] = floorMultiple(box.hi[a], kBlendBlock);
    }
    for (int z = lo[2]; z <= hi[2]; z += kBlendBlock)
        for (int y = lo[1]; y <= hi[1]; y += kBlendBlock)
            for (int x = lo[0]; x <= hi[0]; x += kBlendBlock) out.push_back({x, y, z});
    return out;
}

struct BlendInputs {
    const float* f[3];
    float w[3];
    float band;
};

BlendInputs inputs(const MorphSources& s, const MorphWeights& weights) {
    BlendInputs in{};
    for (std::size_t i = 0; i < 3; ++i) {
        in.f[i] = s.fields[i].values.data();
        in.w[i] = static_cast<float>(weights.w[i]);
    }
    in.band = s.frame.band;
    return in;
}

// A block whose 512 stored values all clamp alike (and so are inactive)
// becomes a tile of that value: the narrow band's rule, as in the sampler.
bool uniformClamped(const FloatLeaf& leaf, float band, float& value) {
    if (!leaf.getValueMask().isOff()) return false;
    const std::uint32_t first = bits(leaf.getValue(0));
    if (first != bits(band) && first != bits(-band)) return false;
    for (openvdb::Index i = 1; i < FloatLeaf::SIZE; ++i)
        if (bits(leaf.getValue(i)) != first) return false;
    value = leaf.getValue(0);
    return true;
}

std::string checkResult(const MorphSources& s, const voxel::Volume& result) {
    const voxel::VolumeFrame& a = s.frame;
    const voxel::VolumeFrame& b = result.frame;
    if (!(a.indexBox == b.indexBox) || a.voxelSize != b.voxelSize || a.band != b.band || a.resolution != b.resolution)
        return "the morph result is not in the sources' frame";
    for (int i = 0; i < 3; ++i)
        if (a.modelBox.lo[i] != b.modelBox.lo[i] || a.modelBox.hi[i] != b.modelBox.hi[i])
            return "the morph result is not in the sources' frame";
    return checkSources(s);
}

}  // namespace

voxel::Volume makeMorphVolume(const MorphSources& sources) {
    voxel::Volume v;
    v.frame = sources.frame;
    v.normalization = 1.0;  // the blend is already in voxels
    v.kind = voxel::VolumeKind::NarrowBand;
    v.source.body = "morph";
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(-sources.frame.band);
    grid->setTransform(voxel::frameTransform(sources.frame));
    grid->setName("morph");
    v.grid().grid = grid;
    return v;
}

voxel::Volume blendMorph(const MorphSources& sources, const MorphWeights& weights) {
    std::string why = checkSources(sources);
    if (!why.empty()) throw std::invalid_argument(why);
    voxel::Volume result = makeMorphVolume(sources);
    const voxel::DenseField& field = sources.fields[0];
    const voxel::IndexBox& box = sources.frame.indexBox;
    const BlendInputs in = inputs(sources, weights);
    const std::vector<std::array<int, 3>> origins = blockOrigins(box);
    std::vector<std::unique_ptr<FloatLeaf>> leaves(origins.size());
    std::vector<char> insideTile(origins.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, origins.size()), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t b = r.begin(); b != r.end(); ++b) {
            const auto& o = origins[b];
            auto leaf = std::make_unique<FloatLeaf>(openvdb::Coord(o[0], o[1], o[2]), -in.band, false);
            Lattice l = itemLattice(o, BlendPass::Fine, box);
            for (int z = 0; z < l.count[2]; ++z)
                for (int y = 0; y < l.count[1]; ++y) {
                    const int k = l.start[2] + z, j = l.start[1] + y;
                    std::size_t d = field.at(l.start[0], j, k);
                    for (int x = 0; x < l.count[0]; ++x, ++d) {
                        float v = blendValue(in.f[0][d], in.f[1][d], in.f[2][d], in.w, in.band);
                        openvdb::Index off = FloatLeaf::coordToOffset(openvdb::Coord(l.start[0] + x, j, k));
                        leaf->setValueOnly(off, v);
                        leaf->setActiveState(off, std::fabs(v) < in.band);
                    }
                }
            float uniform = 0.0f;
            if (uniformClamped(*leaf, in.band, uniform)) {
                insideTile[b] = uniform > 0.0f;  // outside: the background already
                continue;
            }
            leaves[b] = std::move(leaf);
        }
    });
    openvdb::FloatTree& tree = voxel::vdb(result).tree();
    for (std::size_t b = 0; b < origins.size(); ++b) {
        const openvdb::Coord c(origins[b][0], origins[b][1], origins[b][2]);
        if (leaves[b]) tree.addLeaf(leaves[b].release());
        else if (insideTile[b]) tree.addTile(1, c, in.band, false);
    }
    return result;
}

// --- the budgeted partial update ------------------------------------------

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

    Impl(const MorphSources& s, voxel::Volume& r) : sources(s), result(r) {}

    std::array<double, 3> toIndex(const std::array<double, 3>& model) const {
        const voxel::VolumeFrame& f = sources.frame;
        return {(model[0] - f.modelBox.lo[0]) / f.voxelSize, (model[1] - f.modelBox.lo[1]) / f.voxelSize,
                (model[2] - f.modelBox.lo[2]) / f.voxelSize};
    }

    void sortRange(std::size_t first, std::size_t last) {
        if (first >= last) return;
        auto key = [&](const BlendItem& it) {
            double d = 0.0;
            for (std::size_t a = 0; a < 3; ++a) {
                double c = it.origin[a] + 0.5 * (kBlendBlock - 1) - viewer[a];
                d += c * c;
            }
            return d;
        };
        std::sort(items.begin() + static_cast<std::ptrdiff_t>(first), items.begin() + static_cast<std::ptrdiff_t>(last),
                  [&](const BlendItem& a, const BlendItem& b) {
                      double ka = key(a), kb = key(b);
                      if (ka != kb) return ka < kb;
                      return std::array<int, 3>{a.origin[2], a.origin[1], a.origin[0]} <
                             std::array<int, 3>{b.origin[2], b.origin[1], b.origin[0]};
                  });
    }

    void build() {
        items.clear();
        const voxel::IndexBox& box = sources.frame.indexBox;
        std::vector<std::array<int, 3>> origins = blockOrigins(box);
        for (const auto& o : origins) {
            std::uint32_t n = itemLattice(o, BlendPass::Coarse, box).size();
            if (n > 0) items.push_back({o, BlendPass::Coarse, n});
        }
        coarseItems = items.size();
        for (const auto& o : origins) items.push_back({o, BlendPass::Fine, itemLattice(o, BlendPass::Fine, box).size()});
        sortRange(0, coarseItems);
        sortRange(coarseItems, items.size());
        next = 0;
        nextDone = 0;
        consumed = 0;
        total = 0;
        for (const auto& it : items) total += it.samples;
    }

    // One item's share of a batch.
    struct Segment {
        std::size_t item = 0;
        std::uint32_t s0 = 0, s1 = 0;   // sample range of the item
        bool finishes = false;          // s1 is the item's end
        FloatLeaf* leaf = nullptr;
        std::vector<float> pending;     // new values when the block was a tile
        float tileValue = 0.0f;
        bool tileActive = false;
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

    // Calls visit(i, j, k, denseOffset, n) for samples [s0, s1) of the
    // lattice, in runs along x (n samples, `stride` apart).
    template <class Visit>
    static void forRuns(const Lattice& l, std::uint32_t s0, std::uint32_t s1, const voxel::DenseField& field,
                        Visit&& visit) {
        const std::uint32_t nx = static_cast<std::uint32_t>(l.count[0]), ny = static_cast<std::uint32_t>(l.count[1]);
        std::uint32_t r = s0;
        while (r < s1) {
            const std::uint32_t x = r % nx, y = (r / nx) % ny, z = r / (nx * ny);
            const std::uint32_t n = std::min(nx - x, s1 - r);
            const int i = l.start[0] + l.stride * static_cast<int>(x);
            const int j = l.start[1] + l.stride * static_cast<int>(y);
            const int k = l.start[2] + l.stride * static_cast<int>(z);
            visit(i, j, k, field.at(i, j, k), n);
            r += n;
        }
    }

    // Blends the segment's samples; writes them straight into the block's
    // leaf when it has one (each block appears once per batch, so workers
    // never share a leaf), else keeps them for after the leaf is made.
    void blendSegment(Segment& s, const BlendInputs& in, openvdb::FloatTree& tree) const {
        const BlendItem& item = items[s.item];
        const Lattice l = itemLattice(item.origin, item.pass, sources.frame.indexBox);
        const voxel::DenseField& field = sources.fields[0];
        const openvdb::Coord origin(item.origin[0], item.origin[1], item.origin[2]);
        s.leaf = tree.probeLeaf(origin);  // a lookup; the leaf is written by this segment only
        if (!s.leaf) {
            s.tileActive = tree.probeValue(origin, s.tileValue);
            s.pending.reserve(s.s1 - s.s0);
        }
        const std::size_t stride = static_cast<std::size_t>(l.stride);
        forRuns(l, s.s0, s.s1, field, [&](int i, int j, int k, std::size_t d, std::uint32_t n) {
            for (std::uint32_t x = 0; x < n; ++x, d += stride) {
                const int ix = i + l.stride * static_cast<int>(x);
                const float v = blendValue(in.f[0][d], in.f[1][d], in.f[2][d], in.w, in.band);
                const bool on = std::fabs(v) < in.band;
                if (s.leaf) {
                    const openvdb::Index off = FloatLeaf::coordToOffset(openvdb::Coord(ix, j, k));
                    if (bits(s.leaf->getValue(off)) == bits(v) && s.leaf->isValueOn(off) == on) continue;
                    s.leaf->setValueOnly(off, v);
                    s.leaf->setActiveState(off, on);
                    s.noteChange(ix, j, k);
                } else {
                    s.pending.push_back(v);
                    if (bits(s.tileValue) != bits(v) || s.tileActive != on) s.noteChange(ix, j, k);
                }
            }
        });
    }

    // Writes the values kept for a block that was a tile into its new leaf.
    void writePending(Segment& s, const BlendInputs& in) const {
        const BlendItem& item = items[s.item];
        const Lattice l = itemLattice(item.origin, item.pass, sources.frame.indexBox);
        std::size_t p = 0;
        forRuns(l, s.s0, s.s1, sources.fields[0], [&](int i, int j, int k, std::size_t, std::uint32_t n) {
            for (std::uint32_t x = 0; x < n; ++x, ++p) {
                const openvdb::Index off =
                    FloatLeaf::coordToOffset(openvdb::Coord(i + l.stride * static_cast<int>(x), j, k));
                s.leaf->setValueOnly(off, s.pending[p]);
                s.leaf->setActiveState(off, std::fabs(s.pending[p]) < in.band);
            }
        });
    }

    // Blends `samples` samples from the cursor on, never past the end of the
    // coarse pass (so that no block appears twice in one batch).
    void runBatch(std::uint64_t samples, BlendStep& report) {
        std::vector<Segment> segs;
        const std::uint64_t samplesBefore = report.samples;
        const std::size_t passEnd = next < coarseItems ? coarseItems : items.size();
        while (samples > 0 && next < passEnd) {
            const BlendItem& item = items[next];
            Segment s;
            s.item = next;
            s.s0 = nextDone;
            s.s1 = static_cast<std::uint32_t>(std::min<std::uint64_t>(item.samples, nextDone + samples));
            s.finishes = s.s1 == item.samples;
            samples -= s.s1 - s.s0;
            report.samples += s.s1 - s.s0;
            consumed += s.s1 - s.s0;
            if (s.finishes) {
                ++next;
                nextDone = 0;
            } else {
                nextDone = s.s1;
            }
            segs.push_back(std::move(s));
        }
        if (segs.empty()) return;
        const std::uint64_t batchSamples = report.samples - samplesBefore;

        const BlendInputs in = inputs(sources, weights);
        openvdb::FloatTree& tree = voxel::vdb(result).tree();
        const std::size_t grain = std::max<std::size_t>(1, 4096 / (1 + batchSamples / segs.size()));
        // 1. Blend (in place where the block has a leaf).
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, segs.size(), grain),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t i = r.begin(); i != r.end(); ++i) blendSegment(segs[i], in, tree);
                          });
        // 2. Leaves for blocks that were tiles and changed (this changes the
        //    tree: one thread). touchLeaf keeps the tile's value elsewhere.
        for (Segment& s : segs) {
            if (s.leaf || s.changed == 0) continue;
            const auto& o = items[s.item].origin;
            s.leaf = tree.touchLeaf(openvdb::Coord(o[0], o[1], o[2]));
        }
        // 3. Fill the new leaves; decide which finished blocks become tiles.
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, segs.size(), grain),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t i = r.begin(); i != r.end(); ++i) {
                                  Segment& s = segs[i];
                                  if (!s.pending.empty() && s.changed > 0) writePending(s, in);
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
    impl_->build();
}

void MorphBlender::setViewer(const std::array<double, 3>& viewer) {
    Impl& m = *impl_;
    m.viewer = m.toIndex(viewer);
    // The item in progress stays first; the rest of its pass and the whole
    // of a later pass are sorted again.
    std::size_t first = m.next + (m.nextDone > 0 ? 1 : 0);
    if (first < m.coarseItems) {
        m.sortRange(first, m.coarseItems);
        m.sortRange(m.coarseItems, m.items.size());
    } else {
        m.sortRange(first, m.items.size());
    }
}

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
            }
        }
        if (batch == 0) break;
        m.runBatch(batch, report);
    }
    report.coarseDone = coarseDone();
    report.done = done();
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
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
