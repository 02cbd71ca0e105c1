// Scratch folders, small HyperFun models and morph sources for the garden
// tests. Models are tiny programs in HyperFun text, sampled at 32^3..48^3.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "frep/eval/model.h"
#include "frep/language/parser.h"
#include "tests/test_models.h"
#include "voxel/sampler.h"
#include "voxel/volume.h"
#include "garden/morph/morph_sources.h"

namespace hg::garden::test {

using ::hg::test::modelFromSource;


// A sphere of radius sqrt(a[1]) at (a[2], a[3], a[4]); f is not a distance.
constexpr const char* kSphere =
    "sphere(x[3], a[4]) { sphere = a[1] - ((x[1]-a[2])^2 + (x[2]-a[3])^2 + (x[3]-a[4])^2); }";
using ::hg::test::kTorusBlock;
// A rounded bar along x (superellipsoid), f of a very different scale.
constexpr const char* kBar =
    "bar(x[3], a[1]) { bar = 40 * (1 - (x[1]/1.0)^4 - (x[2]/0.3)^4 - (x[3]/0.35)^4); }";

// `source` (with `a`) sampled over the cube [-half, half]^3.
inline voxel::Volume sampledCube(const std::string& source, std::vector<double> a, double half, int resolution) {
    voxel::VolumeRequest req;
    frep::Box3 box;
    for (int i = 0; i < 3; ++i) {
        box.lo[i] = -half;
        box.hi[i] = half;
    }
    req.box = box;
    req.resolution = resolution;
    voxel::VoxelizeResult r = voxel::voxelize(modelFromSource(source, std::move(a)), req);
    EXPECT_TRUE(r.volume) << r.error;
    return r.volume ? std::move(*r.volume) : voxel::Volume();
}

// A ball of radius 0.5 in a box of 1.4 a side, sampled at 64^3: a grid to edit.
inline voxel::Volume ballVolume() {
    return sampledCube("ball(x[3], a[1]) { ball = 0.25 - x[1]^2 - x[2]^2 - x[3]^2; }", {}, 0.7, 64);
}

// Voxels of a's frame whose stored values differ in b.
inline int differingVoxels(const voxel::Volume& a, const voxel::Volume& b) {
    int n = 0;
    const voxel::IndexBox& box = a.frame.indexBox;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) n += a.value(i, j, k) != b.value(i, j, k);
    return n;
}

class ScratchDir : public ::testing::Test {
protected:
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              ("hg_garden_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { if (!std::getenv("HG_KEEP_SCRATCH")) std::filesystem::remove_all(dir); }
    std::string write(const std::string& name, const std::string& text) const {
        std::filesystem::path p = dir / name;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    std::filesystem::path dir;
};

// Three different small shapes in the box [-1.2, 1.2]^3 at `resolution`:
// a sphere off centre, the torus block, the bar.
struct ThreeModels {
    frep::Model sphere = modelFromSource(kSphere, {0.64, 0.15, 0.1, 0.0});
    frep::Model torus = modelFromSource(kTorusBlock);
    frep::Model bar = modelFromSource(kBar);
};

inline MorphSources threeSources(const ThreeModels& m, int resolution) {
    frep::Box3 box;
    for (int a = 0; a < 3; ++a) { box.lo[a] = -1.2; box.hi[a] = 1.2; }
    MorphSourcesResult r = buildMorphSources({&m.sphere, &m.torus, &m.bar}, box, resolution);
    EXPECT_TRUE(r.sources.has_value()) << r.error;
    return std::move(*r.sources);
}

#ifdef HG_HYPERGARDEN_EXE
struct ShellRun {
    int status = -1;
    std::string output;  // stdout and stderr together
};

// A shell command line (the hypergarden executable as $HG), its status and output.
inline ShellRun shell(const std::string& command) {
    ShellRun r;
    const std::string cmd = "HG='" + std::string(HG_HYPERGARDEN_EXE) + "'; " + command + " 2>&1";
    FILE* pipe = ::popen(cmd.c_str(), "r");
    if (!pipe) return r;
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) r.output.append(buf, n);
    const int st = ::pclose(pipe);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return r;
}
#endif

}  // namespace hg::garden::test
