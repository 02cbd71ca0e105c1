#include "polygonizer/lod_pyramid.h"

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
    const openvdb::FloatGrid& grid = impl_->grid(level);
    openvdb::FloatGrid::ConstAccessor acc = grid.getConstAccessor();
    const voxel::IndexBox& inside = impl_->volume->frame.indexBox;
    const float background = grid.background();
    const int s = 1 << level;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k) {
        const bool kIn = k * s >= inside.lo[2] && k * s <= inside.hi[2];
        for (int j = box.lo[1]; j <= box.hi[1]; ++j) {
            const bool jkIn = kIn && j * s >= inside.lo[1] && j * s <= inside.hi[1];
            for (int i = box.lo[0]; i <= box.hi[0]; ++i)
                *out++ = jkIn && i * s >= inside.lo[0] && i * s <= inside.hi[0] ? acc.getValue(Coord(i, j, k)) : background;
        }
    }
}

std::size_t LodPyramid::update(const voxel::IndexBox& box) {
    std::size_t n = 0;
    for (int l = 1; l < levels(); ++l) n += impl_->resample(l, box);
    return n;
}

}  // namespace hg::poly
