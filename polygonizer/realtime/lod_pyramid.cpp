#include "polygonizer/realtime/lod_pyramid.h"

#include <stdexcept>
#include <type_traits>
#include <vector>

#include "voxel/volume_vdb.h"

namespace hg::poly {

namespace {

using openvdb::Coord;

// The coarse levels' trees: the same 8^3 leaves as the sculpture's grid,
// with internal nodes of 8^3 children instead of OpenVDB's 32^3 and 16^3.
// A standard tree's top node is a 32,768-entry table (256 KiB) and its
// next a 4,096-entry one (32 KiB), however few voxels they hold; a frame's
// index box starts below 0 (the band's padding), so a small sculpture's
// grid straddles the origin and needs up to eight of each. At 64^3 the
// three coarse levels of a sculpture held about 2 MiB, more than its grid.
// Here those tables are 512 entries (4 KiB); a top node covers 512 voxels
// a side, enough for a coarse level in one or two per axis. Values, and
// so meshes, are the same: only the tree's shape differs.
using CoarseTree = openvdb::tree::Tree4<float, 3, 3, 3>::Type;
using CoarseGrid = openvdb::Grid<CoarseTree>;
static_assert(std::is_same_v<CoarseTree::LeafNodeType, openvdb::FloatTree::LeafNodeType>,
              "both trees share their leaves (gather reads either)");

// Level-L index of the first level-L voxel at or above level-0 index v.
int ceilShift(int v, int level) { return -((-v) >> level); }
int floorShift(int v, int level) { return v >> level; }

}  // namespace

struct LodPyramid::Impl {
    const voxel::Volume* volume;
    std::vector<CoarseGrid::Ptr> grids;  // levels 1..n-1 (level 0 is the volume's)

    // f(tree) with level `level`'s tree (of either type).
    template <class F>
    decltype(auto) withTree(int level, F&& f) const {
        if (level == 0) return f(voxel::vdb(*volume).tree());
        return f(grids[static_cast<size_t>(level - 1)]->tree());
    }

    // Level-L voxels sampling the level-0 box, from level 0 directly.
    std::size_t resample(int level, const voxel::IndexBox& box) {
        CoarseGrid& coarse = *grids[static_cast<size_t>(level - 1)];
        CoarseGrid::Accessor out = coarse.getAccessor();
        openvdb::FloatGrid::ConstAccessor in = voxel::vdb(*volume).getConstAccessor();
        const float band = volume->frame.band;
        std::size_t n = 0;
        for (int i = ceilShift(box.lo[0], level); i <= floorShift(box.hi[0], level); ++i)
            for (int j = ceilShift(box.lo[1], level); j <= floorShift(box.hi[1], level); ++j)
                for (int k = ceilShift(box.lo[2], level); k <= floorShift(box.hi[2], level); ++k) {
                    const int s = 1 << level;  // multiply: shifting a negative index left is undefined
                    const Coord fine(i * s, j * s, k * s);
                    const float v = in.getValue(fine);
                    if (std::fabs(v) < band) out.setValueOn(Coord(i, j, k), v);
                    else out.setValueOff(Coord(i, j, k), v);
                    ++n;
                }
        return n;
    }

    // Whole level from the level below: tiles first (scaled), then the
    // even voxels of its leaves.
    void build(int level) {
        auto coarse = CoarseGrid::create(voxel::vdb(*volume).background());
        auto xform = voxel::vdb(*volume).transform().copy();
        xform->preScale(static_cast<double>(1 << level));
        coarse->setTransform(xform);
        withTree(level - 1, [&](const auto& fine) { halve(fine, *coarse); });
        grids.push_back(coarse);
    }

    template <class FineTree>
    static void halve(const FineTree& fine, CoarseGrid& coarse) {
        for (auto it = fine.cbeginValueAll(); it; ++it) {
            // Internal nodes list every empty slot as a background tile: those
            // the coarse grid's background already holds.
            if (it.isVoxelValue() || (!it.isValueOn() && *it == fine.background())) continue;
            openvdb::CoordBBox bb;
            it.getBoundingBox(bb);
            Coord lo(ceilShift(bb.min().x(), 1), ceilShift(bb.min().y(), 1), ceilShift(bb.min().z(), 1));
            Coord hi(floorShift(bb.max().x(), 1), floorShift(bb.max().y(), 1), floorShift(bb.max().z(), 1));
            if (lo.x() <= hi.x() && lo.y() <= hi.y() && lo.z() <= hi.z())
                coarse.tree().fill(openvdb::CoordBBox(lo, hi), *it, it.isValueOn());
        }
        CoarseGrid::Accessor out = coarse.getAccessor();
        for (auto leaf = fine.cbeginLeaf(); leaf; ++leaf)
            for (auto v = leaf->cbeginValueAll(); v; ++v) {
                const Coord c = v.getCoord();
                if ((c.x() & 1) || (c.y() & 1) || (c.z() & 1)) continue;
                const Coord half(c.x() >> 1, c.y() >> 1, c.z() >> 1);
                if (v.isValueOn()) out.setValueOn(half, *v);
                else out.setValueOff(half, *v);
            }
    }
};

LodPyramid::LodPyramid(const voxel::Volume& volume, int levels) : impl_(std::make_unique<Impl>()) {
    if (levels < 1 || levels > 8) throw std::invalid_argument("a pyramid has 1 to 8 levels");
    impl_->volume = &volume;
    for (int l = 1; l < levels; ++l) impl_->build(l);
}

LodPyramid::LodPyramid(const LodPyramid& source, const voxel::Volume& volume) : impl_(std::make_unique<Impl>()) {
    impl_->volume = &volume;
    for (const CoarseGrid::Ptr& g : source.impl_->grids) impl_->grids.push_back(g->deepCopy());
}

LodPyramid::~LodPyramid() = default;

int LodPyramid::levels() const { return static_cast<int>(impl_->grids.size()) + 1; }

const voxel::Volume& LodPyramid::volume() const { return *impl_->volume; }

std::size_t LodPyramid::memoryBytes() const {
    std::size_t n = 0;
    for (const auto& g : impl_->grids) n += static_cast<std::size_t>(g->memUsage());
    return n;
}

float LodPyramid::value(int level, int i, int j, int k) const {
    return impl_->withTree(level, [&](const auto& tree) { return tree.getValue(Coord(i, j, k)); });
}

namespace {

// LodPyramid::gather on one level's tree (of either type).
template <class Tree>
void gatherFrom(const Tree& tree, const voxel::Volume& volume, int level, const voxel::IndexBox& box, float* out) {
    // A leaf at a time (one probe per 8^3 block, then its buffer), not a
    // tree lookup per voxel: this is most of a chunk remesh otherwise.
    const float background = tree.background();
    // The level-L indices whose level-0 position lies in the index box.
    const voxel::IndexBox& inside = volume.frame.indexBox;
    int in[2][3];
    for (int a = 0; a < 3; ++a) {
        in[0][a] = ceilShift(inside.lo[a], level);
        in[1][a] = floorShift(inside.hi[a], level);
    }
    const int ex = box.extent(0), ey = box.extent(1);
    auto slot = [&](int i, int j, int k) {
        return static_cast<std::size_t>((k - box.lo[2]) * ey + (j - box.lo[1])) * static_cast<std::size_t>(ex) +
               static_cast<std::size_t>(i - box.lo[0]);
    };
    using Leaf = openvdb::FloatTree::LeafNodeType;
    for (int bz = box.lo[2] & ~7; bz <= box.hi[2]; bz += 8)
        for (int by = box.lo[1] & ~7; by <= box.hi[1]; by += 8)
            for (int bx = box.lo[0] & ~7; bx <= box.hi[0]; bx += 8) {
                const Leaf* leaf = tree.probeConstLeaf(Coord(bx, by, bz));
                const float tile = leaf ? 0.0f : tree.getValue(Coord(bx, by, bz));
                const float* data = leaf ? leaf->buffer().data() : nullptr;
                const int i0 = std::max(bx, box.lo[0]), i1 = std::min(bx + 7, box.hi[0]);
                // The part of the row inside the index box; the rest is background.
                const int in0 = std::max(i0, in[0][0]), in1 = std::min(i1, in[1][0]);
                for (int k = std::max(bz, box.lo[2]); k <= std::min(bz + 7, box.hi[2]); ++k)
                    for (int j = std::max(by, box.lo[1]); j <= std::min(by + 7, box.hi[1]); ++j) {
                        float* rowOut = out + slot(box.lo[0], j, k);
                        auto at = [&](int i) { return rowOut + (i - box.lo[0]); };
                        const bool jkIn = k >= in[0][2] && k <= in[1][2] && j >= in[0][1] && j <= in[1][1];
                        if (!jkIn || in0 > in1) {
                            std::fill(at(i0), at(i1 + 1), background);
                            continue;
                        }
                        std::fill(at(i0), at(in0), background);
                        std::fill(at(in1 + 1), at(i1 + 1), background);
                        if (!data) {
                            std::fill(at(in0), at(in1 + 1), tile);
                            continue;
                        }
                        const float* row = data + (((j & 7) << 3) | (k & 7));  // leaf offsets: x << 6 | y << 3 | z
                        for (int i = in0; i <= in1; ++i) *at(i) = row[(i & 7) << 6];
                    }
            }
}

}  // namespace

void LodPyramid::gather(int level, const voxel::IndexBox& box, float* out) const {
    impl_->withTree(level, [&](const auto& tree) { gatherFrom(tree, *impl_->volume, level, box, out); });
}


std::size_t LodPyramid::update(const voxel::IndexBox& box) {
    std::size_t n = 0;
    for (int l = 1; l < levels(); ++l) n += impl_->resample(l, box);
    return n;
}

}  // namespace hg::poly
