// The renderer in a real GL 3.3 core context: what lands in the image and
// the depth buffer compared with the scene's geometry (projected disc areas,
// ray hits on the ground), depth testing and culling, shading by material
// and light, the chunk buffers' upload accounting, and screenshots.
#include <gtest/gtest.h>

#include <stb/stb_image.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "frep/language/diagnostics.h"
#include "frep/eval/model.h"
#include "frep/language/parser.h"
#include "garden/render/screenshot.h"
#include "garden/render/shapes.h"
#include "gl_fixture.h"
#include "polygonizer/export/export_mesher.h"
#include "polygonizer/export/mesh_validation.h"
#include "voxel/sampler.h"

namespace hg::garden::test {
namespace {

const RenderMaterial kRed{{0.9f, 0.1f, 0.1f}, 0.2f, 32.0f};
const RenderMaterial kGreen{{0.1f, 0.8f, 0.15f}, 0.2f, 32.0f};

poly::Mesh flipped(poly::Mesh mesh) {
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    for (float& n : mesh.normals) n = -n;
    return mesh;
}

glm::mat4 at(const glm::vec3& p, float scale = 1.0f) {
    return glm::scale(glm::translate(glm::mat4(1.0f), p), glm::vec3(scale));
}

// The polygonizer's own mesh of a voxelized sphere of radius sqrt(a[1]).
poly::Mesh voxelizedSphere(double radius, int resolution) {
    const std::string source = "sphere(x[3], a[1]) { sphere = a[1] - (x[1]^2 + x[2]^2 + x[3]^2); }";
    frep::ParseResult r = frep::parseProgram(source, "sphere.hf");
    if (!r.ok()) {
        ADD_FAILURE() << (r.errors.empty() ? "parse failed" : frep::formatDiagnostic(r.errors[0]));
        return {};
    }
    auto program = std::make_shared<const frep::Program>(std::move(*r.program));
    frep::Model model(program, program->defaultBody(), {radius * radius});
    voxel::VolumeRequest request;
    request.resolution = resolution;
    voxel::VoxelizeResult v = voxel::voxelize(model, request);
    if (!v.volume) {
        ADD_FAILURE() << v.error;
        return {};
    }
    return poly::meshVolume(*v.volume);
}

TEST(Shapes, UvSphereIsOutwardFacingAndClosed) {
    const poly::Mesh sphere = uvSphereMesh(1.0f, 32, 16);
    EXPECT_EQ(sphere.triangleCount(), 2u * 32u * 15u);
    poly::Mesh welded = poly::weldByPosition(sphere);
    poly::MeshReport report = poly::validateMesh(welded);
    EXPECT_TRUE(report.closed());
    EXPECT_TRUE(report.outwardFacing());
    EXPECT_NEAR(report.volume, 4.0 / 3.0 * kPi, 0.05 * 4.0 / 3.0 * kPi);
}

TEST_F(GlTest, ContextIsGl33CoreOrNewer) {
    EXPECT_GE(epoxy_gl_version(), 33);
    GLint mask = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    EXPECT_TRUE(mask & GL_CONTEXT_CORE_PROFILE_BIT) << GlWindow::glVersionString();
    EXPECT_EQ(window_->framebufferSize(), glm::ivec2(kWidth, kHeight));
}

TEST_F(GlTest, SphereCoversItsAnalyticDisc) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 96, 48));
    const View view = makeView({0, 0, 5}, {0, 0, 0});
    target_->bind();
    renderer_->beginFrame(view);
    ASSERT_TRUE(renderer_->drawChunk(1, glm::mat4(1.0f), kRed));
    const RenderStats stats = renderer_->endFrame();
    read();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

    const double expected = kPi * std::pow(discRadiusPixels(1.0, 5.0), 2);
    const int red = count(reddish);
    EXPECT_NEAR(red, expected, 0.02 * expected);
    int covered = 0;
    for (float d : depth_) covered += d < 1.0f ? 1 : 0;
    EXPECT_NEAR(covered, expected, 0.02 * expected);
    EXPECT_EQ(stats.drawCalls, 1u);
    EXPECT_EQ(stats.trianglesDrawn, 2u * 96u * 47u);

    // The disc is centred: the centre pixel is sphere, the corners sky.
    EXPECT_TRUE(reddish(pixel(kWidth / 2, kHeight / 2)));
    EXPECT_EQ(depth(0, 0), 1.0f);
    // The centre pixel's depth is the front of the sphere, 4 units away.
    EXPECT_NEAR(eyeDepth(depth(kWidth / 2, kHeight / 2)), 4.0, 0.01);
}

TEST_F(GlTest, ModelMatrixMovesAndScalesTheChunk) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 96, 48));
    // Radius 2 centred 2 units further away: a disc of radius 2 at distance 7.
    const View view = makeView({0, 0, 5}, {0, 0, 0});
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->drawChunk(1, at({0, 0, -2}, 2.0f), kRed);
    renderer_->endFrame();
    read();
    const double expected = kPi * std::pow(discRadiusPixels(2.0, 7.0), 2);
    EXPECT_NEAR(count(reddish), expected, 0.02 * expected);
    EXPECT_NEAR(eyeDepth(depth(kWidth / 2, kHeight / 2)), 5.0, 0.01);
}

TEST_F(GlTest, PolygonizedSphereCoversItsAnalyticDisc) {
    const poly::Mesh mesh = voxelizedSphere(0.8, 64);
    ASSERT_FALSE(mesh.empty());
    renderer_->upload(7, 1, mesh);
    const View view = makeView({0, 0, 4}, {0, 0, 0});
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->drawChunk(7, glm::mat4(1.0f), kRed);
    renderer_->endFrame();
    read();
    const double expected = kPi * std::pow(discRadiusPixels(0.8, 4.0), 2);
    EXPECT_NEAR(count(reddish), expected, 0.03 * expected);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlTest, DepthMatchesRayHitsOnSphereAndGround) {
    // A unit sphere resting on the ground, seen from above and in front.
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 96, 48));
    const glm::vec3 center(0, 1, 0);
    const View view = makeView({0, 3, 7}, {0, 0.5f, 0});
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->drawGround(GroundStyle{});
    renderer_->drawChunk(1, at(center), kRed);
    renderer_->endFrame();
    read();

    const glm::vec3 forward = glm::normalize(glm::vec3(0, 0.5f, 0) - view.eye);
    // Eye depth of the ground seen through pixel (x, y); < 0 for none.
    auto groundDepth = [&](int x, int y) {
        const glm::vec3 dir = rayDirection(view, x, y);
        if (dir.y >= 0.0f) return -1.0;
        const float t = -view.eye.y / dir.y;
        const glm::vec3 hit = view.eye + t * dir;
        if (std::fabs(hit.x) > 90.0f || std::fabs(hit.z) > 90.0f) return -1.0;
        return double(glm::dot(t * dir, forward));
    };
    int sphereChecked = 0, groundChecked = 0;
    for (int y = 4; y < kHeight - 1; y += 9) {
        for (int x = 4; x < kWidth; x += 9) {
            const glm::vec3 dir = rayDirection(view, x, y);
            const double measured = eyeDepth(depth(x, y));
            // The sphere's nearest root, else the ground plane y = 0.
            const glm::vec3 oc = view.eye - center;
            const float b = glm::dot(oc, dir), c = glm::dot(oc, oc) - 1.0f;
            const float disc = b * b - c;
            if (disc > 0.05f) {  // well inside the outline: facets cannot move the edge past it
                // Facets of the UV sphere sit inside the true sphere by up
                // to 1 - cos(pi / 48) of its radius.
                const double expected = double(glm::dot((-b - std::sqrt(disc)) * dir, forward));
                EXPECT_NEAR(measured, expected, 0.01 * expected) << x << "," << y;
                EXPECT_TRUE(reddish(pixel(x, y))) << x << "," << y;
                ++sphereChecked;
            } else if (disc < -0.05f && groundDepth(x, y) > 0.0 && groundDepth(x, y - 1) > 0.0) {
                // The ground is pushed back by about its depth across one
                // pixel (polygon offset), so lines on it stay in front.
                const double expected = groundDepth(x, y);
                const double pixelSpan = groundDepth(x, y - 1) - expected;
                EXPECT_GE(measured, expected - 0.01 * expected) << x << "," << y;
                EXPECT_LE(measured, expected + 1.5 * pixelSpan + 0.01 * expected) << x << "," << y;
                ++groundChecked;
            }
        }
    }
    EXPECT_GT(sphereChecked, 50);
    EXPECT_GT(groundChecked, 200);
    // The sphere's centre pixel is nearer than the ground seen beside it,
    // and the sky above the horizon has no depth.
    const float sphereDepth = depth(kWidth / 2, kHeight / 2);
    const float besideDepth = depth(kWidth / 8, kHeight / 2 + 20);
    EXPECT_LT(sphereDepth, besideDepth);
    EXPECT_EQ(depth(kWidth / 2, 0), 1.0f);
}

TEST_F(GlTest, GroundGridLinesLieOnTheGridAndTheGroundBelowTheHorizon) {
    const View view = makeView({0.37f, 2.0f, 6.0f}, {0.37f, 0.0f, 0.0f});
    GroundStyle ground;
    ground.color = {0.7f, 0.7f, 0.7f};
    ground.lineColor = {0.1f, 0.1f, 0.1f};
    ground.spacing = 1.0f;
    ground.majorEvery = 0;
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->drawGround(ground);
    renderer_->endFrame();
    read();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

    // Classify pixels by where their ray meets the ground: on a line of
    // constant x (closer than a fifth of a pixel's footprint), or in the
    // middle of a cell.
    double onSum = 0, midSum = 0;
    int on = 0, mid = 0;
    for (int y = kHeight / 2 + 10; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec3 dir = rayDirection(view, x, y);
            if (dir.y >= 0.0f) continue;
            const glm::vec3 hit = view.eye + (-view.eye.y / dir.y) * dir;
            const glm::vec3 next = view.eye + (-view.eye.y / rayDirection(view, x + 1, y).y) * rayDirection(view, x + 1, y);
            const float footprint = std::fabs(next.x - hit.x);
            const float dx = std::fabs(hit.x - std::round(hit.x));
            const float dz = std::fabs(hit.z - std::round(hit.z));
            if (dx < 0.2f * footprint && dz > 0.2f) {
                onSum += pixel(x, y).sum();
                ++on;
            } else if (dx > 0.3f && dz > 0.3f) {
                midSum += pixel(x, y).sum();
                ++mid;
            }
        }
    }
    ASSERT_GT(on, 20);
    ASSERT_GT(mid, 1000);
    EXPECT_LT(onSum / on, 0.6 * (midSum / mid)) << "grid lines are darker than the cells, where the grid says";
    // Sky above the horizon, ground below.
    EXPECT_EQ(depth(kWidth / 2, 2), 1.0f);
    EXPECT_LT(depth(kWidth / 2, kHeight - 2), 1.0f);
}

TEST_F(GlTest, NearerSphereHidesTheOneBehindItInEitherDrawOrder) {
    const poly::Mesh sphere = uvSphereMesh(1.0f, 48, 24);
    renderer_->upload(1, 1, sphere);
    const View view = makeView({0, 0, 8}, {0, 0, 0});
    for (bool backFirst : {false, true}) {
        target_->bind();
        renderer_->beginFrame(view);
        if (backFirst) renderer_->drawChunk(1, at({0, 0, -3}, 0.5f), kGreen);
        renderer_->drawChunk(1, at({0, 0, 0}), kRed);
        if (!backFirst) renderer_->drawChunk(1, at({0, 0, -3}, 0.5f), kGreen);
        renderer_->endFrame();
        read();
        EXPECT_EQ(count(greenish), 0) << "back sphere drawn " << (backFirst ? "first" : "last");
        EXPECT_GT(count(reddish), 1000);
    }
    // Moved aside, the back sphere shows.
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->drawChunk(1, at({0, 0, 0}), kRed);
    renderer_->drawChunk(1, at({2.0f, 0, -3}, 0.5f), kGreen);
    renderer_->endFrame();
    read();
    EXPECT_GT(count(greenish), 100);
}

TEST_F(GlTest, BackFacesAreCulled) {
    // A square facing +z, and the same square wound the other way.
    poly::Mesh square;
    square.positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    square.indices = {0, 1, 2, 0, 2, 3};
    poly::Mesh away = flipped(square);
    renderer_->upload(1, 1, square);
    renderer_->upload(2, 1, away);
    for (ChunkId id : {ChunkId{1}, ChunkId{2}}) {
        target_->bind();
        renderer_->beginFrame(makeView({0, 0, 5}, {0, 0, 0}, {0, 0, 1}));
        renderer_->drawChunk(id, glm::mat4(1.0f), kRed);
        renderer_->endFrame();
        read();
        if (id == 1)
            EXPECT_GT(count(reddish), 5000) << "facing the camera";
        else
            EXPECT_EQ(count(reddish), 0) << "facing away";
    }

    // A closed sphere turned inside out shows only its far half: the
    // centre pixel's depth is the back of the sphere, 6 units away.
    const poly::Mesh sphere = uvSphereMesh(1.0f, 48, 24);
    renderer_->upload(3, 1, sphere);
    renderer_->upload(4, 1, flipped(sphere));
    target_->bind();
    renderer_->beginFrame(makeView({0, 0, 5}, {0, 0, 0}));
    renderer_->drawChunk(4, glm::mat4(1.0f), kRed);
    renderer_->endFrame();
    read();
    EXPECT_NEAR(eyeDepth(depth(kWidth / 2, kHeight / 2)), 6.0, 0.01);
    // From inside the sphere every face is a back face.
    target_->bind();
    renderer_->beginFrame(makeView({0, 0, 0.2f}, {0, 0, -1}));
    renderer_->drawChunk(3, glm::mat4(1.0f), kRed);
    renderer_->endFrame();
    read();
    EXPECT_EQ(count(reddish), 0);
    int drawn = 0;
    for (float d : depth_) drawn += d < 1.0f ? 1 : 0;
    EXPECT_EQ(drawn, 0);
}

TEST_F(GlTest, UploadsOnlyNewVersions) {
    const poly::Mesh sphere = uvSphereMesh(1.0f, 16, 8);
    const std::size_t bytes = (sphere.positions.size() + sphere.normals.size()) * sizeof(float) +
                              sphere.indices.size() * sizeof(std::uint32_t);
    EXPECT_FALSE(renderer_->has(5));
    EXPECT_EQ(renderer_->upload(5, 1, sphere), bytes);
    EXPECT_TRUE(renderer_->has(5, 1));
    EXPECT_EQ(renderer_->upload(5, 1, sphere), 0u) << "same version: nothing sent";
    EXPECT_EQ(renderer_->upload(5, 2, sphere), bytes) << "new version: sent again";
    EXPECT_FALSE(renderer_->has(5, 1));
    EXPECT_TRUE(renderer_->has(5, 2));
    EXPECT_EQ(renderer_->residentBytes(), bytes);
    EXPECT_EQ(renderer_->stats().bytesUploaded, 2 * bytes);
    EXPECT_EQ(renderer_->endFrame().bytesUploaded, 2 * bytes);
    EXPECT_EQ(renderer_->stats().bytesUploaded, 0u) << "endFrame starts the next frame's count";

    // Without normals: still drawn (face normals in the shader); the arena
    // keeps one vertex format, so the normals' room is taken (zeros).
    poly::Mesh bare = sphere;
    bare.normals.clear();
    EXPECT_EQ(renderer_->upload(6, 1, bare), bytes);
    EXPECT_EQ(renderer_->upload(8, 1, poly::Mesh{}), 0u);
    EXPECT_TRUE(renderer_->has(8, 1)) << "an empty chunk is current, with nothing to draw";
    EXPECT_EQ(renderer_->chunkCount(), 3u);

    target_->bind();
    renderer_->beginFrame(makeView({0, 0, 5}, {0, 0, 0}));
    EXPECT_TRUE(renderer_->drawChunk(6, glm::mat4(1.0f), kRed));
    EXPECT_TRUE(renderer_->drawChunk(8, glm::mat4(1.0f), kRed));
    EXPECT_FALSE(renderer_->drawChunk(99, glm::mat4(1.0f), kRed)) << "not resident";
    const RenderStats stats = renderer_->endFrame();
    read();
    EXPECT_EQ(stats.drawCalls, 1u);
    EXPECT_EQ(stats.trianglesDrawn, bare.triangleCount());
    EXPECT_GT(count(reddish), 5000);

    renderer_->drop(5);
    renderer_->drop(6);
    EXPECT_FALSE(renderer_->has(5));
    EXPECT_EQ(renderer_->residentBytes(), 0u);

    poly::Mesh broken = sphere;
    broken.indices.back() = static_cast<std::uint32_t>(sphere.vertexCount());
    EXPECT_THROW(renderer_->upload(9, 1, broken), std::invalid_argument);
    broken = sphere;
    broken.normals.pop_back();
    EXPECT_THROW(renderer_->upload(9, 1, broken), std::invalid_argument);
    EXPECT_FALSE(renderer_->has(9));
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlTest, MaterialsGiveTheirColours) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    const View view = makeView({0, 0, 5}, {0, 0, 0}, {0, 0, 1});
    Rgba centre[2];
    for (int m = 0; m < 2; ++m) {
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawChunk(1, glm::mat4(1.0f), m == 0 ? kRed : kGreen);
        renderer_->endFrame();
        read();
        centre[m] = pixel(kWidth / 2 + 20, kHeight / 2 + 20);  // off the highlight
    }
    EXPECT_TRUE(reddish(centre[0]));
    EXPECT_TRUE(greenish(centre[1]));
    // Lit head-on, a surface shows about its base colour: sRGB in, sRGB out.
    // (n.l is below 1 off centre, so a bit darker.)
    EXPECT_NEAR(centre[0].r, 0.9 * 255, 40);
    EXPECT_NEAR(centre[1].g, 0.8 * 255, 40);
}

TEST_F(GlTest, LitSideIsBrighterThanTheOther) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    const int r = static_cast<int>(discRadiusPixels(1.0, 5.0));
    int right[2], left[2];
    for (int side = 0; side < 2; ++side) {
        const View view = makeView({0, 0, 5}, {0, 0, 0}, {side == 0 ? 1.0f : -1.0f, 0.0f, 0.3f});
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawChunk(1, glm::mat4(1.0f), RenderMaterial{{0.8f, 0.8f, 0.8f}, 0.0f, 16.0f});
        renderer_->endFrame();
        read();
        right[side] = pixel(kWidth / 2 + r * 6 / 10, kHeight / 2).sum();
        left[side] = pixel(kWidth / 2 - r * 6 / 10, kHeight / 2).sum();
    }
    EXPECT_GT(right[0], left[0] + 150) << "light from +x";
    EXPECT_GT(left[1], right[1] + 150) << "light from -x";
    EXPECT_NEAR(right[0], left[1], 6) << "mirror images";

    // Two lights add up; the ambient term alone lights the dark side.
    View both = makeView({0, 0, 5}, {0, 0, 0}, {1, 0, 0.3f});
    both.lights.push_back(DirectionalLight{{-1, 0, 0.3f}, glm::vec3(1.0f)});
    target_->bind();
    renderer_->beginFrame(both);
    renderer_->drawChunk(1, glm::mat4(1.0f), RenderMaterial{{0.8f, 0.8f, 0.8f}, 0.0f, 16.0f});
    renderer_->endFrame();
    read();
    EXPECT_NEAR(pixel(kWidth / 2 - r * 6 / 10, kHeight / 2).sum(), left[1], 6);
    EXPECT_NEAR(pixel(kWidth / 2 + r * 6 / 10, kHeight / 2).sum(), right[0], 6);
    EXPECT_GT(left[0], 3 * 40) << "ambient";

    View tooMany = both;
    tooMany.lights.resize(kMaxLights + 1);
    EXPECT_THROW(renderer_->beginFrame(tooMany), std::invalid_argument);
}

TEST_F(GlTest, PointLightsFallWithDistanceAndStopAtTheirRange) {
    // A unit sphere at the origin seen from +z, lit only by a point light
    // on its right (+x) and a little ambient light.
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    const int r = static_cast<int>(discRadiusPixels(1.0, 5.0));
    auto render = [&](std::vector<PointLight> points) {
        View view = makeView({0, 0, 5}, {0, 0, 0});
        view.lights.clear();
        view.ambient = glm::vec3(0.05f);
        view.pointLights = std::move(points);
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawChunk(1, glm::mat4(1.0f), RenderMaterial{{0.8f, 0.8f, 0.8f}, 0.0f, 16.0f});
        renderer_->endFrame();
        read();
        return std::pair<int, int>{pixel(kWidth / 2 + r * 6 / 10, kHeight / 2).sum(),
                                   pixel(kWidth / 2 - r * 6 / 10, kHeight / 2).sum()};
    };
    const auto [darkRight, darkLeft] = render({});
    const auto [nearRight, nearLeft] = render({PointLight{{2.0f, 0.0f, 1.0f}, glm::vec3(4.0f), 10.0f}});
    const auto [farRight, farLeft] = render({PointLight{{4.0f, 0.0f, 2.0f}, glm::vec3(4.0f), 10.0f}});
    EXPECT_NEAR(darkRight, darkLeft, 3) << "ambient alone lights both sides alike";
    EXPECT_GT(nearRight, nearLeft + 150) << "the side facing the light is lit";
    EXPECT_NEAR(nearLeft, darkLeft, 3) << "the far side gets nothing";
    EXPECT_GT(nearRight, farRight + 60) << "the same light twice as far is dimmer";
    EXPECT_GT(farRight, darkRight + 30) << "but still lights";
    // The sphere's nearest point is 1.24 m from the light: a range of 1 m
    // reaches nothing, 1.5 m some of it.
    const auto [shortRight, shortLeft] = render({PointLight{{2.0f, 0.0f, 1.0f}, glm::vec3(4.0f), 1.0f}});
    EXPECT_NEAR(shortRight, darkRight, 3) << "beyond its range a light adds nothing";
    (void)shortLeft;

    // The ground under a lamp is brighter than the ground away from it.
    View lamp = makeView({0.0f, 2.0f, 6.0f}, {0.0f, 0.0f, 0.0f});
    lamp.lights.clear();
    lamp.ambient = glm::vec3(0.05f);
    lamp.pointLights = {PointLight{{-2.0f, 0.5f, 0.0f}, glm::vec3(2.0f), 3.0f}};
    GroundStyle ground;
    ground.color = {0.7f, 0.7f, 0.7f};
    ground.lineColor = ground.color;
    target_->bind();
    renderer_->beginFrame(lamp);
    renderer_->drawGround(ground);
    renderer_->endFrame();
    read();
    const glm::ivec2 under = worldToPixel(lamp, {-2.0f, 0.0f, 0.0f});
    const glm::ivec2 away = worldToPixel(lamp, {2.0f, 0.0f, 0.0f});
    EXPECT_GT(pixel(under.x, under.y).sum(), pixel(away.x, away.y).sum() + 100);

    View tooMany = lamp;
    tooMany.pointLights.resize(kMaxPointLights + 1);
    EXPECT_THROW(renderer_->beginFrame(tooMany), std::invalid_argument);
}

TEST_F(GlTest, NonUniformScaleKeepsNormalsPerpendicular) {
    // Squashed to half height, the sphere's top is flatter: lit from above
    // it stays bright across more of its width than the round one.
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 96, 48));
    int litRound = 0, litFlat = 0;
    for (int pass = 0; pass < 2; ++pass) {
        const View view = makeView({0, 6, 0.01f}, {0, 0, 0}, {0, 1, 0});
        const glm::mat4 model = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, pass == 0 ? 1.0f : 0.5f, 1.0f));
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawChunk(1, model, RenderMaterial{{0.8f, 0.8f, 0.8f}, 0.0f, 16.0f});
        renderer_->endFrame();
        read();
        // Pixels brighter than n.l = 0.9 would give.
        const int bright = count([](const Rgba& p) { return p.r > 215; });
        (pass == 0 ? litRound : litFlat) = bright;
    }
    EXPECT_GT(litFlat, litRound * 3 / 2);
}

TEST_F(GlTest, LinesOnTheGroundShowAndRespectDepth) {
    const View view = makeView({0, 3, 6}, {0, 0, 0});
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    const glm::vec4 yellow(1.0f, 1.0f, 0.0f, 1.0f);
    const std::vector<glm::vec3> triangle{{-2, 0, 1}, {2, 0, 1}, {0, 0, -2.5f}};
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->drawGround(GroundStyle{});
    renderer_->drawChunk(1, at({0, 1, 0}), kRed);
    renderer_->drawLines(triangle, yellow, LineMode::Loop);
    renderer_->endFrame();
    read();
    auto yellowish = [](const Rgba& p) { return p.r > 200 && p.g > 200 && p.b < 80; };
    auto yellowNear = [&](const glm::vec3& world) {
        const glm::vec3 w = glm::project(world, view.view, view.projection, glm::vec4(0, 0, kWidth, kHeight));
        const int x = int(w.x), y = kHeight - 1 - int(w.y);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (yellowish(pixel(std::clamp(x + dx, 0, kWidth - 1), std::clamp(y + dy, 0, kHeight - 1)))) return true;
        return false;
    };
    // The front edge lies on the ground in full view; the far corner is
    // behind the sphere.
    EXPECT_TRUE(yellowNear({0, 0, 1}));
    EXPECT_TRUE(yellowNear({-1, 0, 1}));
    EXPECT_FALSE(yellowNear({0, 0, -2.5f})) << "hidden by the sphere";
    EXPECT_GT(count(yellowish), 150);

    // Undepth-tested lines (gizmos) show through.
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->drawChunk(1, at({0, 1, 0}), kRed);
    renderer_->drawLines(triangle, yellow, LineMode::Loop, false);
    renderer_->endFrame();
    read();
    EXPECT_TRUE(yellowNear({0, 0, -2.5f}));
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlTest, DetailSphereWireframeOutlinesItAndSolidBlends) {
    const View view = makeView({0, 0, 5}, {0, 0, 0});
    const glm::vec4 white(1.0f, 1.0f, 1.0f, 1.0f);
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->drawSphere({0, 0, 0}, 1.0f, white, true);
    renderer_->endFrame();
    read();
    // The outline circle is at the projected disc's radius.
    const double r = discRadiusPixels(1.0, 5.0);
    int hits = 0;
    for (int k = 0; k < 16; ++k) {
        const double a = 2 * kPi * k / 16;
        bool found = false;
        for (double dr = -1.5; dr <= 1.5 && !found; dr += 0.5) {
            const int x = int(kWidth / 2 + (r + dr) * std::cos(a));
            const int y = int(kHeight / 2 - (r + dr) * std::sin(a));
            found = pixel(x, y).sum() > 700;
        }
        hits += found ? 1 : 0;
    }
    EXPECT_GE(hits, 15);
    EXPECT_LT(count([](const Rgba& p) { return p.sum() > 700; }), 4000) << "lines, not a filled disc";

    // Solid and translucent: the background shows through, tinted.
    target_->bind();
    renderer_->beginFrame(view);
    renderer_->drawSphere({0, 0, 0}, 1.0f, {1.0f, 1.0f, 0.0f, 0.5f}, false);
    renderer_->endFrame();
    read();
    const Rgba c = pixel(kWidth / 2, kHeight / 2);
    // Clear (51, 76, 204) half-way to yellow (255, 255, 0).
    EXPECT_NEAR(c.r, 153, 3);
    EXPECT_NEAR(c.g, 166, 3);
    EXPECT_NEAR(c.b, 102, 3);
    EXPECT_EQ(depth(kWidth / 2, kHeight / 2), 1.0f) << "a translucent shell writes no depth";
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlTest, ScreenshotPngReadsBackTheSamePixels) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    target_->bind();
    renderer_->beginFrame(makeView({0, 2, 5}, {0, 0.5f, 0}));
    renderer_->drawGround(GroundStyle{});
    renderer_->drawChunk(1, at({0, 1, 0}), kRed);
    renderer_->endFrame();
    read();

    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("hg_render_png_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "shot.png").string();
    ASSERT_EQ(writePng(path, kWidth, kHeight, color_), "");
    int w = 0, h = 0, channels = 0;
    stbi_uc* loaded = stbi_load(path.c_str(), &w, &h, &channels, 4);
    ASSERT_NE(loaded, nullptr) << stbi_failure_reason();
    EXPECT_EQ(w, kWidth);
    EXPECT_EQ(h, kHeight);
    EXPECT_TRUE(std::equal(color_.begin(), color_.end(), loaded));
    // Top-down: the sky is in the first row, the ground in the last.
    EXPECT_GT(int(loaded[2]), int(loaded[0]) + 80) << "the sky, blue overhead";
    EXPECT_NE(int(loaded[(kHeight - 1) * kWidth * 4 + 2]), 204);
    stbi_image_free(loaded);

    // The bound framebuffer as read for F12 is the same image.
    const std::string again = (dir / "again.png").string();
    ASSERT_EQ(writeFramebufferPng(again, kWidth, kHeight), "");
    loaded = stbi_load(again.c_str(), &w, &h, &channels, 4);
    ASSERT_NE(loaded, nullptr);
    EXPECT_TRUE(std::equal(color_.begin(), color_.end(), loaded));
    stbi_image_free(loaded);

    // Only the finished files: no temporaries left beside them.
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) files += entry.is_regular_file() ? 1 : 0;
    EXPECT_EQ(files, 2);

    const std::string missing = (dir / "no" / "such" / "dir.png").string();
    const std::string why = writePng(missing, kWidth, kHeight, color_);
    EXPECT_NE(why.find(missing), std::string::npos) << why;
    EXPECT_NE(why.find("No such file or directory"), std::string::npos) << why;
    EXPECT_NE(writePng(path, kWidth, kHeight - 1, color_), "") << "size mismatch";
    std::filesystem::remove_all(dir);
}

TEST_F(GlTest, OffscreenTargetRowsAreTopDown) {
    // Clear, then fill only the top half with a scissor: row 0 must be the
    // filled colour.
    target_->bind();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, kHeight / 2, kWidth, kHeight / 2);  // GL's y grows upwards
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    read();
    EXPECT_EQ(pixel(0, 0).r, 255);
    EXPECT_EQ(pixel(0, kHeight - 1).r, 0);
}

TEST(GlWindowTest, NoDisplayIsAClearError) {
    const char* saved = std::getenv("DISPLAY");
    const std::string keep = saved ? saved : "";
    ::unsetenv("DISPLAY");
    try {
        GlWindow window(WindowOptions{});
        ADD_FAILURE() << "a window without a display";
    } catch (const GlError& e) {
        EXPECT_NE(std::string(e.what()).find("xvfb-run -a"), std::string::npos) << e.what();
    }
    if (saved) ::setenv("DISPLAY", keep.c_str(), 1);
}

}  // namespace
}  // namespace hg::garden::test
