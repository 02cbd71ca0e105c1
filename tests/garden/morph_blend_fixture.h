// What the morph blender's tests share: snapshots of a grid's voxels to
// compare bit for bit, and three sources at 40^3 with weights between them.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <set>
#include <vector>

#include "garden/morph/morph_blend.h"
#include "garden_test_util.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "voxel/volume_vdb.h"

namespace hg::garden::test {

inline std::uint32_t bits(float v) {
    std::uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
}

// Every voxel's value and active state over a box.
struct Snapshot {
    voxel::IndexBox box;
    std::vector<float> value;
    std::vector<char> on;

    std::size_t at(int i, int j, int k) const {
        return (static_cast<std::size_t>(k - box.lo[2]) * static_cast<std::size_t>(box.extent(1)) +
                static_cast<std::size_t>(j - box.lo[1])) * static_cast<std::size_t>(box.extent(0)) +
               static_cast<std::size_t>(i - box.lo[0]);
    }
};

inline voxel::IndexBox padded(const voxel::IndexBox& b, int by) {
    return voxel::IndexBox::fromCorners(b.lo[0] - by, b.lo[1] - by, b.lo[2] - by, b.hi[0] + by, b.hi[1] + by, b.hi[2] + by);
}

inline Snapshot snapshot(const voxel::Volume& v) {
    Snapshot s;
    s.box = padded(v.frame.indexBox, kBlendBlock);
    s.value.resize(s.box.volume());
    s.on.resize(s.box.volume());
    auto acc = voxel::vdb(v).getConstAccessor();
    for (int k = s.box.lo[2]; k <= s.box.hi[2]; ++k)
        for (int j = s.box.lo[1]; j <= s.box.hi[1]; ++j)
            for (int i = s.box.lo[0]; i <= s.box.hi[0]; ++i) {
                openvdb::Coord c(i, j, k);
                s.value[s.at(i, j, k)] = acc.getValue(c);
                s.on[s.at(i, j, k)] = acc.isValueOn(c);
            }
    return s;
}

// The number of voxels that differ (value bits or active state).
inline std::size_t differences(const Snapshot& a, const Snapshot& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.value.size(); ++i) n += bits(a.value[i]) != bits(b.value[i]) || a.on[i] != b.on[i];
    return n;
}

inline std::set<std::array<int, 3>> leafOrigins(const voxel::Volume& v) {
    std::set<std::array<int, 3>> out;
    for (auto it = voxel::vdb(v).tree().cbeginLeaf(); it; ++it)
        out.insert({it->origin().x(), it->origin().y(), it->origin().z()});
    return out;
}

// A pyramid kept up to date by changed boxes holds the values of one built
// from `scratch`, on every level above 0 over the frame's box.
inline void expectPyramidOf(const poly::LodPyramid& pyramid, const voxel::Volume& scratch, const voxel::IndexBox& b) {
    poly::LodPyramid fresh(scratch, 4);
    for (int level = 1; level < 4; ++level)
        for (int k = (b.lo[2] >> level) - 1; k <= (b.hi[2] >> level) + 1; ++k)
            for (int j = (b.lo[1] >> level) - 1; j <= (b.hi[1] >> level) + 1; ++j)
                for (int i = (b.lo[0] >> level) - 1; i <= (b.hi[0] >> level) + 1; ++i)
                    ASSERT_EQ(bits(pyramid.value(level, i, j, k)), bits(fresh.value(level, i, j, k)))
                        << "level " << level << " at " << i << " " << j << " " << k;
}

class MorphBlend : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        models = new ThreeModels;
        sources = new MorphSources(threeSources(*models, 40));
    }
    static void TearDownTestSuite() {
        delete sources;
        delete models;
    }
    static inline ThreeModels* models = nullptr;
    static inline MorphSources* sources = nullptr;

    const MorphWeights w1 = weightsFromBarycentric({0.6, 0.3, 0.1});
    const MorphWeights w2 = weightsFromBarycentric({0.1, 0.3, 0.6});
    const MorphWeights w3 = weightsFromBarycentric({0.2, 0.7, 0.1}, {1.0, 1.3, 0.8});
    const std::array<double, 3> viewer{1.5, 1.1, -1.0};  // model units, just outside a corner of the box
};

}  // namespace hg::garden::test
