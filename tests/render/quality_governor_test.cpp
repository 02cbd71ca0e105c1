// --quality auto's governor: it steps down when the GPU's time passes the
// budget, all the way to low if need be and never past it, climbs back only
// after a long quiet stretch, ignores frames without a measurement, does
// not flicker at the threshold, and judges a slow renderer in a second of
// its frames rather than in a fixed count of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "garden/render/quality_governor.h"

namespace hg::garden::test {
namespace {

// Frames of `gpuMs` until the quality changes (or `limit` frames pass).
std::size_t framesUntilChange(QualityGovernor& g, double gpuMs, std::size_t limit = 10000) {
    for (std::size_t f = 1; f <= limit; ++f)
        if (g.observe(gpuMs)) return f;
    return 0;
}

// The frames a change waits for at `gpuMs` a frame: kSettle, or fewer that
// add up to kJudgeMs, never under kMinFrames.
std::size_t settleFrames(double gpuMs) {
    const auto forTime = static_cast<std::size_t>(std::ceil(QualityGovernor::kJudgeMs / gpuMs));
    return std::min(QualityGovernor::kSettle, std::max(QualityGovernor::kMinFrames, forTime));
}

TEST(QualityGovernor, StepsDownToLowUnderLoadAndNoFurther) {
    QualityGovernor g(QualityPreset::High, 11.1);
    EXPECT_EQ(g.step(), 0u);
    EXPECT_GT(g.steps(), 4u);
    EXPECT_EQ(g.quality().aoSamples, qualityOf(QualityPreset::High).aoSamples);
    int cost = 0;  // each step must give something up
    while (g.step() + 1 < g.steps()) {
        const RenderQuality before = g.quality();
        const std::size_t frames = framesUntilChange(g, 20.0);
        ASSERT_GT(frames, 0u) << "a frame over budget steps down, at step " << g.step();
        EXPECT_EQ(frames, settleFrames(20.0)) << "not before the last change has settled";
        const RenderQuality& after = g.quality();
        cost += (after.msaaSamples < before.msaaSamples) + (after.shadowMapSize < before.shadowMapSize) +
                (!after.shadows && before.shadows) + (!after.ambientOcclusion && before.ambientOcclusion) +
                (after.aoSamples < before.aoSamples) + (after.aoHalfResolution && !before.aoHalfResolution) +
                (after.renderScale < before.renderScale) + (after.detailScale < before.detailScale);
    }
    EXPECT_GE(cost, static_cast<int>(g.steps()) - 1);
    const RenderQuality low = qualityOf(QualityPreset::Low);
    EXPECT_EQ(g.quality().msaaSamples, low.msaaSamples);
    EXPECT_FALSE(g.quality().shadows);
    EXPECT_FALSE(g.quality().ambientOcclusion);
    EXPECT_FLOAT_EQ(g.quality().renderScale, 0.5f) << "then fewer pixels";
    EXPECT_FLOAT_EQ(g.quality().detailScale, 0.5f) << "then coarser meshes for them";
    EXPECT_EQ(framesUntilChange(g, 50.0, 1000), 0u) << "low at half size with coarser meshes is the floor";
}

TEST(QualityGovernor, ClimbsBackOnlyAfterALongQuietStretch) {
    QualityGovernor g(QualityPreset::High, 11.1);
    ASSERT_GT(framesUntilChange(g, 20.0), 0u);
    ASSERT_GT(framesUntilChange(g, 20.0), 0u);
    ASSERT_EQ(g.step(), 2u);
    // Inside the budget but over half of it: stays where it is.
    EXPECT_EQ(framesUntilChange(g, 7.0, 2000), 0u);
    // Well under: back up, one step per quiet stretch.
    const std::size_t frames = framesUntilChange(g, 2.0);
    EXPECT_GE(frames, QualityGovernor::kUpWindow);
    EXPECT_EQ(g.step(), 1u);
    ASSERT_GT(framesUntilChange(g, 2.0), 0u);
    EXPECT_EQ(g.step(), 0u);
    EXPECT_EQ(framesUntilChange(g, 1.0, 2000), 0u) << "the ceiling is the top";
}

TEST(QualityGovernor, AFastRendererJustOverBudgetWaitsTheFullSettleCount) {
    // 12 ms frames against 11.1: 60 of them are 720 ms, under kJudgeMs, so
    // the frame count decides, as it did before time was counted.
    QualityGovernor g(QualityPreset::High, 11.1);
    EXPECT_EQ(framesUntilChange(g, 12.0), QualityGovernor::kSettle);
    EXPECT_EQ(g.step(), 1u);
    // Slow frames after a change still wait kMinFrames: the timer queries
    // report a few frames late.
    EXPECT_EQ(framesUntilChange(g, 5000.0), QualityGovernor::kMinFrames);
    EXPECT_EQ(g.changes(), 2u);
}

TEST(QualityGovernor, UnmeasuredFramesChangeNothingAndTheThresholdDoesNotFlicker) {
    QualityGovernor g(QualityPreset::High, 10.0);
    for (int f = 0; f < 1000; ++f) EXPECT_FALSE(g.observe(-1.0));
    EXPECT_EQ(g.step(), 0u);
    // Alternating just over and just under the step-down line: the mean
    // sits under it, so nothing changes.
    int changes = 0;
    for (int f = 0; f < 3000; ++f) changes += g.observe(f % 2 ? 8.9 : 7.9) ? 1 : 0;
    EXPECT_EQ(changes, 0);
}

TEST(QualityGovernor, ASoftwareRendererStartsLowAndDrawsFewerPixelsWhenSlow) {
    QualityGovernor g(QualityPreset::Low, 16.7);
    EXPECT_EQ(g.steps(), 4u);
    EXPECT_FLOAT_EQ(g.quality().renderScale, 1.0f);
    // 400 ms frames: judged after kMinFrames of them (2.4 s), not after
    // kSettle (24 s at two and a half frames a second).
    EXPECT_EQ(framesUntilChange(g, 400.0), QualityGovernor::kMinFrames);
    EXPECT_FLOAT_EQ(g.quality().renderScale, 0.75f);
    EXPECT_EQ(framesUntilChange(g, 150.0), settleFrames(150.0));
    EXPECT_EQ(settleFrames(150.0), 7u) << "a second of 150 ms frames";
    EXPECT_FLOAT_EQ(g.quality().renderScale, 0.5f);
    EXPECT_FLOAT_EQ(g.quality().detailScale, 1.0f) << "the meshes still for every scene pixel";
    EXPECT_FALSE(g.quality().shadows);
    EXPECT_EQ(framesUntilChange(g, 150.0), settleFrames(150.0));
    EXPECT_FLOAT_EQ(g.quality().renderScale, 0.5f);
    EXPECT_FLOAT_EQ(g.quality().detailScale, 0.5f) << "last, coarser meshes";
    EXPECT_EQ(framesUntilChange(g, 400.0, 500), 0u);
    ASSERT_GT(framesUntilChange(g, 1.0), 0u);
    EXPECT_FLOAT_EQ(g.quality().detailScale, 1.0f);
    ASSERT_GT(framesUntilChange(g, 1.0), 0u);
    EXPECT_FLOAT_EQ(g.quality().renderScale, 0.75f);
}

// The scene's pixels at a render scale, as the renderer draws them and the
// level of detail is chosen for them.
TEST(RenderQuality, TheSceneHasTheRenderScalesShareOfThePixels) {
    RenderQuality q;
    EXPECT_EQ(scenePixels(720, q), 720);
    q.renderScale = 0.5f;
    EXPECT_EQ(scenePixels(720, q), 360);
    q.renderScale = 0.75f;
    EXPECT_EQ(scenePixels(1081, q), 811) << "rounded";
    q.renderScale = 0.1f;
    EXPECT_EQ(scenePixels(720, q), 180) << "never under a quarter";
    q.renderScale = 3.0f;
    EXPECT_EQ(scenePixels(720, q), 720) << "never over the output";
    EXPECT_EQ(scenePixels(1, q), 1);
}

// The level of detail's pixels: the scene's at the detail scale.
TEST(RenderQuality, TheLevelOfDetailCountsTheDetailScalesShareOfTheScenesPixels) {
    RenderQuality q;
    EXPECT_EQ(detailPixels(720, q), 720);
    q.renderScale = 0.5f;
    EXPECT_EQ(detailPixels(720, q), 360) << "the scene's pixels";
    q.detailScale = 0.5f;
    EXPECT_EQ(detailPixels(720, q), 180);
    EXPECT_EQ(detailPixels(721, q), 181) << "rounded";
    q.detailScale = 0.01f;
    EXPECT_EQ(detailPixels(720, q), 90) << "never under a quarter of the scene's";
    q.detailScale = 2.0f;
    EXPECT_EQ(detailPixels(720, q), 360) << "never over the scene's";
    EXPECT_EQ(detailPixels(1, q), 1);
}

// What a still view sharpens to: the ceiling at the window's full size,
// then the high preset there (below a high ceiling), each with the level of
// detail of the rung in use (the same pixels for the meshes, so stopping
// does not remesh the garden) and its sky map.
TEST(QualityGovernor, AStillViewSharpensToTheCeilingAndHighAtFullSizeWithTheMeshesInUse) {
    for (const QualityPreset ceiling : {QualityPreset::Low, QualityPreset::High}) {
        QualityGovernor g(ceiling, 11.1);
        const RenderQuality top = qualityOf(ceiling), high = qualityOf(QualityPreset::High);
        while (true) {
            const std::vector<RenderQuality> stills = g.stillQualities();
            ASSERT_EQ(stills.size(), ceiling == QualityPreset::High ? 1u : 2u) << "step " << g.step();
            EXPECT_EQ(stills.front().msaaSamples, top.msaaSamples);
            EXPECT_EQ(stills.front().shadows, top.shadows);
            EXPECT_EQ(stills.front().ambientOcclusion, top.ambientOcclusion);
            EXPECT_EQ(stills.back().msaaSamples, high.msaaSamples);
            EXPECT_EQ(stills.back().shadows, high.shadows);
            EXPECT_EQ(stills.back().ambientOcclusion, high.ambientOcclusion);
            for (const RenderQuality& still : stills) {
                EXPECT_FLOAT_EQ(still.renderScale, 1.0f);
                EXPECT_EQ(still.skyMapSize, g.quality().skyMapSize) << "no sky baked again";
                for (const int pixels : {720, 1080, 2208})
                    EXPECT_EQ(detailPixels(pixels, still), detailPixels(pixels, g.quality()))
                        << "step " << g.step() << ", " << pixels << " pixels";
            }
            if (g.step() + 1 == g.steps()) break;
            ASSERT_GT(framesUntilChange(g, 50.0), 0u);
        }
        EXPECT_FLOAT_EQ(g.stillQualities().front().detailScale, 0.25f)
            << "the last rung: half the pixels, meshes for half of them";
    }
}

}  // namespace
}  // namespace hg::garden::test
