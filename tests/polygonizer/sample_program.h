// A volume from HyperFun text, for the polygonizer tests: the program's
// default body at `res` voxels along its estimated model box.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "frep/parser.h"
#include "voxel/sampler.h"

namespace hg::poly::test {

inline voxel::Volume sampleProgram(const std::string& source, int res, std::vector<double> a = {}) {
    frep::ParseResult r = frep::parseProgram(source, "test.hf");
    EXPECT_TRUE(r.ok());
    auto program = std::make_shared<const frep::Program>(std::move(*r.program));
    frep::Model model(program, program->defaultBody(), std::move(a));
    voxel::VolumeRequest req;
    req.resolution = res;
    voxel::VoxelizeResult v = voxel::voxelize(model, req);
    EXPECT_TRUE(v.volume) << v.error;
    return std::move(*v.volume);
}

}  // namespace hg::poly::test
