// The garden's ground and air (docs/rendering.md, "The ground and the
// haze"), read back as pixels: the survey grid near the eye only, mown
// stripes that swap with the view, a meadow beyond the garden, blades
// close by, haze that takes what is far to the horizon's colour, and
// clouds in part of the sky, baked into a cube map that shows what each
// pixel would.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "garden/render/shapes.h"
#include "gl_fixture.h"

namespace hg::garden::test {
namespace {

class GroundTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        if (!renderer_) return;
        renderer_->setQuality(plainQuality());
    }
    void drawGround(const View& view, const GroundStyle& ground) {
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawGround(ground);
        renderer_->endFrame();
        read();
    }
    // Where the ray through pixel (x, y) meets the ground (y = 0); false
    // above the horizon.
    bool groundHit(const View& v, int x, int y, glm::vec3& hit) const {
        const glm::vec3 d = rayDirection(v, x, y);
        if (d.y >= -1e-4f) return false;
        hit = v.eye + (-v.eye.y / d.y) * d;
        return true;
    }
};

// Mean brightness of pixels on a grid line of constant x and of pixels in
// the middle of cells, among ground pixels between lo and hi metres away.
struct LineContrast {
    double line = 0, cell = 0;
    int lines = 0, cells = 0;
};

TEST_F(GroundTest, TheGridShowsNearTheEyeAndNotBeyondItsReach) {
    const View view = makeView({0.37f, 1.6f, 0.0f}, {0.37f, 0.0f, -7.0f});
    GroundStyle ground;
    ground.color = {0.7f, 0.7f, 0.7f};
    ground.lineColor = {0.1f, 0.1f, 0.1f};
    ground.majorEvery = 0;
    auto contrast = [&](float lo, float hi) {
        LineContrast c;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth - 1; ++x) {
                glm::vec3 hit, next;
                if (!groundHit(view, x, y, hit) || !groundHit(view, x + 1, y, next)) continue;
                const float distance = glm::distance(hit, view.eye);
                if (distance < lo || distance > hi) continue;
                const float footprint = std::fabs(next.x - hit.x);
                const float dx = std::fabs(hit.x - std::round(hit.x));
                const float dz = std::fabs(hit.z - std::round(hit.z));
                if (dx < 0.2f * footprint && dz > 0.2f) {
                    c.line += pixel(x, y).sum();
                    ++c.lines;
                } else if (dx > 0.3f && dz > 0.3f) {
                    c.cell += pixel(x, y).sum();
                    ++c.cells;
                }
            }
        return c;
    };

    drawGround(view, ground);  // no reach: lines everywhere
    const LineContrast nearAll = contrast(1.6f, 3.0f), farAll = contrast(9.0f, 14.0f);
    ground.gridReach = 4.0f;
    drawGround(view, ground);
    const LineContrast nearReach = contrast(1.6f, 3.0f), farReach = contrast(9.0f, 14.0f);

    for (const LineContrast* c : {&nearAll, &farAll, &nearReach, &farReach}) {
        ASSERT_GT(c->lines, 10);
        ASSERT_GT(c->cells, 200);
    }
    auto ratio = [](const LineContrast& c) { return (c.line / c.lines) / (c.cell / c.cells); };
    EXPECT_LT(ratio(farAll), 0.8) << "without a reach the far lines show";
    EXPECT_LT(ratio(nearReach), 0.6) << "within reach the lines show";
    EXPECT_NEAR(ratio(farReach), 1.0, 0.03) << "beyond twice the reach the lawn has no lines";
    EXPECT_NEAR(ratio(nearReach), ratio(nearAll), 0.02) << "the reach leaves near lines as they were";
}

TEST_F(GroundTest, MownStripesSwapWithTheViewAndTheMeadowBeyondIsUnmown) {
    GroundStyle ground;
    ground.lineWidth = 0.0f;
    ground.stripeWidth = 1.0f;
    ground.gardenHalfExtent = {3.0f, 3.0f};
    // Per side of the lawn: the brightness of even bands (round(x) even)
    // less that of odd bands, and the mean brightness.
    struct Bands {
        double even = 0, odd = 0, all = 0;
        int evens = 0, odds = 0, count = 0;
        double difference() const { return even / evens - odd / odds; }
        double mean() const { return all / count; }
    };
    auto look = [&](const glm::vec3& eye, Bands& garden, Bands& meadow) {
        const View view = makeView(eye, {0.0f, 0.0f, 0.0f});
        drawGround(view, ground);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                glm::vec3 hit;
                if (!groundHit(view, x, y, hit)) continue;
                const float edge = std::max(std::fabs(hit.x), std::fabs(hit.z));
                if (edge > 2.8f && edge < 3.2f) continue;  // the garden's edge
                // Bands are centred on whole metres of x; their edges left out.
                if (std::fabs(hit.x - std::round(hit.x)) > 0.3f) continue;
                Bands& b = edge < 3.0f ? garden : meadow;
                const bool even = (static_cast<long>(std::lround(hit.x)) % 2 + 2) % 2 == 0;
                (even ? b.even : b.odd) += pixel(x, y).sum();
                ++(even ? b.evens : b.odds);
                b.all += pixel(x, y).sum();
                ++b.count;
            }
    };
    Bands gardenFront, meadowFront, gardenBack, meadowBack;
    look({0.0f, 2.5f, 7.0f}, gardenFront, meadowFront);
    look({0.0f, 2.5f, -7.0f}, gardenBack, meadowBack);
    for (const Bands* b : {&gardenFront, &meadowFront, &gardenBack, &meadowBack}) {
        ASSERT_GT(b->evens, 300);
        ASSERT_GT(b->odds, 300);
    }
    // The lawn's own patches are the same from either side: what changes
    // between the views is the stripes' sheen.
    const double swap = gardenFront.difference() - gardenBack.difference();
    EXPECT_GT(std::fabs(swap), 0.08 * gardenFront.mean()) << "the garden's stripes swap light and dark";
    const double meadowSwap = meadowFront.difference() - meadowBack.difference();
    EXPECT_LT(std::fabs(meadowSwap), 0.25 * std::fabs(swap)) << "the meadow is not mown";
    EXPECT_LT(meadowFront.mean(), 0.93 * gardenFront.mean()) << "the meadow's longer grass is darker";
    EXPECT_LT(meadowBack.mean(), 0.93 * gardenBack.mean());
}

// Close by, the lawn shows its blades: neighbouring pixels differ. Far
// off, where a blade is smaller than a pixel, they fade to their mean:
// neighbours differ no more than the lawn's broad patches make them.
TEST_F(GroundTest, BladesShowCloseAndFadeWhereTheyShrinkBelowAPixel) {
    GroundStyle ground;
    ground.lineWidth = 0.0f;
    // The mean difference in r + g + b between horizontal neighbours over
    // the middle rows.
    auto roughness = [&](const glm::vec3& eye, const glm::vec3& at) {
        drawGround(makeView(eye, at), ground);
        double sum = 0.0;
        int n = 0;
        for (int y = kHeight / 2 - 20; y < kHeight / 2 + 20; ++y)
            for (int x = 0; x + 1 < kWidth; ++x) {
                sum += std::abs(pixel(x + 1, y).sum() - pixel(x, y).sum());
                ++n;
            }
        return sum / n;
    };
    const double close = roughness({0.3f, 0.4f, 0.2f}, {0.3f, 0.0f, 0.0f});   // a pixel is about 1 mm
    const double far = roughness({0.3f, 12.0f, 0.2f}, {0.3f, 0.0f, 0.0f});    // about 4 cm
    // Measured: 5.2 close and 1.9 far; without blades 0.2 close; with
    // blades never faded 18.8 far.
    EXPECT_GT(close, 3.0) << "blades a few pixels across";
    EXPECT_LT(far, 3.0) << "blades below a pixel are not sampled into noise";
}

TEST_F(GroundTest, HazeTakesFarSurfacesToTheHorizonColourAndLeavesNearOnesAlone) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    const RenderMaterial red{{0.9f, 0.1f, 0.1f}, 0.0f, 16.0f};
    GroundStyle ground;
    ground.lineWidth = 0.0f;
    ground.halfExtent = kFar;
    auto draw = [&](float haze) {
        View view = makeView({0.0f, 1.7f, 0.0f}, {0.0f, 1.7f, -10.0f});
        view.hazeDistance = haze;
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawGround(ground);
        renderer_->drawChunk(1, glm::translate(glm::mat4(1.0f), glm::vec3(-1.5f, 1.7f, -8.0f)), red);
        renderer_->drawChunk(1, glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(20.0f, 1.7f, -150.0f)), glm::vec3(12.0f)),
                             red);
        renderer_->endFrame();
        read();
        return view;
    };
    const View view = draw(0.0f);
    const glm::ivec2 nearPx = worldToPixel(view, {-1.5f, 1.7f, -8.0f});
    const glm::ivec2 farPx = worldToPixel(view, {20.0f, 1.7f, -150.0f});
    // The horizon is the middle row: ground 5 rows below it lies about
    // 95 m away (inside the far plane), sky 2 rows above; at the left
    // edge, clear of the near sphere.
    const int horizonRow = kHeight / 2;
    const Rgba nearClear = pixel(nearPx.x, nearPx.y), farClear = pixel(farPx.x, farPx.y);
    const Rgba groundClear = pixel(6, horizonRow + 5), skyClear = pixel(6, horizonRow - 2);
    ASSERT_TRUE(reddish(nearClear));
    ASSERT_TRUE(reddish(farClear));
    EXPECT_GT(std::abs(groundClear.b - skyClear.b), 60) << "without haze the lawn ends against the sky";

    draw(40.0f);
    const Rgba nearHazy = pixel(nearPx.x, nearPx.y), farHazy = pixel(farPx.x, farPx.y);
    const Rgba groundHazy = pixel(6, horizonRow + 5), skyHazy = pixel(6, horizonRow - 2);
    EXPECT_NEAR(nearHazy.r, nearClear.r, 12) << "8 m away: hardly any haze";
    EXPECT_NEAR(nearHazy.g, nearClear.g, 12);
    EXPECT_FALSE(reddish(farHazy)) << "150 m away: the haze covers it";
    EXPECT_NEAR(farHazy.b, skyHazy.b, 8) << "in the horizon's colour";
    EXPECT_NEAR(groundHazy.b, skyHazy.b, 8) << "the lawn meets the sky without an edge";
    EXPECT_NEAR(groundHazy.g, skyHazy.g, 8);
}

// Clouds cover part of the sky above the horizon, whiter than the clear
// sky there, and nothing below it; a clear sky (a bare View's) has none.
TEST_F(GroundTest, CloudsCoverPartOfTheSkyAndNothingBelowTheHorizon) {
    auto sky = [&](float clouds) {
        View view = makeView({0.0f, 1.7f, 0.0f}, {0.0f, 5.0f, -10.0f});
        view.clouds = clouds;
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->endFrame();
        read();
        return view;
    };
    const View view = sky(0.0f);
    const std::vector<std::uint8_t> clear = color_;
    sky(0.55f);
    int above = 0, clouded = 0, belowChanged = 0, below = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 4;
            const Rgba p = pixel(x, y);
            if (rayDirection(view, x, y).y > 0.0f) {
                ++above;
                // A cloud: brighter than the clear sky there, and nearly grey.
                clouded += (p.sum() > int(clear[i]) + int(clear[i + 1]) + int(clear[i + 2]) + 60 && p.b - p.r < 40) ? 1 : 0;
            } else {
                ++below;
                belowChanged += (p.r != clear[i] || p.g != clear[i + 1] || p.b != clear[i + 2]) ? 1 : 0;
            }
        }
    ASSERT_GT(above, 10000);
    ASSERT_GT(below, 1000);
    EXPECT_GT(clouded, above / 25) << "clouds over part of the sky (8.6 % are this white here)";
    EXPECT_LT(clouded, above * 8 / 10) << "and blue between them";
    EXPECT_EQ(belowChanged, 0) << "no cloud below the horizon";
}

// The sky's gradient and clouds come from a cube map baked while the sky's
// look holds (sky_pass.h): it shows what the sky evaluated at each pixel
// shows, up to the map's filtering, the sun's disc included; it is baked
// once for frames that keep the look and again when the look changes.
TEST_F(GroundTest, TheBakedSkyShowsWhatEachPixelWouldAndIsBakedOnlyWhenItsLookChanges) {
    const glm::vec3 toSun = glm::normalize(glm::vec3(0.3f, 0.35f, -0.8f));
    const glm::vec3 eye(0.0f, 1.7f, 0.0f);
    // The sun in the upper part of the picture, clouds around it.
    View view = makeView(eye, eye + 10.0f * glm::normalize(toSun - glm::vec3(0.0f, 0.25f, 0.0f)), toSun);
    view.clouds = 0.55f;
    RenderQuality quality = plainQuality();
    auto sky = [&](bool baked) {
        renderer_->setQuality(quality);
        renderer_->setSkyBaked(baked);
        target_->bind();
        renderer_->beginFrame(view);
        const RenderStats stats = renderer_->endFrame();
        read();
        return stats.skyBakes;
    };
    EXPECT_EQ(sky(false), 0u) << "evaluated per pixel: nothing baked";
    const std::vector<std::uint8_t> direct = color_;
    // Each baked pixel within the colours the per-pixel sky has around it
    // (its 3 x 3 neighbours, give or take 6 levels): the map resamples the
    // sky, so its pixel may be any blend of its neighbours', but a face
    // turned the wrong way or a seam would put a colour there that is not.
    // A few are not at any size: where the clouds' pattern is finer than a
    // pixel (towards the horizon) the per-pixel sky catches specks between
    // the map's texels.
    const auto at = [&](const std::vector<std::uint8_t>& image, int x, int y, int c) {
        x = std::clamp(x, 0, kWidth - 1);
        y = std::clamp(y, 0, kHeight - 1);
        return int(image[(static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 4 + c]);
    };
    for (const int faceSize : {1024, 512}) {
        SCOPED_TRACE(faceSize);
        quality.skyMapSize = faceSize;
        EXPECT_EQ(sky(true), 1u) << "the first baked frame at this size bakes";
        double difference = 0.0;
        int outside = 0, sun = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                bool within = true;
                for (int c = 0; c < 3; ++c) {
                    int lo = 255, hi = 0;
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            lo = std::min(lo, at(direct, x + dx, y + dy, c));
                            hi = std::max(hi, at(direct, x + dx, y + dy, c));
                        }
                    const int v = at(color_, x, y, c);
                    within = within && v >= lo - 6 && v <= hi + 6;
                    difference += std::abs(v - at(direct, x, y, c));
                }
                outside += within ? 0 : 1;
                sun += (glm::dot(rayDirection(view, x, y), toSun) > 0.99996f && pixel(x, y).sum() > 3 * 250) ? 1 : 0;
            }
        const int pixels = kWidth * kHeight;
        // Measured: 1.25 and 2.65 levels on average; 100 and 130 outside.
        EXPECT_LT(difference / pixels, faceSize >= 1024 ? 2.0 : 4.0) << "levels (r + g + b) a pixel on average";
        EXPECT_LT(outside, pixels / 400) << "pixels unlike any of the per-pixel sky's around them";
        EXPECT_GT(sun, 0) << "the sun's disc, white, where it stands";
    }

    EXPECT_EQ(sky(true), 0u) << "the same look: the map is kept";
    EXPECT_EQ(sky(true), 0u);
    view.clouds = 0.3f;
    EXPECT_EQ(sky(true), 1u) << "fewer clouds: baked again";
    view.lights.front().direction = glm::vec3(-0.5f, 0.6f, -0.4f);
    EXPECT_EQ(sky(true), 1u) << "the sun moved: baked again";
    view.clearColor = glm::vec4(0.7f, 0.6f, 0.5f, 1.0f);
    EXPECT_EQ(sky(true), 1u) << "another horizon: baked again";
    EXPECT_EQ(sky(true), 0u);
}

}  // namespace
}  // namespace hg::garden::test
