// Volumes for the polygonizer tests: HyperFun text's default body at `res`
// voxels along its estimated model box, or a model in the cube [-1, 1]^3.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "tests/test_models.h"
#include "voxel/sampler.h"

namespace hg::poly::test {

inline voxel::Volume sampleProgram(const std::string& source, int res, std::vector<double> a = {}) {
    const frep::Model model = ::hg::test::modelFromSource(source, std::move(a));
    voxel::VolumeRequest req;
    req.resolution = res;
    voxel::VoxelizeResult v = voxel::voxelize(model, req);
    EXPECT_TRUE(v.volume) << v.error;
    return std::move(*v.volume);
}

// `model` at `res` voxels in the cube [-1, 1]^3.
inline voxel::Volume sampleInUnitCube(const frep::Model& model, int res) {
    voxel::VolumeRequest req;
    req.resolution = res;
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = -1;
        b.hi[a] = 1;
    }
    req.box = b;
    voxel::VoxelizeResult v = voxel::voxelize(model, req);
    EXPECT_TRUE(v.volume) << v.error;
    return std::move(*v.volume);
}

}  // namespace hg::poly::test
