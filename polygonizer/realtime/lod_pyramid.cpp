#include "polygonizer/realtime/lod_pyramid.h"

#include <stdexcept>
#include <vector>

#include "voxel/volume_vdb.h"

namespace hg::poly {

namespace {

using openvdb::Coord;

// Level-L index of the first level-L voxel at or above level-0 index v.
int ceilShift(int v, int level) { return -((-v) >> level); }
int floorShift(int v, int level) { return v >> level; }

}  // namespace

struct LodPyramid::Impl {
    const voxel::Volume* volume;
    std::vector<openvdb::FloatGrid::Ptr> grids;  // levels 1..n-1 (level 0 is the volume's)

    const openvdb::FloatGrid& grid(int level) const {
        return level == 0 ? voxel::vdb(*volume) : *grids[static_cast<size_t>(level - 1)];
    }

    // Level-L voxels sampling the level-0 box, from level 0 directly.
    std::size_t resample(int level, const voxel::IndexBox& box) {
        openvdb::FloatGrid& coarse = *grids[static_cast<size_t>(level - 1)];
        openvdb::FloatGrid::Accessor out = coarse.getAccessor();
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
        const openvdb::FloatGrid& fine = grid(level - 1);
        auto coarse = openvdb::FloatGrid::create(fine.background());
        auto xform = fine.transform().copy();
        xform->preScale(2.0);
        coarse->setTransform(xform);
        for (auto it = fine.tree().cbeginValueAll(); it; ++it) {
            // Internal nodes list every empty slot as a background tile: those
            // the coarse grid's background already holds.
            if (it.isVoxelValue() || (!it.isValueOn() && *it == fine.background())) continue;
            openvdb::CoordBBox bb;
            it.getBoundingBox(bb);
            Coord lo(ceilShift(bb.min().x(), 1), ceilShift(bb.min().y(), 1), ceilShift(bb.min().z(), 1));
            Coord hi(floorShift(bb.max().x(), 1), floorShift(bb.max().y(), 1), floorShift(bb.max().z(), 1));
            if (lo.x() <= hi.x() && lo.y() <= hi.y() && lo.z() <= hi.z())
                coarse->tree().fill(openvdb::CoordBBox(lo, hi), *it, it.isValueOn());
        }
        openvdb::FloatGrid::Accessor out = coarse->getAccessor();
        for (auto leaf = fine.tree().cbeginLeaf(); leaf; ++leaf)
            for (auto v = leaf->cbeginValueAll(); v; ++v) {
                const Coord c = v.getCoord();
                if ((c.x() & 1) || (c.y() & 1) || (c.z() & 1)) continue;
                const Coord half(c.x() >> 1, c.y() >> 1, c.z() >> 1);
                if (v.isValueOn()) out.setValueOn(half, *v);
                else out.setValueOff(half, *v);
            }
        grids.push_back(coarse);
    }
};

LodPyramid::LodPyramid(const voxel::Volume& volume, int levels) : impl_(std::make_unique<Impl>()) {
    if (levels < 1 || levels > 8) throw std::invalid_argument("a pyramid has 1 to 8 levels");
    impl_->volume = &volume;
    for (int l = 1; l < levels; ++l) impl_->build(l);
}

LodPyramid::~LodPyramid() = default;

int LodPyramid::levels() const { return static_cast<int>(impl_->grids.size()) + 1; }

float LodPyramid::value(int level, int i, int j, int k) const {
    return impl_->grid(level).tree().getValue(Coord(i, j, k));
}

void LodPyramid::gather(int level, const voxel::IndexBox& box, float* out) const {
    // A leaf at a time (one probe per 8^3 block, then its buffer), not a
    // tree lookup per voxel: this is most of a chunk remesh otherwise.
    const openvdb::FloatTree& tree = impl_->grid(level).tree();
    const float background = tree.background();
    // The level-L indices whose level-0 position lies in the index box.
    const voxel::IndexBox& inside = impl_->volume->frame.indexBox;
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

std::size_t LodPyramid::update(const voxel::IndexBox& box) {
    std::size_t n = 0;
    for (int l = 1; l < levels(); ++l) n += impl_->resample(l, box);
    return n;
}

}  // namespace hg::poly
