// The memory guard (voxel/memory_guard.h): estimates are checked against a
// limit before anything is allocated, and a request that would not fit is
// refused with a message naming it, the sizes, and the largest resolution
// that would fit given how memory grows with resolution. What is tested:
//  * formatBytes picks the unit and prints what the bytes are, to a tenth
//    of that unit;
//  * availableMemoryBytes is /proc/meminfo's MemAvailable, memoryLimit 80%
//    of it unless a limit is asked for;
//  * refuseIfTooBig: nothing when the need fits (equal included); otherwise
//    the message, and its suggested resolution does fit by the growth law,
//    within 10% of the largest that does; no suggestion below 4;
//  * end to end on the sampler and the dense cache: the refusal carries
//    the estimate and the limit, the suggested resolution then passes the
//    same guard, and the narrow-band estimate bounds the grid's memory.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <regex>
#include <string>

#include "test_models.h"
#include "voxel/dense_field.h"
#include "voxel/memory_guard.h"
#include "voxel/sampler.h"

namespace hg::voxel {
namespace {

constexpr std::uint64_t KiB = 1024, MiB = KiB * 1024, GiB = MiB * 1024, TiB = GiB * 1024;

frep::Box3 cube(double h) {
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = -h;
        b.hi[a] = h;
    }
    return b;
}

// The resolution a refusal suggests, or -1 when it suggests none.
int suggested(const std::string& message) {
    std::smatch m;
    if (!std::regex_search(message, m, std::regex("; resolution ([0-9]+) or less would fit$"))) return -1;
    return std::stoi(m[1]);
}

// MemAvailable read here, in bytes (0 when absent).
std::uint64_t memAvailable() {
    std::ifstream in("/proc/meminfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("MemAvailable:", 0) == 0) return std::stoull(line.substr(13)) * 1024;
    return 0;
}

TEST(MemoryGuard, FormatBytesPicksTheUnitAndOneDecimal) {
    EXPECT_EQ(formatBytes(0), "0 B");
    EXPECT_EQ(formatBytes(1), "1 B");
    EXPECT_EQ(formatBytes(1023), "1023 B");
    EXPECT_EQ(formatBytes(1024), "1.0 KiB");
    EXPECT_EQ(formatBytes(1536), "1.5 KiB");
    EXPECT_EQ(formatBytes(320 * MiB), "320.0 MiB");
    EXPECT_EQ(formatBytes(3 * GiB / 2), "1.5 GiB");
    EXPECT_EQ(formatBytes(32 * GiB + 400 * MiB), "32.4 GiB");
    EXPECT_EQ(formatBytes(TiB), "1.0 TiB");
    EXPECT_EQ(formatBytes(5000 * TiB), "5000.0 TiB") << "no unit above TiB";
    // Any size: the number in its unit is the bytes, to half a tenth.
    std::mt19937_64 rng(3);
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
    for (int n = 0; n < 2000; ++n) {
        const std::uint64_t bytes = rng() >> (rng() % 64);
        const std::string text = formatBytes(bytes);
        const std::size_t space = text.find(' ');
        ASSERT_NE(space, std::string::npos) << text;
        const double number = std::stod(text.substr(0, space));
        const std::string unit = text.substr(space + 1);
        int u = 0;
        while (u < 5 && unit != units[u]) ++u;
        ASSERT_LT(u, 5) << text;
        const double scale = std::pow(1024.0, u);
        EXPECT_NEAR(number * scale, static_cast<double>(bytes), 0.05 * scale + 0.5) << text;
        EXPECT_TRUE(number >= 1.0 || bytes == 0) << text << ": a smaller unit";
        EXPECT_TRUE(number <= 1024.0 || u == 4) << text << ": a larger unit";
    }
}

TEST(MemoryGuard, TheLimitIsWhatWasAskedForOrMostOfTheAvailableMemory) {
    EXPECT_EQ(memoryLimit(1), 1u);
    EXPECT_EQ(memoryLimit(123 * MiB), 123 * MiB);
    EXPECT_EQ(memoryLimit(~std::uint64_t{0}), ~std::uint64_t{0});
    const std::uint64_t before = memAvailable();
    const std::uint64_t available = availableMemoryBytes(), limit = memoryLimit(0);
    const std::uint64_t after = memAvailable();
    ASSERT_GT(before, 0u) << "this machine has /proc/meminfo";
    // MemAvailable moves while other processes run: within 5% of it.
    const double here = 0.5 * static_cast<double>(before + after), slack = 0.05 * here + 64.0 * MiB;
    EXPECT_NEAR(static_cast<double>(available), here, slack);
    EXPECT_NEAR(static_cast<double>(limit), 0.8 * here, slack);
    EXPECT_LT(limit, available + 64 * MiB);
}

TEST(MemoryGuard, WhatFitsIsNotRefused) {
    EXPECT_EQ(refuseIfTooBig("the grid", 512, 100 * MiB, 100 * MiB, 2.0), "");
    EXPECT_EQ(refuseIfTooBig("the grid", 512, 0, 0, 2.0), "");
    EXPECT_EQ(refuseIfTooBig("the grid", 512, 99, 100, 3.0), "");
    EXPECT_NE(refuseIfTooBig("the grid", 512, 101, 100, 3.0), "");
}

TEST(MemoryGuard, ARefusalSaysWhatWouldFit) {
    // Eight times too much for a dense box: half the resolution, less 5%.
    EXPECT_EQ(refuseIfTooBig("a dense box", 512, 8 * GiB, GiB, 3.0),
              "a dense box at resolution 512 needs about 8.0 GiB but only 1.0 GiB may be used; "
              "resolution 243 or less would fit");
    // Four times too much for a narrow band: half the resolution, less 5%.
    EXPECT_EQ(suggested(refuseIfTooBig("a band", 1000, 400 * MiB, 100 * MiB, 2.0)), 475);
    // Far too much: no resolution of at least 4 would fit.
    const std::string none = refuseIfTooBig("the mesh", 16, 5 * GiB, 1 * MiB, 3.0);
    EXPECT_EQ(none, "the mesh at resolution 16 needs about 5.0 GiB but only 1.0 MiB may be used");
    EXPECT_EQ(suggested(none), -1);
    // Any request: the suggestion fits by the growth law, and no resolution
    // more than about 5% above it would.
    std::mt19937_64 rng(8);
    for (int n = 0; n < 2000; ++n) {
        const int res = 8 + static_cast<int>(rng() % 8000);
        const std::uint64_t limit = 1 + rng() % (64 * GiB);
        const std::uint64_t needed = limit + 1 + rng() % (limit * 50);
        const double growth = n % 2 ? 2.0 : 3.0;
        const std::string m = refuseIfTooBig("x", res, needed, limit, growth);
        ASSERT_EQ(m.rfind("x at resolution " + std::to_string(res) + " needs about " + formatBytes(needed) +
                              " but only " + formatBytes(limit) + " may be used",
                          0),
                  0u)
            << m;
        const int fits = suggested(m);
        const double largest = res * std::pow(static_cast<double>(limit) / static_cast<double>(needed), 1.0 / growth);
        if (largest < 4.0) {
            EXPECT_EQ(fits, -1) << m;
            continue;
        }
        if (fits < 0) {
            EXPECT_LT(0.95 * largest, 4.0) << m;
            continue;
        }
        EXPECT_LT(fits, res) << m;
        EXPECT_LE(static_cast<double>(needed) * std::pow(static_cast<double>(fits) / res, growth), static_cast<double>(limit))
            << m;
        EXPECT_GE(fits, 0.9 * largest - 1.0) << m;
    }
}

TEST(MemoryGuard, TheSamplerRefusesWithItsEstimateAndTheSuggestionFits) {
    const frep::Model sphere = test::modelFromSource(test::kSphere, {0.5});
    VolumeRequest req;
    req.resolution = 512;
    req.box = cube(1.0);
    SampleOptions opts;
    opts.memoryLimit = 2 * MiB;
    const VoxelizeResult refused = voxelize(sphere, req, opts);
    ASSERT_FALSE(refused.volume);
    EXPECT_GT(refused.stats.estimatedBytes, opts.memoryLimit);
    EXPECT_EQ(refused.error, refuseIfTooBig("the narrow-band grid", 512, refused.stats.estimatedBytes, opts.memoryLimit, 2.0));
    const int fits = suggested(refused.error);
    ASSERT_GT(fits, 4) << refused.error;
    // At the suggested resolution the same guard lets it through, and the
    // estimate bounds what the grid takes.
    req.resolution = fits;
    const VoxelizeResult ok = voxelize(sphere, req, opts);
    ASSERT_TRUE(ok.volume) << ok.error;
    EXPECT_LE(ok.stats.estimatedBytes, opts.memoryLimit);
    EXPECT_GT(ok.stats.estimatedBytes, 0u);
    EXPECT_LE(ok.volume->memoryBytes(), ok.stats.estimatedBytes);
}

TEST(MemoryGuard, TheDenseCacheRefusesWithItsSizeAndTheSuggestionFits) {
    const frep::Model sphere = test::modelFromSource(test::kSphere, {0.5});
    VolumeFrame frame;
    ASSERT_EQ(makeFrame(cube(1.0), 128, 3.0f, frame), "");
    const std::uint64_t limit = 1 * MiB;
    const DenseResult refused = sampleDense(sphere, frame, 1.0, IndexBox::fromCorners(0, 0, 0, 127, 127, 99), limit);
    EXPECT_TRUE(refused.field.values.empty());
    EXPECT_EQ(refused.bytes, 128u * 128u * 100u * sizeof(float));
    EXPECT_EQ(refused.error, "a dense cache of 128x128x100 voxels at resolution 128 needs about 6.2 MiB but only "
                             "1.0 MiB may be used; resolution 66 or less would fit");
    const int fits = suggested(refused.error);
    ASSERT_GT(fits, 4);
    // The resolution is the box's longest side: the box scaled to it fits.
    const int depth = fits * 100 / 128;
    const DenseResult ok = sampleDense(sphere, frame, 1.0, IndexBox::fromCorners(0, 0, 0, fits - 1, fits - 1, depth - 1), limit);
    EXPECT_EQ(ok.error, "");
    EXPECT_EQ(ok.field.values.size(), static_cast<std::size_t>(fits) * fits * depth);
}

}  // namespace
}  // namespace hg::voxel
