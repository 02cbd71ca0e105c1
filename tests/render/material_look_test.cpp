// Materials per sculpture, the clay view and the wireframe overlay
// (docs/rendering.md "Materials"), read back as real pixels: the built-in
// materials differ as their substances do, their procedural detail lies in
// the model's frame (it moves and scales with the sculpture), the clay
// view makes every material one, and the overlay draws the edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "garden/render/material_look.h"
#include "garden/render/screenshot.h"
#include "garden/render/shapes.h"
#include "garden/scene/materials.h"
#include "gl_fixture.h"

namespace hg::garden::test {
namespace {

RenderMaterial builtin(const std::string& name, float detailScale = 0.1f) {
    const auto m = builtinMaterial(name);
    EXPECT_TRUE(m.has_value()) << name;
    return renderMaterial(m ? *m : Material{}, detailScale);
}

// A square of side 2 in the model's z = 0 plane, facing +z, cut into a
// grid of n x n cells (the wireframe has inner edges to show).
poly::Mesh square(int n = 1) {
    poly::Mesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            m.positions.insert(m.positions.end(), {-1.0f + 2.0f * float(i) / float(n), -1.0f + 2.0f * float(j) / float(n), 0.0f});
            m.normals.insert(m.normals.end(), {0.0f, 0.0f, 1.0f});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto a = static_cast<std::uint32_t>(j * (n + 1) + i), b = a + 1, c = a + static_cast<std::uint32_t>(n + 1),
                       d = c + 1;
            m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
        }
    return m;
}

class MaterialLookTest : public GlTest {
protected:
    void render(const View& view, const glm::mat4& model, const RenderMaterial& material,
                const RenderQuality& quality = plainQuality()) {
        renderer_->setQuality(quality);
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawChunk(1, model, material);
        renderer_->endFrame();
        read();
        if (const char* dump = std::getenv("HG_LOOK_DUMP"))
            writePng(std::string(dump) + ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                         std::to_string(dumps_++) + ".png", kWidth, kHeight, color_);
    }
    // Mean red, green and blue over the square of (2k + 1) pixels about the centre.
    glm::dvec3 meanColour(int k) const {
        glm::dvec3 sum(0.0);
        for (int y = kHeight / 2 - k; y <= kHeight / 2 + k; ++y)
            for (int x = kWidth / 2 - k; x <= kWidth / 2 + k; ++x) {
                const Rgba p = pixel(x, y);
                sum += glm::dvec3(p.r, p.g, p.b);
            }
        return sum / double((2 * k + 1) * (2 * k + 1));
    }
    // r + g + b along the middle row, from x0 to x1.
    std::vector<int> row(int x0, int x1) const {
        std::vector<int> sums;
        for (int x = x0; x <= x1; ++x) sums.push_back(pixel(x, kHeight / 2).sum());
        return sums;
    }
    // The variance of r + g + b over the square of (2k + 1) pixels about the centre.
    double centreVariance(int k) const {
        double sum = 0.0, sum2 = 0.0;
        for (int y = kHeight / 2 - k; y <= kHeight / 2 + k; ++y)
            for (int x = kWidth / 2 - k; x <= kWidth / 2 + k; ++x) {
                const double v = pixel(x, y).sum();
                sum += v;
                sum2 += v * v;
            }
        const double n = double((2 * k + 1) * (2 * k + 1));
        return sum2 / n - (sum / n) * (sum / n);
    }
    static int spread(const std::vector<int>& v) {
        return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
    }
    int dumps_ = 0;
};

TEST_F(MaterialLookTest, BronzeIsDarkerAndWarmerThanPlaster) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 96, 48));
    const View view = makeView({0, 0, 4}, {0, 0, 0});
    render(view, glm::mat4(1.0f), builtin("plaster"));
    const glm::dvec3 plaster = meanColour(30);
    render(view, glm::mat4(1.0f), builtin("bronze"));
    const glm::dvec3 bronze = meanColour(30);
    const auto sum = [](const glm::dvec3& c) { return c.r + c.g + c.b; };
    EXPECT_LT(sum(bronze), 0.7 * sum(plaster)) << "bronze " << bronze.r << " " << bronze.g << " " << bronze.b
                                               << ", plaster " << plaster.r << " " << plaster.g << " " << plaster.b;
    // Warm: red well above blue, where plaster is nearly neutral.
    EXPECT_GT(bronze.r, 1.3 * bronze.b);
    EXPECT_LT(plaster.r, 1.1 * plaster.b);
}

TEST_F(MaterialLookTest, MarbleShowsVeinsAlongALineWherePlainShowsNone) {
    renderer_->upload(1, 1, square());
    // Straight on, the light behind the eye: a flat face of one shade
    // unless the material varies.
    const View view = makeView({0, 0, 2.2f}, {0, 0, 0}, {0, 0, 1});
    const int x0 = kWidth / 8, x1 = kWidth - kWidth / 8;
    // No highlight: it would vary along the line by itself.
    RenderMaterial marbleMatte = builtin("marble");
    marbleMatte.specular = 0.0f;
    RenderMaterial flat = marbleMatte;
    flat.kind = kSurfacePlain;
    render(view, glm::mat4(1.0f), flat);
    const int plainSpread = spread(row(x0, x1));
    render(view, glm::mat4(1.0f), marbleMatte);
    const std::vector<int> marble = row(x0, x1);
    EXPECT_LE(plainSpread, 3) << "a plain face is one shade";
    EXPECT_GT(spread(marble), 60) << "marble's veins darken it in places along the line";
    // Veins are thin: most of the line is the pale body.
    const int top = *std::max_element(marble.begin(), marble.end());
    const auto pale = std::count_if(marble.begin(), marble.end(), [&](int s) { return s > top - 60; });
    EXPECT_GT(pale, static_cast<long>(marble.size()) / 2);
}

TEST_F(MaterialLookTest, EveryBuiltInMaterialLooksItsOwn) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 96, 48));
    const View view = makeView({0, 0, 4}, {0, 0, 0});
    std::vector<std::vector<std::uint8_t>> images;
    for (const Material& m : builtinMaterials()) {
        render(view, glm::mat4(1.0f), renderMaterial(m, 0.1f));
        images.push_back(color_);
    }
    for (std::size_t a = 0; a < images.size(); ++a)
        for (std::size_t b = a + 1; b < images.size(); ++b)
            EXPECT_NE(images[a], images[b]) << builtinMaterials()[a].name << " and " << builtinMaterials()[b].name;
}

TEST_F(MaterialLookTest, TheDetailMovesAndScalesWithTheSculpture) {
    renderer_->upload(1, 1, square());
    const glm::vec3 eye(0, 0, 2.2f);
    for (const char* name : {"marble", "wood", "stone"}) {
        SCOPED_TRACE(name);
        const RenderMaterial m = builtin(name);
        render(makeView(eye, {0, 0, 0}, {0, 0, 1}), glm::mat4(1.0f), m);
        const std::vector<std::uint8_t> home = color_;
        // Moved 3.7 m along x and twice the size, seen from as far again:
        // the same picture, vein for vein.
        const glm::vec3 to(3.7f, 0.0f, 0.0f);
        const glm::mat4 moved = glm::scale(glm::translate(glm::mat4(1.0f), to), glm::vec3(2.0f));
        render(makeView(to + 2.0f * eye, to, {0, 0, 1}), moved, m);
        int differing = 0;
        for (std::size_t i = 0; i < home.size(); ++i) differing += std::abs(int(home[i]) - int(color_[i])) > 3 ? 1 : 0;
        EXPECT_LT(differing, static_cast<int>(home.size() / 200)) << "pixels that changed";
        // Moved without the camera following, the pattern is not painted on the screen.
        render(makeView(eye, {0, 0, 0}, {0, 0, 1}), glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -0.3f)), m);
        int changed = 0;
        for (std::size_t i = 0; i < home.size(); ++i) changed += std::abs(int(home[i]) - int(color_[i])) > 3 ? 1 : 0;
        EXPECT_GT(changed, static_cast<int>(home.size() / 20));
    }
}

// The procedural detail is relief too: on a flat square under a low light
// stone, wood and clay vary more with the shading normal tilted by their
// detail than with colour alone; a plain material has no relief, and the
// low preset switches it off.
TEST_F(MaterialLookTest, TheDetailStandsOutAsReliefUnlessSwitchedOff) {
    renderer_->upload(1, 1, square());
    const View view = makeView({0, 0, 2.2f}, {0, 0, 0}, {1.0f, 0.3f, 0.35f});  // low, from the side
    RenderQuality flat = plainQuality();
    flat.materialBump = false;
    for (const char* name : {"stone", "wood", "clay"}) {
        SCOPED_TRACE(name);
        render(view, glm::mat4(1.0f), builtin(name), flat);
        const double colourOnly = centreVariance(40);
        const std::vector<std::uint8_t> without = color_;
        render(view, glm::mat4(1.0f), builtin(name));
        EXPECT_GT(centreVariance(40), 1.5 * colourOnly) << "colour only: " << colourOnly;
        render(view, glm::mat4(1.0f), builtin(name), qualityOf(QualityPreset::Low));
        EXPECT_EQ(color_, without) << "the low preset draws no relief";
    }
    const RenderMaterial plain{{0.7f, 0.7f, 0.7f}, 0.2f, 16.0f};
    render(view, glm::mat4(1.0f), plain, flat);
    const std::vector<std::uint8_t> without = color_;
    render(view, glm::mat4(1.0f), plain);
    EXPECT_EQ(color_, without) << "no detail, no relief";
}

// A pattern finer than a pixel fades to its mean instead of speckling the
// surface: the same square with the detail a thousandth of its size is one
// shade, nearly, where the detail at a tenth shows (docs/rendering.md,
// "Materials").
TEST_F(MaterialLookTest, DetailFinerThanAPixelFadesToItsMean) {
    renderer_->upload(1, 1, square());
    const View view = makeView({0, 0, 2.2f}, {0, 0, 0}, {0, 0, 1});
    for (const char* name : {"stone", "bronze", "clay"}) {
        SCOPED_TRACE(name);
        RenderMaterial m = builtin(name, 0.2f);
        m.specular = 0.0f;
        // The peer: the same colour and metal without detail (a metal's
        // highlight still varies over the face).
        RenderMaterial plain = m;
        plain.kind = kSurfacePlain;
        render(view, glm::mat4(1.0f), plain);
        const double none = centreVariance(40);
        render(view, glm::mat4(1.0f), m);
        const double seen = centreVariance(40);
        m.detailScale = 0.0002f;
        render(view, glm::mat4(1.0f), m);
        const double fine = centreVariance(40);
        EXPECT_GT(seen, none + 20.0) << "the detail shows where it is larger than a pixel";
        EXPECT_LT(fine, none + 2.0) << "detail finer than a pixel is averaged, not sampled (seen: " << seen
                                    << ", no detail: " << none << ")";
    }
}

TEST_F(MaterialLookTest, TheClayViewGivesEveryMaterialTheSamePixels) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 96, 48));
    const View view = makeView({0, 0, 4}, {0, 0, 0});
    ViewLook clay;
    clay.clay = true;
    render(view, glm::mat4(1.0f), builtin("bronze"));
    const std::vector<std::uint8_t> bronze = color_;
    render(view, glm::mat4(1.0f), builtin("marble"));
    ASSERT_NE(bronze, color_) << "the materials differ without the clay view";
    render(view, glm::mat4(1.0f), lookedAt(builtin("bronze"), clay));
    const std::vector<std::uint8_t> bronzeInClay = color_;
    render(view, glm::mat4(1.0f), lookedAt(builtin("marble"), clay));
    EXPECT_EQ(bronzeInClay, color_);
    // Neutral and matte: grey, no coloured tint.
    const glm::dvec3 c = meanColour(20);
    EXPECT_LT(std::abs(c.r - c.b), 0.12 * c.r);
    // With cavity shading (look_test.cpp shows what it does to a groove),
    // which the Garden panel switches off; outside the clay view the
    // material's own.
    EXPECT_EQ(lookedAt(builtin("bronze"), clay).cavity, 1.0f);
    clay.cavity = false;
    EXPECT_EQ(lookedAt(builtin("bronze"), clay).cavity, 0.0f);
    EXPECT_EQ(lookedAt(builtin("bronze"), ViewLook{}).cavity, builtin("bronze").cavity);
}

TEST_F(MaterialLookTest, TheWireframeOverlayDrawsTheEdgesOnTheSurfaceOnly) {
    renderer_->upload(1, 1, square(8));
    const View view = makeView({0, 0, 2.6f}, {0, 0, 0}, {0, 0, 1});
    const RenderMaterial plaster = builtin("plaster");
    render(view, glm::mat4(1.0f), plaster);
    const std::vector<std::uint8_t> bare = color_;
    ViewLook wire;
    wire.wireframe = true;
    render(view, glm::mat4(1.0f), lookedAt(plaster, wire));
    // The square spans the middle of the image; its 8 x 8 cells' edges (and
    // diagonals) cross the middle row about 17 times.
    int darkened = 0, outside = 0, runs = 0;
    bool inRun = false;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = (std::size_t(y) * kWidth + std::size_t(x)) * 4;
            const int before = bare[i] + bare[i + 1] + bare[i + 2], after = pixel(x, y).sum();
            const bool onSquare = std::abs(x - kWidth / 2) < kWidth * 0.35 && std::abs(y - kHeight / 2) < kHeight * 0.35;
            const bool dark = after < before - 60;
            if (dark && onSquare) ++darkened;
            if (before != after && !onSquare && (std::abs(x - kWidth / 2) > kWidth * 0.49 || std::abs(y - kHeight / 2) > kHeight * 0.49))
                ++outside;
            if (y == kHeight / 2 + 3) {
                if (dark && !inRun) ++runs;
                inRun = dark;
            }
        }
    EXPECT_GT(darkened, 2000) << "edge pixels darkened on the square";
    EXPECT_GE(runs, 12) << "edges crossed along one row";
    EXPECT_EQ(outside, 0) << "the sky is left alone";
}

}  // namespace
}  // namespace hg::garden::test
