// The LOD pyramid: every coarse voxel is the level-0 value at its scaled
// position (tiles included), and a local update after a region resample
// gives the same levels as building the pyramid again, touching only the
// voxels that sample the region.
#include <gtest/gtest.h>

#include <random>

#include "sample_program.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "voxel/sampler.h"

namespace hg::poly {
namespace {

frep::Model sphere(double r2) {
    return ::hg::test::modelFromSource("q(x[3], a[1]) { q = a[1] - (x[1]^2 + x[2]^2 + x[3]^2); }", {r2});
}

voxel::Volume sample(const frep::Model& m) { return test::sampleInUnitCube(m, 96); }

void expectSampled(const voxel::Volume& v, const LodPyramid& p, const voxel::IndexBox& box) {
    for (int l = 1; l < p.levels(); ++l)
        for (int i = box.lo[0] >> l; i <= box.hi[0] >> l; ++i)
            for (int j = box.lo[1] >> l; j <= box.hi[1] >> l; ++j)
                for (int k = box.lo[2] >> l; k <= box.hi[2] >> l; ++k)
                    ASSERT_EQ(p.value(l, i, j, k), v.value(i * (1 << l), j * (1 << l), k * (1 << l))) << "level " << l << " at " << i << "," << j << "," << k;
}

TEST(LodPyramid, CoarseVoxelsAreFineSamples) {
    frep::Model m = sphere(0.5);
    voxel::Volume v = sample(m);
    LodPyramid p(v, 4);
    EXPECT_EQ(p.levels(), 4);
    expectSampled(v, p, v.frame.indexBox);
}

TEST(LodPyramid, LocalUpdateEqualsARebuild) {
    frep::Model small = sphere(0.3), large = sphere(0.5);
    voxel::Volume v = sample(small);
    LodPyramid p(v, 4);
    const voxel::IndexBox region = voxel::IndexBox::fromCorners(10, 20, 30, 60, 50, 77);
    voxel::resampleRegion(v, large, region);
    std::size_t written = p.update(region);
    EXPECT_LE(written, region.volume() / 8 + region.volume() / 64 + region.volume() / 512 + 3000);
    LodPyramid rebuilt(v, 4);
    const voxel::IndexBox& all = v.frame.indexBox;
    for (int l = 1; l < 4; ++l)
        for (int i = all.lo[0] >> l; i <= all.hi[0] >> l; ++i)
            for (int j = all.lo[1] >> l; j <= all.hi[1] >> l; ++j)
                for (int k = all.lo[2] >> l; k <= all.hi[2] >> l; ++k)
                    ASSERT_EQ(p.value(l, i, j, k), rebuilt.value(l, i, j, k)) << "level " << l;
    EXPECT_THROW(LodPyramid(v, 0), std::invalid_argument);
}

TEST(LodPyramid, GatherReadsTheLevelInsideTheIndexBoxAndBackgroundOutside) {
    frep::Model m = sphere(0.5);
    voxel::Volume v = sample(m);
    LodPyramid p(v, 3);
    const voxel::IndexBox& in = v.frame.indexBox;
    for (int l = 0; l < 3; ++l) {
        // A box reaching past the index box on every side, unaligned.
        voxel::IndexBox box = voxel::IndexBox::fromCorners((in.lo[0] >> l) - 5, (in.lo[1] >> l) - 3, (in.lo[2] >> l) - 9,
                                                           (in.hi[0] >> l) + 4, (in.hi[1] >> l) + 7, (in.hi[2] >> l) + 2);
        std::vector<float> out(static_cast<std::size_t>(box.volume()));
        p.gather(l, box, out.data());
        std::size_t n = 0, outside = 0;
        for (int k = box.lo[2]; k <= box.hi[2]; ++k)
            for (int j = box.lo[1]; j <= box.hi[1]; ++j)
                for (int i = box.lo[0]; i <= box.hi[0]; ++i, ++n) {
                    const int s = 1 << l;
                    const bool inside = in.contains(i * s, j * s, k * s);
                    outside += !inside;
                    const float expected = inside ? p.value(l, i, j, k) : -v.frame.band;
                    ASSERT_EQ(out[n], expected) << "level " << l << " at " << i << "," << j << "," << k;
                }
        EXPECT_GT(outside, 0u);
    }
}

}  // namespace
}  // namespace hg::poly
