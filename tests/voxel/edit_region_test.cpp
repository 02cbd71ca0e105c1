// Edit regions (voxel/edit_region.h): a box of a grid recomputed from a base
// grid through an edit tape (W the base value, x, y, z the voxel's model
// position), clamped to the band, active inside it. What it promises and
// what is tested here, on real grids from the sampler:
//  * every voxel is the tape at its float-rounded position and base value,
//    clamped, active exactly inside the band: checked against the batch
//    evaluator run on the whole tape voxel by voxel, for a short tape and
//    for one long enough to be specialized to each leaf (with and without
//    specialization);
//  * a box computed alone equals the same box of a whole-grid update, bit
//    for bit, and nothing outside the box changes; in place (target = base)
//    equals from a distinct base; one thread equals several;
//  * a tape of a model's own field times the normalization gives exactly
//    what resampling the model there stores (resampleRegion);
//  * the region is clipped to the frame: nothing is written outside it;
//  * domain errors of the tape are counted, the points stored outside;
//  * applyEditTapes (many regions, a tape each, on TBB) equals applying
//    them one at a time.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <optional>
#include <random>

#include "edit_tapes.h"
#include "frep/eval/eval_batch.h"
#include "frep/eval/tape_specializer.h"
#include "test_models.h"
#include "voxel/edit_region.h"
#include "voxel/sampler.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {
namespace {

using test::Ball;
using test::differingVoxels;
using test::grown;

frep::Box3 cube(double h) {
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = -h;
        b.hi[a] = h;
    }
    return b;
}

// A sphere of radius sqrt(a) in [-1, 1]^3 at 64 voxels.
Volume sphereGrid(double a = 0.5) {
    VolumeRequest req;
    req.resolution = 64;
    req.box = cube(1.0);
    VoxelizeResult r = voxelize(test::modelFromSource(test::kSphere, {a}), req);
    EXPECT_TRUE(r.volume) << r.error;
    return r.volume ? std::move(*r.volume) : Volume();
}

// About one unit per voxel at a ball's surface.
double ballScale(const Volume& v, double radius) { return 1.0 / (2.0 * radius * v.frame.voxelSize); }

// Bumps and dents on the sphere of radius 0.707, one reaching past the frame.
frep::Tape shortTape(const Volume& v) {
    return test::ballsTape({{{0.7, 0.0, 0.0}, 0.15, true},
                            {{0.0, 0.7, 0.1}, 0.2, false},
                            {{0.95, -0.2, 0.95}, 0.25, true}},
                           ballScale(v, 0.2));
}

// Sixteen balls about the surface, added and carved in turn: more than the
// 96 instructions from which edit_region.cpp specializes the tape per leaf.
frep::Tape longTape(const Volume& v) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-1.0, 1.0), r(0.05, 0.15);
    std::vector<Ball> balls;
    for (int i = 0; i < 16; ++i) {
        double p[3] = {u(rng), u(rng), u(rng)};
        const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / 0.7;
        balls.push_back({{p[0] / len, p[1] / len, p[2] / len}, r(rng), i % 2 == 0});
    }
    return test::ballsTape(balls, ballScale(v, 0.1));
}

// What applyEditTape must store over `clip`: the whole tape on the batch
// evaluator at each voxel's float position with the base value, clamped.
// Returns the voxels of `edited` that differ (value bits or active state).
std::size_t differingFromReference(const Volume& base, const Volume& edited, const IndexBox& clip,
                                   const frep::Tape& tape) {
    std::vector<float> x, y, z, w;
    for (int k = clip.lo[2]; k <= clip.hi[2]; ++k)
        for (int j = clip.lo[1]; j <= clip.hi[1]; ++j)
            for (int i = clip.lo[0]; i <= clip.hi[0]; ++i) {
                x.push_back(static_cast<float>(base.frame.coordinate(0, i)));
                y.push_back(static_cast<float>(base.frame.coordinate(1, j)));
                z.push_back(static_cast<float>(base.frame.coordinate(2, k)));
                w.push_back(base.value(i, j, k));
            }
    std::vector<float> out(x.size());
    frep::BatchEvaluator<float> eval(tape);
    frep::ErrorReport errors;
    eval.evaluate(x.data(), y.data(), z.data(), w.data(), out.data(), x.size(), errors);
    EXPECT_EQ(errors.count, 0u);
    const float band = base.frame.band;
    std::size_t n = 0, at = 0;
    for (int k = clip.lo[2]; k <= clip.hi[2]; ++k)
        for (int j = clip.lo[1]; j <= clip.hi[1]; ++j)
            for (int i = clip.lo[0]; i <= clip.hi[0]; ++i, ++at) {
                const float want = std::clamp(out[at], -band, band), got = edited.value(i, j, k);
                const bool wantOn = std::fabs(want) < band;
                if (std::memcmp(&want, &got, sizeof want) != 0 || edited.active(i, j, k) != wantOn) {
                    if (n++ < 3)
                        ADD_FAILURE() << "voxel (" << i << ", " << j << ", " << k << "): stored " << got << ", tape "
                                      << want;
                }
            }
    return n;
}

TEST(EditRegion, EachVoxelIsTheTapeAtItsPositionAndBaseValueClampedToTheBand) {
    const Volume base = sphereGrid();
    const IndexBox& all = base.frame.indexBox;
    const frep::Tape tapes[] = {shortTape(base), longTape(base)};
    ASSERT_GE(tapes[1].size(), 96u) << "the long tape should be specialized per leaf";
    for (const frep::Tape& tape : tapes) {
        for (bool specialize : {true, false}) {
            SCOPED_TRACE(::testing::Message() << tape.size() << " instructions, specialization " << specialize);
            frep::setSpecialization(specialize);
            Volume edited = base.clone();
            const EditRegionStats st = applyEditTape(base, edited, all, tape);
            frep::setSpecialization(true);
            EXPECT_EQ(st.voxels, all.volume());
            EXPECT_EQ(st.errors.count, 0u);
            EXPECT_EQ(differingFromReference(base, edited, all, tape), 0u);
            // The edits did something: values changed, voxels came into the
            // band and left it.
            std::size_t changed = 0, entered = 0, left = 0;
            for (int k = all.lo[2]; k <= all.hi[2]; ++k)
                for (int j = all.lo[1]; j <= all.hi[1]; ++j)
                    for (int i = all.lo[0]; i <= all.hi[0]; ++i) {
                        changed += edited.value(i, j, k) != base.value(i, j, k);
                        entered += edited.active(i, j, k) && !base.active(i, j, k);
                        left += !edited.active(i, j, k) && base.active(i, j, k);
                    }
            EXPECT_GT(changed, 2000u);
            EXPECT_GT(entered, 200u);
            EXPECT_GT(left, 10u);
            // Stored active exactly inside the band, as the sampler stores.
            for (auto it = vdb(edited).tree().cbeginValueOn(); it; ++it) ASSERT_LT(std::fabs(*it), base.frame.band);
        }
    }
}

TEST(EditRegion, ABoxAloneEqualsTheSameBoxOfAWholeGridUpdate) {
    const Volume base = sphereGrid();
    const frep::Tape tape = longTape(base);
    Volume full = base.clone();
    applyEditTape(base, full, full.frame.indexBox, tape);
    ASSERT_GT(differingVoxels(full, base, base.frame.indexBox), 1000u);
    const IndexBox regions[] = {IndexBox::fromCorners(13, 5, 20, 57, 40, 66),    // unaligned, inside
                                IndexBox::fromCorners(-9, 30, 30, 10, 33, 90),   // reaches past the frame
                                IndexBox::fromCorners(53, 31, 31, 53, 31, 31),   // one voxel
                                IndexBox::fromCorners(40, 24, 24, 63, 47, 47)};  // leaf-aligned
    const IndexBox around = grown(base.frame.indexBox, 3);
    for (const IndexBox& region : regions) {
        SCOPED_TRACE(::testing::Message() << "region " << region.lo[0] << "," << region.lo[1] << "," << region.lo[2]
                                          << " .. " << region.hi[0] << "," << region.hi[1] << "," << region.hi[2]);
        Volume part = base.clone();
        const EditRegionStats st = applyEditTape(base, part, region, tape);
        const IndexBox clip = intersect(region, base.frame.indexBox);
        EXPECT_EQ(st.voxels, clip.volume());
        EXPECT_EQ(differingVoxels(part, full, clip, "inside the box"), 0u);
        // Outside the box nothing changed, however the leaves were touched.
        std::size_t outside = 0;
        for (int k = around.lo[2]; k <= around.hi[2]; ++k)
            for (int j = around.lo[1]; j <= around.hi[1]; ++j)
                for (int i = around.lo[0]; i <= around.hi[0]; ++i)
                    if (!clip.contains(i, j, k))
                        outside += part.value(i, j, k) != base.value(i, j, k) || part.active(i, j, k) != base.active(i, j, k);
        EXPECT_EQ(outside, 0u);
    }
}

TEST(EditRegion, InPlaceAndOnAnyNumberOfThreadsGiveTheSameGrid) {
    const Volume base = sphereGrid();
    const frep::Tape tape = longTape(base);
    const IndexBox region = IndexBox::fromCorners(-2, 10, 3, 70, 50, 60);
    std::optional<Volume> one, many;
    tbb::task_arena(1).execute([&] {
        one = base.clone();
        applyEditTape(base, *one, region, tape);
    });
    tbb::task_arena(2).execute([&] {
        many = base.clone();
        applyEditTape(base, *many, region, tape);
    });
    const IndexBox around = grown(base.frame.indexBox, 2);
    EXPECT_EQ(differingVoxels(*one, *many, around, "1 vs 2 threads"), 0u);
    // In place: each voxel's base value is read before it is written.
    Volume inPlace = base.clone();
    applyEditTape(inPlace, inPlace, region, tape);
    EXPECT_EQ(differingVoxels(inPlace, *one, around, "in place"), 0u);
    EXPECT_GT(differingVoxels(inPlace, base, around), 500u);
}

TEST(EditRegion, AModelsFieldTimesTheNormalizationIsWhatResamplingStores) {
    // The sphere grows from radius sqrt(0.3) to sqrt(0.5): the tape ignores
    // W and computes the larger sphere's field with the small grid's
    // normalization, as resampleRegion does.
    const Volume small = sphereGrid(0.3);
    const frep::Model large = test::modelFromSource(test::kSphere, {0.5});
    ASSERT_TRUE(large.compiled());
    const frep::Tape tape = test::scaledTape(*large.tape(), small.normalization);
    const IndexBox around = grown(small.frame.indexBox, 2);
    for (const IndexBox& region : {small.frame.indexBox, IndexBox::fromCorners(5, -3, 17, 44, 37, 80)}) {
        Volume edited = small.clone(), resampled = small.clone();
        applyEditTape(small, edited, region, tape);
        resampleRegion(resampled, large, region);
        EXPECT_EQ(differingVoxels(edited, resampled, around, "edit tape vs resample"), 0u);
        EXPECT_GT(differingVoxels(edited, small, around), 1000u);
    }
    // Over the whole frame that is the larger sphere's own grid, had it been
    // sampled with the small one's normalization: its sign everywhere.
    Volume edited = small.clone();
    applyEditTape(small, edited, small.frame.indexBox, tape);
    const Volume big = sphereGrid(0.5);
    std::size_t signs = 0;
    const IndexBox& all = small.frame.indexBox;
    for (int k = all.lo[2]; k <= all.hi[2]; ++k)
        for (int j = all.lo[1]; j <= all.hi[1]; ++j)
            for (int i = all.lo[0]; i <= all.hi[0]; ++i)
                if (std::fabs(big.value(i, j, k)) > 0.5f) signs += (edited.value(i, j, k) > 0) != (big.value(i, j, k) > 0);
    EXPECT_EQ(signs, 0u);
}

TEST(EditRegion, NothingIsWrittenOutsideTheFrame) {
    const Volume base = sphereGrid();
    // A ball far larger than the frame: +band everywhere it is evaluated.
    const frep::Tape everything = test::ballsTape({{{0.0, 0.0, 0.0}, 10.0, true}}, 1.0);
    const IndexBox& frame = base.frame.indexBox;
    Volume v = base.clone();
    const EditRegionStats st = applyEditTape(base, v, grown(frame, 20), everything);
    EXPECT_EQ(st.voxels, frame.volume()) << "the region is clipped to the frame";
    const float band = base.frame.band;
    std::size_t inside = 0, outside = 0;
    const IndexBox shell = grown(frame, 9);
    for (int k = shell.lo[2]; k <= shell.hi[2]; ++k)
        for (int j = shell.lo[1]; j <= shell.hi[1]; ++j)
            for (int i = shell.lo[0]; i <= shell.hi[0]; ++i) {
                if (frame.contains(i, j, k)) inside += v.value(i, j, k) == band && !v.active(i, j, k);
                else outside += v.value(i, j, k) == -band && !v.active(i, j, k);
            }
    EXPECT_EQ(inside, frame.volume());
    EXPECT_EQ(outside, shell.volume() - frame.volume()) << "outside the frame: the background, untouched";

    // A region wholly outside the frame, and an empty one: nothing at all.
    const std::size_t leaves = base.leafCount(), active = base.activeVoxelCount();
    for (const IndexBox& region : {IndexBox::fromCorners(frame.hi[0] + 1, 0, 0, frame.hi[0] + 30, 20, 20),
                                   IndexBox::fromCorners(-40, -40, -40, frame.lo[0] - 1, 10, 10), IndexBox()}) {
        Volume w = base.clone();
        EXPECT_EQ(applyEditTape(base, w, region, everything).voxels, 0u);
        EXPECT_EQ(w.leafCount(), leaves);
        EXPECT_EQ(w.activeVoxelCount(), active);
        EXPECT_EQ(differingVoxels(w, base, grown(frame, 2), "outside region"), 0u);
    }
}

TEST(EditRegion, DomainErrorsAreCountedAndStoredOutside) {
    // sqrt(W): fails wherever the base is negative (outside the sphere).
    const Volume base = sphereGrid();
    frep::TapeBuilder b;
    const frep::Tape tape = b.finish(b.fallible(frep::Op::HfSqrt, b.w(), frep::kNoReg, frep::kNoReg, {7, 3}));
    const IndexBox region = IndexBox::fromCorners(0, 20, 20, 40, 40, 45);
    Volume v = base.clone();
    const EditRegionStats st = applyEditTape(base, v, region, tape);
    std::uint64_t negative = 0;
    for (int k = region.lo[2]; k <= region.hi[2]; ++k)
        for (int j = region.lo[1]; j <= region.hi[1]; ++j)
            for (int i = region.lo[0]; i <= region.hi[0]; ++i) {
                const float w = base.value(i, j, k);
                if (w < 0.0f) {
                    ++negative;
                    ASSERT_EQ(v.value(i, j, k), static_cast<float>(frep::kOutsideValue));
                } else {
                    ASSERT_EQ(v.value(i, j, k), std::min(std::sqrt(w), base.frame.band));
                }
            }
    ASSERT_GT(negative, 100u);
    EXPECT_EQ(st.errors.count, negative);
    EXPECT_EQ(st.errors.first, frep::DomainError::NegativeSqrt);
    EXPECT_EQ(st.errors.firstLoc.line, 7);
}

TEST(EditRegion, ManyRegionsWithATapeEachEqualApplyingThemOneAtATime) {
    const Volume base = sphereGrid();
    // Cells of 16^3 on the leaf grid (a bulk rebuild's cells share no leaf),
    // the last one past the frame; each gets a ball of its own.
    std::vector<IndexBox> regions;
    std::vector<frep::Tape> tapes;
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(-0.8, 0.8);
    for (int z = 0; z < 64; z += 16)
        for (int y = 0; y < 64; y += 32)
            for (int x = 8; x < 64; x += 24) {
                regions.push_back(IndexBox::fromCorners(x, y, z, x + 15, y + 15, z + 15));
                const std::array<double, 3> c{base.frame.coordinate(0, x + 8), base.frame.coordinate(1, y + 8),
                                              base.frame.coordinate(2, z + 8)};
                tapes.push_back(tapes.size() % 3 == 2 ? longTape(base)
                                                      : test::ballsTape({{c, 0.2, tapes.size() % 2 == 0}}, ballScale(base, 0.2)));
            }
    regions.push_back(IndexBox::fromCorners(64, 64, 64, 95, 95, 95));
    tapes.push_back(shortTape(base));

    Volume bulk = base.clone();
    std::atomic<std::size_t> calls{0};
    const EditRegionStats st = applyEditTapes(base, bulk, regions, [&](std::size_t i) {
        ++calls;
        return tapes.at(i);
    });
    EXPECT_GE(calls.load(), regions.size() - 1);
    EXPECT_EQ(st.errors.count, 0u);

    Volume serial = base.clone();
    std::uint64_t voxels = 0;
    for (std::size_t i = 0; i < regions.size(); ++i) voxels += applyEditTape(base, serial, regions[i], tapes[i]).voxels;
    EXPECT_EQ(st.voxels, voxels);
    const IndexBox around = grown(base.frame.indexBox, 2);
    EXPECT_EQ(differingVoxels(bulk, serial, around, "bulk vs one at a time"), 0u);
    EXPECT_GT(differingVoxels(bulk, base, around), 1000u);
}

}  // namespace
}  // namespace hg::voxel
