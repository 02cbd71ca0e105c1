// Sampling with tapes specialized to each box (voxel/box_walker.h,
// frep/eval/tape_specializer.h) stores the same grid, voxel for voxel and bit for
// bit, as sampling with the full tape: our content, the bounded files and a
// program of many bounded edits, whose leaves then run a far shorter tape.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <array>
#include <random>
#include <vector>

#include "frep/eval/tape_specializer.h"
#include "test_models.h"
#include "voxel/lattice_evaluation.h"
#include "voxel/sampler.h"

namespace hg::voxel {
namespace {

namespace fs = std::filesystem;

struct Sampled {
    Volume volume;
    SampleStats stats;
};

Sampled sample(const frep::Model& model, int resolution, bool specialize) {
    frep::setSpecialization(specialize);
    VolumeRequest req;
    req.resolution = resolution;
    VoxelizeResult r = voxelize(model, req);
    frep::setSpecialization(true);
    EXPECT_TRUE(r.volume) << r.error;
    return {r.volume ? std::move(*r.volume) : Volume(), r.stats};
}

std::size_t differing(const Volume& a, const Volume& b) {
    std::size_t n = 0;
    const IndexBox& box = a.frame.indexBox;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                const float va = a.value(i, j, k), vb = b.value(i, j, k);
                n += std::memcmp(&va, &vb, sizeof va) != 0 || a.active(i, j, k) != b.active(i, j, k);
            }
    return n;
}

// Bounded carves, adds and bumps on a ball, as an exported sculpture has them.
std::string editedBall(int edits) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> dir(-1.0, 1.0), r(0.04, 0.1);
    std::string body = "  f = max(min((0.6 - (x[1]^2 + x[2]^2 + x[3]^2)) * 30, 3), -3);\n";
    for (int i = 0; i < edits; ++i) {
        double p[3] = {dir(rng), dir(rng), dir(rng)};
        const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / 0.77;
        const double rad = r(rng);
        const std::string d = "((x[1] - " + std::to_string(p[0] / len) + ")^2 + (x[2] - " + std::to_string(p[1] / len) +
                              ")^2 + (x[3] - " + std::to_string(p[2] / len) + ")^2)";
        const std::string g = "max(min((" + std::to_string(rad * rad) + " - " + d + ") * 300, 3), -3)";
        body += i % 2 ? "  f = min(f, -" + g + ");\n" : "  f = max(f, " + g + ");\n";
    }
    return "edited(x[3], a[1]) {\n" + body + "  edited = f;\n}\n";
}

// Our content, the bounded files and a ball of 400 edits.
std::vector<std::pair<std::string, frep::Model>> models() {
    std::vector<std::pair<std::string, frep::Model>> out;
    for (const fs::path& dir : {fs::path(HG_SOURCE_DIR) / "content" / "hyperfun", fs::path(HG_TEST_DATA_DIR) / "bounded"})
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().extension() == ".hf") out.emplace_back(e.path().stem().string(), test::modelFromFile(e.path().string(), {0.4}));
    out.emplace_back("edited", test::modelFromSource(editedBall(400).c_str()));
    return out;
}

TEST(SpecializedSampling, GridsAreTheSameBitForBit) {
    for (const auto& [name, model] : models()) {
        SCOPED_TRACE(name);
        const Sampled full = sample(model, 72, false), fast = sample(model, 72, true);
        EXPECT_EQ(full.volume.normalization, fast.volume.normalization);
        EXPECT_EQ(full.stats.samples, fast.stats.samples);
        EXPECT_EQ(full.stats.boxesCulled, fast.stats.boxesCulled);
        EXPECT_EQ(differing(full.volume, fast.volume), 0u);
        EXPECT_LE(fast.stats.leafTapeMean, full.stats.leafTapeMean);
        if (name == "edited") {
            // 400 edits, each reaching a few leaves: the leaves run a few of them.
            EXPECT_LT(fast.stats.leafTapeMean, 0.1 * full.stats.leafTapeMean)
                << fast.stats.leafTapeMean << " of " << full.stats.leafTapeMean;
        }
    }
}

// The point-tape probe (HG_PROBE_POINT_TAPES=1, a measurement for
// bench_tools and voxelize --stats): single voxels' tapes are no longer
// than their leaves', shorter for many edits, and probing leaves the grid
// as it was.
TEST(SpecializedSampling, VoxelsOwnTapesAreTheFloorOfTheLeaves) {
    const frep::Model model = test::modelFromSource(editedBall(400).c_str());
    const Sampled plain = sample(model, 72, true);
    EXPECT_EQ(plain.stats.pointTapeMean, 0.0) << "probed only when asked";
    ::setenv("HG_PROBE_POINT_TAPES", "1", 1);
    const Sampled probed = sample(model, 72, true);
    ::unsetenv("HG_PROBE_POINT_TAPES");
    EXPECT_EQ(differing(plain.volume, probed.volume), 0u);
    EXPECT_GT(probed.stats.pointTapeMean, 0.0);
    EXPECT_LT(probed.stats.pointTapeMean, probed.stats.leafTapeMean);
}

// The lattice (the normalization's probe, the dense source cache) is
// evaluated in blocks, each with the tape specialized to its box: the same
// values, failures and error count as the full tape at every point, on a
// lattice whose sides are no multiple of the blocks and whose points are
// not evenly spaced.
TEST(SpecializedSampling, LatticesAreTheSameBitForBit) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> step(0.01f, 0.09f);
    std::array<std::vector<float>, 3> axes;
    const std::size_t counts[3] = {37, 29, 45};
    for (std::size_t a = 0; a < 3; ++a) {
        float v = -1.3f;
        for (std::size_t i = 0; i < counts[a]; ++i, v += step(rng)) axes[a].push_back(v);
    }
    const std::size_t n = counts[0] * counts[1] * counts[2];
    std::size_t specialized = 0;
    for (const auto& [name, model] : models()) {
        SCOPED_TRACE(name);
        std::vector<float> full(n), fast(n);
        std::vector<std::uint8_t> fullFailed(n), fastFailed(n);
        frep::setSpecialization(false);
        const frep::ErrorReport fullErrors = evaluateLattice(model, axes, full.data(), fullFailed.data(), 3.5f);
        frep::setSpecialization(true);
        const frep::ErrorReport fastErrors = evaluateLattice(model, axes, fast.data(), fastFailed.data(), 3.5f);
        EXPECT_EQ(std::memcmp(full.data(), fast.data(), n * sizeof(float)), 0);
        EXPECT_EQ(fullFailed, fastFailed);
        EXPECT_EQ(fullErrors.count, fastErrors.count);
        specialized += model.tape() != nullptr;
    }
    EXPECT_GT(specialized, 10u);
}

}  // namespace
}  // namespace hg::voxel
