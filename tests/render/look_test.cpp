// The passes that make the garden worth seeing (docs/rendering.md), each
// read back as real pixels: anti-aliased edges, tone mapping that keeps
// ordinary colours, the sun's shadow without acne, ambient occlusion in a
// carved groove, GPU timings per pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>
#include <memory>
#include <string>

#include "frep/language/diagnostics.h"
#include "frep/eval/model.h"
#include "frep/language/parser.h"
#include "garden/render/material_look.h"
#include "garden/render/screenshot.h"
#include "garden/render/shapes.h"
#include "gl_fixture.h"
#include "polygonizer/export/export_mesher.h"
#include "voxel/sampler.h"

namespace hg::garden::test {
namespace {

const RenderMaterial kRed{{0.9f, 0.1f, 0.1f}, 0.2f, 32.0f};
const RenderMaterial kMatteWhite{{0.8f, 0.8f, 0.8f}, 0.0f, 16.0f};

glm::mat4 at(const glm::vec3& p, float scale = 1.0f) {
    return glm::scale(glm::translate(glm::mat4(1.0f), p), glm::vec3(scale));
}

// A HyperFun body with one parameter a[1], voxelized at 96 and meshed as
// the garden does.
poly::Mesh meshedBody(const std::string& source, double a) {
    frep::ParseResult r = frep::parseProgram(source, "carved.hf");
    if (!r.ok()) {
        ADD_FAILURE() << (r.errors.empty() ? "parse failed" : frep::formatDiagnostic(r.errors[0]));
        return {};
    }
    auto program = std::make_shared<const frep::Program>(std::move(*r.program));
    frep::Model model(program, program->defaultBody(), {a});
    voxel::VolumeRequest request;
    request.resolution = 96;
    voxel::VoxelizeResult v = voxel::voxelize(model, request);
    if (!v.volume) {
        ADD_FAILURE() << v.error;
        return {};
    }
    return poly::meshVolume(*v.volume);
}

// A real sculpture, carved: a 1 x 0.6 x 1 m block with a slot 0.12 m wide
// and 0.15 m deep along z across its top.
poly::Mesh slottedBlock() {
    return meshedBody("slotted(x[3], a[1]) {\n"
                      "  block = (0.5 - x[1]) & (0.5 + x[1]) & (0.3 - x[2]) & (0.3 + x[2]) & (0.5 - x[3]) & (0.5 + x[3]);\n"
                      "  slot = (a[1] - x[1]) & (a[1] + x[1]) & (x[2] - 0.15);\n"
                      "  slotted = block \\ slot;\n"
                      "}\n",
                      0.06);
}

// The same block with a round-bottomed groove along z across its top: a
// cylinder of radius a[1] whose axis lies in the top face.
poly::Mesh groovedBlock(double radius) {
    return meshedBody("grooved(x[3], a[1]) {\n"
                      "  block = (0.5 - x[1]) & (0.5 + x[1]) & (0.3 - x[2]) & (0.3 + x[2]) & (0.5 - x[3]) & (0.5 + x[3]);\n"
                      "  groove = a[1] * a[1] - x[1] * x[1] - (x[2] - 0.3) * (x[2] - 0.3);\n"
                      "  grooved = block \\ groove;\n"
                      "}\n",
                      radius);
}

class LookTest : public GlTest {
protected:
    void render(const View& view, const RenderQuality& quality, bool ground, const glm::mat4& model,
                const RenderMaterial& material, ChunkId chunk = 1) {
        renderer_->setQuality(quality);
        target_->bind();
        renderer_->beginFrame(view);
        if (ground) renderer_->drawGround(GroundStyle{});
        renderer_->drawChunk(chunk, model, material);
        renderer_->endFrame();
        read();
        if (std::getenv("HG_LOOK_DUMP")) writePng(std::string(std::getenv("HG_LOOK_DUMP")) + std::to_string(dumps_++) + ".png", kWidth, kHeight, color_);
    }
    int dumps_ = 0;
    // Mean of r + g + b over a square of (2k + 1) pixels a side about p.
    double meanSum(glm::ivec2 p, int k = 2) const {
        double sum = 0.0;
        for (int y = p.y - k; y <= p.y + k; ++y)
            for (int x = p.x - k; x <= p.x + k; ++x) sum += pixel(x, y).sum();
        return sum / double((2 * k + 1) * (2 * k + 1));
    }
};

RenderQuality plain() { return plainQuality(); }

TEST_F(LookTest, MultisamplingGivesSilhouettesIntermediateCoverageAndLeavesFlatColoursAlone) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 96, 48));
    const View view = makeView({0, 0, 5}, {0, 0, 0});
    // The sky alone, to tell sky pixels from the sphere's.
    renderer_->setQuality(plain());
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->endFrame();
    read();
    const std::vector<std::uint8_t> sky = color_;
    // Neither the sky nor the sphere: a pixel the silhouette crosses.
    auto mixedCount = [&] {
        int n = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const std::size_t i = (std::size_t(y) * kWidth + std::size_t(x)) * 4;
                bool isSky = true;
                for (int c = 0; c < 3; ++c) isSky = isSky && std::abs(int(color_[i + c]) - int(sky[i + c])) <= 2;
                n += (!isSky && !reddish(pixel(x, y))) ? 1 : 0;
            }
        return n;
    };
    RenderQuality aliased = plain();
    render(view, aliased, false, glm::mat4(1.0f), kRed);
    const int hard = mixedCount();
    const Rgba flatAliased = pixel(kWidth / 2, kHeight / 2);

    RenderQuality smooth = aliased;
    smooth.msaaSamples = 4;
    render(view, smooth, false, glm::mat4(1.0f), kRed);
    const int soft = mixedCount();
    const Rgba flatSmooth = pixel(kWidth / 2, kHeight / 2);

    const double perimeter = 2.0 * kPi * discRadiusPixels(1.0, 5.0);
    EXPECT_LT(hard, 0.05 * perimeter) << "one sample: every pixel is sky or sphere";
    EXPECT_GT(soft, 0.5 * perimeter) << "four samples: the outline's pixels blend sky and sphere";
    EXPECT_NEAR(flatSmooth.r, flatAliased.r, 1);
    EXPECT_NEAR(flatSmooth.g, flatAliased.g, 1);
    EXPECT_NEAR(flatSmooth.b, flatAliased.b, 1);
}

// Without multisampling a pixel is covered where its centre is, as a
// one-sample framebuffer is. The scene's targets were multisample textures
// of one sample, which a driver may make four (llvmpipe does): each pixel
// was then the coverage of its first sample, a quarter of a pixel off its
// centre, and the low preset rasterized four samples for the one it shows
// (at one sample they are now plain textures). An upright square
// whose edges lie 0.45 of a pixel past pixel boundaries, seen square on
// with one model unit a pixel, covers exactly the pixels whose centres it
// holds.
TEST_F(LookTest, WithoutMultisamplingEachPixelIsCoveredAtItsCentre) {
    const float x0 = 100.45f, x1 = 150.45f, y0 = 60.45f, y1 = 180.45f;
    poly::Mesh square;
    square.positions = {x0, y0, 0, x1, y0, 0, x1, y1, 0, x0, y1, 0};
    square.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    square.indices = {0, 1, 2, 0, 2, 3};
    renderer_->upload(1, 1, square);
    View view = makeView({0, 0, 10}, {0, 0, 0}, {0.3f, 0.4f, 1.0f});
    view.projection = glm::ortho(0.0f, float(kWidth), 0.0f, float(kHeight), 1.0f, 100.0f);
    render(view, plain(), false, glm::mat4(1.0f), kRed);
    int wrong = 0, inside = 0;
    // Window rows count up from the bottom; the read-back image's from the top.
    for (int wy = 40; wy < 200; ++wy)
        for (int x = 80; x < 170; ++x) {
            const bool centreInside = x + 0.5f > x0 && x + 0.5f < x1 && wy + 0.5f > y0 && wy + 0.5f < y1;
            inside += centreInside ? 1 : 0;
            wrong += reddish(pixel(x, kHeight - 1 - wy)) != centreInside ? 1 : 0;
        }
    EXPECT_EQ(inside, 50 * 120);
    EXPECT_EQ(wrong, 0) << "pixels whose colour does not follow their centre";
}

TEST_F(LookTest, ToneMappingKeepsOrdinaryColoursAndRollsHighlightsOffWithTheirHue) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    View view = makeView({0, 0, 5}, {0, 0, 0});
    view.lights.clear();  // ambient alone: one known linear value on the whole disc
    const RenderMaterial orange{{0.8f, 0.4f, 0.2f}, 0.0f, 16.0f};
    auto linear = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
    auto encode = [](double c) { return 255.0 * (c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1 / 2.4) - 0.055); };

    view.ambient = glm::vec3(0.5f);
    render(view, plain(), false, glm::mat4(1.0f), orange);
    Rgba c = pixel(kWidth / 2, kHeight / 2);
    EXPECT_NEAR(c.r, encode(0.5 * linear(0.8)), 1.5) << "below the roll-off a colour passes unchanged";
    EXPECT_NEAR(c.g, encode(0.5 * linear(0.4)), 1.5);
    EXPECT_NEAR(c.b, encode(0.5 * linear(0.2)), 1.5);

    RenderQuality brighter = plain();
    brighter.exposure = 2.0f;
    render(view, brighter, false, glm::mat4(1.0f), orange);
    c = pixel(kWidth / 2, kHeight / 2);
    EXPECT_NEAR(c.r, encode(linear(0.8)), 1.5) << "exposure scales the linear light";

    view.ambient = glm::vec3(6.0f);
    render(view, plain(), false, glm::mat4(1.0f), orange);
    c = pixel(kWidth / 2, kHeight / 2);
    EXPECT_LT(c.r, 255) << "rolled off, not clipped";
    EXPECT_GT(c.r, 240);
    EXPECT_GT(c.r, c.g + 10) << "still orange";
    EXPECT_GT(c.g, c.b);
}

TEST_F(LookTest, TheSunCastsASoftShadowOnTheGroundAndNoneOnLitFaces) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    const glm::vec3 sun(0.3f, 1.0f, 0.2f);
    const View view = makeView({0, 4, 7}, {0, 0.5f, 0}, sun);
    const glm::vec3 centre(0, 1.2f, 0);
    const glm::mat4 model = at(centre, 0.5f);
    // Where the sun's ray through the sphere's centre meets the ground.
    const glm::vec3 l = glm::normalize(sun);
    const glm::vec3 under = centre - l * (centre.y / l.y);
    const glm::vec3 away(-2.5f, 0, 1.5f);
    const glm::ivec2 underPx = worldToPixel(view, under), awayPx = worldToPixel(view, away);

    RenderQuality quality;
    quality.ambientOcclusion = false;
    quality.shadows = false;
    render(view, quality, true, model, kRed);
    const std::vector<std::uint8_t> lit = color_;
    const double underLit = meanSum(underPx), awayLit = meanSum(awayPx);

    quality.shadows = true;
    render(view, quality, true, model, kRed);
    const double underShadow = meanSum(underPx), awayShadow = meanSum(awayPx);
    EXPECT_LT(underShadow, underLit - 60) << "the sphere's shadow lies where the sun's ray meets the ground";
    EXPECT_NEAR(awayShadow, awayLit, 3) << "ground in the open is not shadowed";
    // Soft edge: walking out of the shadow, some pixels are partly lit.
    int between = 0;
    for (float t = 0.0f; t < 1.2f; t += 0.01f) {
        const glm::ivec2 p = worldToPixel(view, under + glm::vec3(t, 0, 0));
        const std::size_t i = (std::size_t(p.y) * kWidth + std::size_t(p.x)) * 4;
        const double open = double(lit[i]) + lit[i + 1] + lit[i + 2];
        const double ratio = pixel(p.x, p.y).sum() / std::max(open, 1.0);
        between += (ratio > 0.75 && ratio < 0.95) ? 1 : 0;
    }
    EXPECT_GE(between, 2) << "PCF gives the shadow a graded edge";
}

// The shadow map is drawn again only when something it shows changes: the
// same garden from the same sun keeps it (a still frame, the headset's
// second eye), and a kept map gives the very pixels a drawn one does. A
// moved sculpture, a chunk's new mesh or the map's size draw it again.
TEST_F(LookTest, TheShadowMapIsKeptWhileNothingItShowsChanges) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    const glm::vec3 sun(0.3f, 1.0f, 0.2f);
    RenderQuality quality;
    quality.ambientOcclusion = false;
    renderer_->setQuality(quality);
    // One frame of one view or more (eyes a little apart); its stats.
    auto frame = [&](const glm::vec3& centre, std::initializer_list<float> eyes = {0.0f}) {
        for (float dx : eyes) {
            target_->bind();
            renderer_->beginFrame(makeView({dx, 4, 7}, {dx, 0.5f, 0}, sun));
            renderer_->drawGround(GroundStyle{});
            renderer_->drawChunk(1, at(centre, 0.5f), kRed);
            renderer_->finishView();
        }
        const RenderStats stats = renderer_->endFrame();
        read();
        return stats;
    };
    const glm::vec3 here(0, 1.2f, 0), there(0.6f, 1.2f, 0);

    RenderStats s = frame(here);
    EXPECT_EQ(s.shadowMapsDrawn, 1u);
    const std::vector<std::uint8_t> first = color_;
    s = frame(here);
    EXPECT_EQ(s.shadowMapsDrawn, 0u);
    EXPECT_EQ(s.shadowMapsKept, 1u) << "nothing changed: the map is kept";
    EXPECT_EQ(color_, first) << "and gives the same picture";

    s = frame(there);
    EXPECT_EQ(s.shadowMapsDrawn, 1u) << "the sculpture moved";
    const std::vector<std::uint8_t> moved = color_;
    EXPECT_NE(moved, first);
    renderer_->setShadowReuse(false);
    s = frame(there);
    EXPECT_EQ(s.shadowMapsDrawn, 1u) << "reuse off: drawn every view";
    EXPECT_EQ(color_, moved) << "a kept map and a drawn one give the same pixels";
    renderer_->setShadowReuse(true);

    // Two eyes a few centimetres apart see the same casters: one map.
    s = frame(there, {-0.032f, 0.032f});
    EXPECT_EQ(s.shadowMapsDrawn + s.shadowMapsKept, 2u);
    EXPECT_EQ(s.shadowMapsKept, 2u) << "both eyes keep the map of the frame before";

    // A new mesh for the chunk (a carve, a new level) of the same size and
    // box, in the same place of the arena: the same draws, other bytes.
    // Drawn again, and its shadow is the new mesh's.
    poly::Mesh flattened = uvSphereMesh(1.0f, 48, 24);
    for (std::size_t i = 1; i < flattened.positions.size(); i += 3)
        if (std::abs(flattened.positions[i]) < 0.99f) flattened.positions[i] *= 0.3f;
    const std::size_t firstVertex = renderer_->arena().slot(1)->firstVertex;
    renderer_->upload(1, 2, flattened);
    ASSERT_EQ(renderer_->arena().slot(1)->firstVertex, firstVertex);
    s = frame(there);
    EXPECT_EQ(s.shadowMapsDrawn, 1u) << "the chunk's mesh changed";
    const std::vector<std::uint8_t> bigger = color_;
    renderer_->setShadowReuse(false);
    frame(there);
    EXPECT_EQ(color_, bigger);
    renderer_->setShadowReuse(true);

    quality.shadowMapSize = 1024;
    renderer_->setQuality(quality);
    EXPECT_EQ(frame(there).shadowMapsDrawn, 1u) << "another size";
    EXPECT_EQ(frame(there).shadowMapsKept, 1u);
}

TEST_F(LookTest, ALitFlatFaceHasNoShadowAcne) {
    const poly::Mesh block = slottedBlock();
    ASSERT_FALSE(block.empty());
    renderer_->upload(1, 1, block);
    // The sun low at 35 degrees, facing the block's +x side squarely.
    const glm::vec3 sun(1.0f, 0.7f, 0.0f);
    const View view = makeView({3.0f, 1.0f, 1.5f}, {0.5f, 0.3f, 0}, sun);
    const glm::mat4 model = at({0, 0.3f, 0});
    const glm::ivec2 face = worldToPixel(view, {0.5f, 0.3f, 0.0f});

    RenderQuality quality;
    quality.ambientOcclusion = false;
    quality.shadows = false;
    render(view, quality, true, model, kMatteWhite);
    const double open = meanSum(face, 6);
    quality.shadows = true;
    render(view, quality, true, model, kMatteWhite);
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int y = face.y - 6; y <= face.y + 6; ++y)
        for (int x = face.x - 6; x <= face.x + 6; ++x) {
            const double s = pixel(x, y).sum();
            sum += s;
            sum2 += s * s;
            ++n;
        }
    const double mean = sum / n, variance = sum2 / n - mean * mean;
    EXPECT_NEAR(mean, open, 4) << "the lit face does not shadow itself";
    EXPECT_LT(variance, 4.0) << "no acne: a flat lit patch is even";
}

TEST_F(LookTest, AmbientOcclusionDarkensACarvedGrooveAndNotTheOpenTop) {
    const poly::Mesh block = slottedBlock();
    ASSERT_FALSE(block.empty());
    renderer_->upload(1, 1, block);
    // Sun straight above: the groove's floor and the top get the same direct light.
    const View view = makeView({0.0f, 1.9f, 1.5f}, {0, 0.45f, 0}, {0.0f, 1.0f, 0.0f});
    const glm::mat4 model = at({0, 0.3f, 0});
    const glm::ivec2 groove = worldToPixel(view, {0.0f, 0.45f, 0.1f});
    const glm::ivec2 top = worldToPixel(view, {0.3f, 0.6f, 0.1f});

    RenderQuality quality;
    quality.shadows = false;
    quality.ambientOcclusion = false;
    render(view, quality, false, model, kMatteWhite);
    const double grooveOpen = meanSum(groove, 1), topOpen = meanSum(top, 1);

    EXPECT_NEAR(grooveOpen, topOpen, 6) << "without occlusion the floor of the groove is lit like the top";

    quality.ambientOcclusion = true;
    render(view, quality, false, model, kMatteWhite);
    const double grooveShut = meanSum(groove, 1), topShut = meanSum(top, 1);

    EXPECT_LT(grooveShut, grooveOpen - 30) << "the groove reads darker";
    EXPECT_NEAR(topShut, topOpen, 8) << "an open flat top is not darkened";

    quality.aoHalfResolution = true;
    render(view, quality, false, model, kMatteWhite);
    EXPECT_LT(meanSum(groove, 1), grooveOpen - 30) << "at half resolution too";
}

// Occlusion at half resolution is brought to the scene's pixels by depth:
// a pixel takes the occlusion of texels at its own depth, so the darkness
// of a hollow does not bleed across a silhouette onto the nearer or farther
// surface beside it. Near every depth step of the picture (the slot's
// edges, the block against the lawn) the half-resolution picture stays
// close to the full-resolution one.
TEST_F(LookTest, HalfResolutionOcclusionKeepsToItsSideOfEachSilhouette) {
    const poly::Mesh block = slottedBlock();
    ASSERT_FALSE(block.empty());
    renderer_->upload(1, 1, block);
    const View view = makeView({0.0f, 1.7f, 1.6f}, {0, 0.45f, 0}, {0.0f, 1.0f, 0.0f});
    const glm::mat4 model = at({0, 0.3f, 0});
    RenderQuality quality;
    quality.shadows = false;
    quality.msaaSamples = 1;
    quality.aoSamples = 16;
    render(view, quality, true, model, kMatteWhite);
    const std::vector<std::uint8_t> full = color_;
    const std::vector<float> depths = depth_;
    quality.aoHalfResolution = true;
    render(view, quality, true, model, kMatteWhite);
    const std::vector<std::uint8_t> half = color_;

    // Pixels beside a depth step: a neighbour more than 5 cm nearer or farther.
    int edges = 0, off = 0;
    double offSum = 0.0;
    for (int y = 1; y + 1 < kHeight; ++y)
        for (int x = 1; x + 1 < kWidth; ++x) {
            const double z = eyeDepth(depths[static_cast<std::size_t>(y * kWidth + x)]);
            if (z > 50.0) continue;  // sky
            bool step = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    step = step || std::abs(eyeDepth(depths[static_cast<std::size_t>((y + dy) * kWidth + x + dx)]) - z) > 0.05;
            if (!step) continue;
            ++edges;
            const std::size_t i = static_cast<std::size_t>(y * kWidth + x) * 4;
            const int d = std::abs(int(full[i]) - int(half[i])) + std::abs(int(full[i + 1]) - int(half[i + 1])) +
                          std::abs(int(full[i + 2]) - int(half[i + 2]));
            offSum += d;
            off += d > 30 ? 1 : 0;
        }
    ASSERT_GT(edges, 300) << "the picture has silhouettes to look at";
    // Stretched bilinearly instead, 90 of 2,176 such pixels were off by more
    // than 30 and the mean difference was 7.7; by depth, 2 and 3.9.
    EXPECT_LT(off, edges / 70) << "pixels beside a silhouette darkened or lightened by the other side's occlusion";
    EXPECT_LT(offSum / edges, 5.5);
}

// The clay view's cavity shading: the floor of a round-bottomed groove 8 cm
// in radius reads darker with it than without, the flat top beside it the
// same, and a small ball (a ridge all round) lighter. No occlusion or
// shadows here: the curvature alone.
TEST_F(LookTest, CavityShadingDarkensAGrooveAndLightensARidge) {
    const poly::Mesh block = groovedBlock(0.08);
    ASSERT_FALSE(block.empty());
    renderer_->upload(1, 1, block);
    const View view = makeView({0.0f, 1.9f, 1.5f}, {0, 0.45f, 0}, {0.0f, 1.0f, 0.0f});
    const glm::mat4 model = at({0, 0.3f, 0});
    const glm::ivec2 groove = worldToPixel(view, {0.0f, 0.3f + 0.3f - 0.08f, 0.1f});
    const glm::ivec2 top = worldToPixel(view, {0.3f, 0.6f, 0.1f});
    RenderMaterial flat = clayViewMaterial();
    flat.cavity = 0.0f;
    render(view, plain(), false, model, flat);
    const double grooveFlat = meanSum(groove, 1), topFlat = meanSum(top, 1);
    render(view, plain(), false, model, clayViewMaterial());
    EXPECT_LT(meanSum(groove, 1), grooveFlat - 40) << "the groove reads darker";
    EXPECT_NEAR(meanSum(top, 1), topFlat, 6) << "a flat top is left as it is";

    renderer_->upload(2, 1, uvSphereMesh(0.15f, 48, 24));
    const View ballView = makeView({0, 0, 5}, {0, 0, 0});
    const glm::ivec2 centre = worldToPixel(ballView, {0, 0, 0});
    render(ballView, plain(), false, glm::mat4(1.0f), flat, 2);
    const double ballFlat = meanSum(centre, 1);
    render(ballView, plain(), false, glm::mat4(1.0f), clayViewMaterial(), 2);
    EXPECT_GT(meanSum(centre, 1), ballFlat + 15) << "a ridge reads lighter";
}

TEST_F(LookTest, TheSkyDeepensOverheadAndShowsTheSun) {
    const glm::vec3 sun(0.0f, 0.35f, -1.0f);  // low, ahead
    View view = makeView({0, 1, 0}, {0, 1.4f, -5}, sun);
    renderer_->setQuality(plain());
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->endFrame();
    read();
    const glm::ivec2 sunPx = worldToPixel(view, view.eye + 50.0f * glm::normalize(sun));
    EXPECT_GT(pixel(sunPx.x, sunPx.y).sum(), 740) << "the sun's disc is white";
    EXPECT_LT(pixel(10, sunPx.y).sum(), 600) << "the sky away from it is not";

    view.lights.clear();  // no sun: the gradient alone
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->endFrame();
    read();
    const glm::ivec2 horizonPx = worldToPixel(view, view.eye + glm::vec3(-30.0f, 0.0f, -50.0f));
    const Rgba horizon = pixel(horizonPx.x, horizonPx.y), top = pixel(kWidth / 2, 0);
    EXPECT_NEAR(horizon.r, 51, 8) << "the clear colour at the horizon";
    EXPECT_NEAR(horizon.b, 204, 8);
    EXPECT_LT(top.r + top.g, horizon.r + horizon.g) << "deeper blue overhead";
    EXPECT_EQ(depth(kWidth / 2, 0), 1.0f) << "the sky is behind everything";
}

TEST_F(LookTest, TheLawnVariesInWorldSpace) {
    const glm::vec3 spot(0.37f, 0.0f, 0.41f);  // inside a grid cell
    GroundStyle lawn;
    lawn.lineWidth = 0.0f;
    renderer_->setQuality(plain());
    auto look = [&](const glm::vec3& eye) {
        const View view = makeView(eye, spot);
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawGround(lawn);
        renderer_->endFrame();
        read();
        return view;
    };
    View v = look({0.37f, 1.5f, 2.4f});
    glm::ivec2 p = worldToPixel(v, spot);
    const Rgba first = pixel(p.x, p.y);
    double sum = 0, sum2 = 0;
    for (int x = 0; x < kWidth; ++x) {
        const double s = pixel(x, kHeight - 20).sum();
        sum += s;
        sum2 += s * s;
    }
    const double mean = sum / kWidth;
    EXPECT_GT(std::sqrt(sum2 / kWidth - mean * mean), 3.0) << "not one flat colour";
    v = look({-1.2f, 1.1f, 1.9f});
    p = worldToPixel(v, spot);
    const Rgba second = pixel(p.x, p.y);
    EXPECT_NEAR(first.g, second.g, 6) << "the same patch of lawn from elsewhere";
    EXPECT_GT(first.g, first.r) << "green";
}

// The scene drawn at half the size is stretched bilinearly: the sphere's
// hard silhouette (no multisampling) becomes a ramp over the stretched
// pixels, where nearest sampling would repeat each scene pixel twice and
// keep the full step between sky and sphere; lines drawn over it stay as
// thin as at full size.
TEST_F(LookTest, ARenderScaleIsStretchedSmoothlyAndLinesStaySharp) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 96, 48));
    const View view = makeView({0, 0, 5}, {0, 0, 0});
    const glm::vec4 lineColor(1.0f, 1.0f, 0.0f, 1.0f);
    const float lineY = 1.6f;  // above the sphere, across the sky
    auto draw = [&](const RenderQuality& q) {
        renderer_->setQuality(q);
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawChunk(1, glm::mat4(1.0f), kRed);
        renderer_->drawLines({{-3.0f, lineY, 0.0f}, {3.0f, lineY, 0.0f}}, lineColor, LineMode::Segments);
        renderer_->endFrame();
        read();
    };
    // Over the rows through the sphere: the largest step in r + g + b
    // between neighbouring pixels of a row, averaged; and the pairs of
    // pixels (2k, 2k + 1) that differ.
    const int top = worldToPixel(view, {0, 0.8f, 0}).y, bottom = worldToPixel(view, {0, -0.8f, 0}).y;
    auto edgeStep = [&] {
        double sum = 0.0;
        for (int y = std::min(top, bottom); y <= std::max(top, bottom); ++y) {
            int largest = 0;
            for (int x = 0; x + 1 < kWidth; ++x) largest = std::max(largest, std::abs(pixel(x, y).sum() - pixel(x + 1, y).sum()));
            sum += largest;
        }
        return sum / (std::abs(top - bottom) + 1);
    };
    auto pairsDiffer = [&] {
        int n = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x + 1 < kWidth; x += 2) n += pixel(x, y).sum() != pixel(x + 1, y).sum() ? 1 : 0;
        return n;
    };
    const int lineColumn = worldToPixel(view, {0.0f, lineY, 0.0f}).x;
    auto lineThickness = [&] {
        int n = 0;
        for (int y = 0; y < kHeight; ++y) {
            const Rgba p = pixel(lineColumn, y);
            n += p.r > 200 && p.g > 200 && p.b < 80 ? 1 : 0;
        }
        return n;
    };
    RenderQuality q = plainQuality();
    draw(q);
    const int full = count(reddish);
    const double fullStep = edgeStep();
    const int fullLine = lineThickness();
    ASSERT_GT(fullStep, 100.0) << "a hard silhouette against the sky";
    ASSERT_GT(fullLine, 0);
    q.renderScale = 0.5f;
    draw(q);
    EXPECT_NEAR(count(reddish), full, 0.05 * full) << "the same disc, drawn at half the resolution";
    EXPECT_LT(edgeStep(), 0.7 * fullStep) << "the silhouette is a ramp (nearest sampling keeps the whole step)";
    EXPECT_GT(pairsDiffer(), 100) << "stretched pixels are not doubled";
    EXPECT_EQ(lineThickness(), fullLine) << "lines are drawn at the output's size";
    // Switched off: each scene pixel doubled, the whole step kept.
    q.smoothUpscale = false;
    draw(q);
    EXPECT_EQ(pairsDiffer(), 0);
    EXPECT_GT(edgeStep(), 0.9 * fullStep);
}

// The stretch is bilinear between the scene's resolved pixels, in display
// space (sRGB-encoded, as a reconstruction filter: docs/rendering.md,
// "Quality"): with nearest sampling each scene pixel is the output's 2 x 2
// block, so the smooth picture can be worked out from the nearest one and
// compared pixel by pixel. The same blend in linear light, as the stretch
// once was, is worked out beside it and must be told apart: tens of levels
// on the silhouette.
TEST_F(LookTest, TheStretchIsBilinearBetweenTheScenesPixelsInDisplaySpace) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 96, 48));
    const View view = makeView({0, 0, 4}, {0.3f, 0.2f, 0});
    auto draw = [&](bool smooth) {
        RenderQuality q = plainQuality();
        q.renderScale = 0.5f;
        q.smoothUpscale = smooth;
        renderer_->setQuality(q);
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawGround(GroundStyle{});
        renderer_->drawChunk(1, glm::mat4(1.0f), kRed);
        renderer_->endFrame();
        read();
        return color_;
    };
    const std::vector<std::uint8_t> nearest = draw(false), smooth = draw(true);
    const int sceneWidth = kWidth / 2, sceneHeight = kHeight / 2;
    const auto toLinear = [](double v) {
        const double c = v / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    const auto toSrgb = [](double c) {
        c = std::clamp(c, 0.0, 1.0);
        return 255.0 * (c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055);
    };
    const auto scene = [&](int i, int j, int c) {
        i = std::clamp(i, 0, sceneWidth - 1);
        j = std::clamp(j, 0, sceneHeight - 1);
        return static_cast<double>(
            nearest[(static_cast<std::size_t>(2 * j) * kWidth + static_cast<std::size_t>(2 * i)) * 4 + c]);
    };
    int worst = 0, ramps = 0, apartFromLinear = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            // Output pixel centre in scene pixels, less half a pixel.
            const double tx = (x + 0.5) * 0.5 - 0.5, ty = (y + 0.5) * 0.5 - 0.5;
            const int i = static_cast<int>(std::floor(tx)), j = static_cast<int>(std::floor(ty));
            const double fx = tx - i, fy = ty - j;
            const double w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
            for (int c = 0; c < 3; ++c) {
                const double a = scene(i, j, c), b = scene(i + 1, j, c), d = scene(i, j + 1, c),
                             e = scene(i + 1, j + 1, c);
                const double display = w00 * a + w10 * b + w01 * d + w11 * e;
                const double linear =
                    toSrgb(w00 * toLinear(a) + w10 * toLinear(b) + w01 * toLinear(d) + w11 * toLinear(e));
                const int got = smooth[(static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 4 + c];
                worst = std::max(worst, static_cast<int>(std::lround(std::abs(display - got))));
                apartFromLinear += std::abs(display - linear) > 8.0 && std::abs(linear - got) > 6.0 ? 1 : 0;
                const int near = nearest[(static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 4 + c];
                ramps += c == 0 && std::abs(got - near) > 20 ? 1 : 0;
            }
        }
    EXPECT_LE(worst, 2) << "levels from the bilinear blend of the scene's encoded pixels";
    EXPECT_GT(ramps, 100) << "the silhouette's pixels differ from the nearest stretch";
    EXPECT_GT(apartFromLinear, 100) << "pixels where a blend in linear light would have shown otherwise";
}

TEST(RenderQualityTest, PresetsSwitchTheEffectsAndParseByName) {
    EXPECT_EQ(parseQualityPreset("low"), QualityPreset::Low);
    EXPECT_EQ(parseQualityPreset("medium"), QualityPreset::Medium);
    EXPECT_EQ(parseQualityPreset("high"), QualityPreset::High);
    EXPECT_FALSE(parseQualityPreset("ultra").has_value());
    const RenderQuality low = qualityOf(QualityPreset::Low), medium = qualityOf(QualityPreset::Medium),
                        high = qualityOf(QualityPreset::High);
    EXPECT_EQ(low.msaaSamples, 1);
    EXPECT_FALSE(low.shadows || low.ambientOcclusion);
    EXPECT_LT(medium.shadowMapSize, high.shadowMapSize);
    EXPECT_LT(medium.aoSamples, high.aoSamples);
    // Both at half resolution, brought up by depth (full resolution costs
    // five times as much on a GPU for a picture within a level a pixel).
    EXPECT_TRUE(medium.aoHalfResolution && high.aoHalfResolution);
    EXPECT_LT(medium.msaaSamples, high.msaaSamples);
    // --quality auto: low on Mesa's software rasterizers, high on a GPU.
    EXPECT_EQ(rendererPreset("4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)"), QualityPreset::Low);
    EXPECT_EQ(rendererPreset("4.6.0 NVIDIA 550.54.15, NVIDIA H100 80GB HBM3/PCIe/SSE2"), QualityPreset::High);
}

TEST_F(LookTest, EachPassReportsItsGpuTime) {
    renderer_->setShadowReuse(false);  // the same view each frame: the map drawn each time, and timed
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    const View view = makeView({0, 2, 5}, {0, 0.5f, 0});
    RenderStats stats;
    // Results come a few views late, without waiting for the GPU.
    for (int frame = 0; frame < 8 && !(stats.gpuSceneMs >= 0.0f && stats.gpuShadowMs >= 0.0f); ++frame) {
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawGround(GroundStyle{});
        renderer_->drawChunk(1, at({0, 1, 0}), kRed);
        stats = renderer_->endFrame();
        glFinish();
    }
    EXPECT_GE(stats.gpuShadowMs, 0.0f);
    EXPECT_GT(stats.gpuSceneMs, 0.0f);
    EXPECT_GE(stats.gpuOcclusionMs, 0.0f);
    EXPECT_GE(stats.gpuPostMs, 0.0f);
    EXPECT_GE(stats.gpuMs(), stats.gpuSceneMs);
    EXPECT_EQ(stats.shadowDrawCalls, 1u) << "the sphere is drawn into the shadow map, the ground is not";
}

}  // namespace
}  // namespace hg::garden::test
