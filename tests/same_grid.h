// Two volumes' grids compared bit for bit: the same topology, background,
// and every value (tiles and voxels, active or not) and active state. For
// the tests of what must give back exactly the grid it took (paging a grid
// to disk and back).
#pragma once

#include <gtest/gtest.h>

#include <cstring>

#include "voxel/volume_vdb.h"

namespace hg::test {

inline bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline void expectSameGrid(const voxel::Volume& a, const voxel::Volume& b) {
    const openvdb::FloatTree& ta = voxel::vdb(a).tree();
    const openvdb::FloatTree& tb = voxel::vdb(b).tree();
    ASSERT_TRUE(ta.hasSameTopology(tb));
    EXPECT_TRUE(sameBits(ta.background(), tb.background()));
    EXPECT_EQ(ta.leafCount(), tb.leafCount());
    EXPECT_EQ(ta.activeVoxelCount(), tb.activeVoxelCount());
    std::size_t differ = 0, seen = 0;
    for (auto it = ta.cbeginValueAll(); it; ++it) {
        ++seen;
        const openvdb::Coord c = it.getCoord();
        if (!sameBits(*it, tb.getValue(c)) || it.isValueOn() != tb.isValueOn(c)) ++differ;
    }
    EXPECT_GT(seen, 0u);
    EXPECT_EQ(differ, 0u) << "values or active states that differ";
}

}  // namespace hg::test
