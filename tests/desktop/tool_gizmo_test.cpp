// Tool gizmos (garden/render/tool_gizmo.*): their geometry is the tool's
// live size and shape as the tool would place it, and drawn in the garden
// (real GL) they show in the tool's colour around the point the aim meets,
// as large as the tool.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include "../garden/session_garden.h"
#include "../render/gl_fixture.h"
#include "garden/app/garden_session.h"
#include "garden/app/sculpture_gizmos.h"
#include "garden/window/garden_view.h"
#include "garden/hands/desktop_hands.h"
#include "garden/render/tool_gizmo.h"

namespace hg::garden {
namespace {

using Kind = ToolSettings::Kind;

// Every point of every line list, whatever it is drawn as.
std::vector<glm::vec3> allPoints(const std::vector<GizmoLines>& lines) {
    std::vector<glm::vec3> p;
    for (const GizmoLines& l : lines) p.insert(p.end(), l.points.begin(), l.points.end());
    return p;
}

TEST(ToolGizmoGeometry, StrokeToolsAreSpheresOfTheRadiusInTheirColour) {
    ToolSettings t;
    const glm::vec3 at(1, 2, 3), eye(1, 2, 8), dir(0, 0, -1);
    t.kind = Kind::None;
    EXPECT_TRUE(toolGizmo(t, at, eye, dir, eye).empty());
    t.kind = Kind::Move;
    EXPECT_TRUE(toolGizmo(t, at, eye, dir, eye).empty()) << "the move gizmo is on the sculpture";
    for (const Kind k : {Kind::Carve, Kind::Add, Kind::Melt}) {
        t.kind = k;
        t.radius = 0.3;
        const auto lines = toolGizmo(t, at, eye, dir, eye);
        ASSERT_FALSE(lines.empty());
        for (const glm::vec3& p : allPoints(lines)) EXPECT_NEAR(glm::distance(p, at), 0.3f, 1e-5f);
        for (const GizmoLines& l : lines) {
            EXPECT_EQ(glm::vec3(l.color), glm::vec3(toolColor(t)));
            EXPECT_EQ(l.color.a < 1.0f, l.overEverything) << "the see-through part is faint";
        }
    }
    t.kind = Kind::Carve;
    const glm::vec4 carve = toolColor(t);
    t.reverse = true;
    EXPECT_EQ(toolColor(t), toolColor(ToolSettings{Kind::Add})) << "carve reversed adds, and looks it";
    EXPECT_NE(toolColor(t), carve);
}

TEST(ToolGizmoGeometry, PerturbationsAreTheirQuadricAtTheScaledRadii) {
    ToolSettings t;
    t.kind = Kind::Perturb;
    t.radii = {0.1, 0.2, 0.3};
    t.perturbScale = 2.0;
    const glm::vec3 at(1, 2, 3), eye(1, 2, 8), dir(0, 0, -1);
    const auto ellipsoid = allPoints(toolGizmo(t, at, eye, dir, eye));
    ASSERT_FALSE(ellipsoid.empty());
    glm::vec3 extent(0.0f);
    for (const glm::vec3& p : ellipsoid) {
        const glm::vec3 u = (p - at) / glm::vec3(0.2f, 0.4f, 0.6f);
        EXPECT_NEAR(glm::dot(u, u), 1.0f, 1e-4f) << "on the ellipsoid Q = 0";
        extent = glm::max(extent, glm::abs(p - at));
    }
    EXPECT_NEAR(extent.x, 0.2f, 1e-4f);
    EXPECT_NEAR(extent.y, 0.4f, 1e-4f);
    EXPECT_NEAR(extent.z, 0.6f, 1e-4f);
    // A torus of ring R and tube r about the z axis: every point on its
    // surface, Q = 1 - ((sqrt(x^2 + y^2) - R)^2 + z^2) / r^2 = 0.
    t.shape = QuadricShape::Torus;
    t.radii = {0.3, 0.1, 0.0};
    t.perturbScale = 1.0;
    const auto torus = allPoints(toolGizmo(t, at, eye, dir, eye));
    ASSERT_GT(torus.size(), 100u);
    for (const glm::vec3& p : torus) {
        const glm::vec3 d = p - at;
        const float ring = std::hypot(d.x, d.y) - 0.3f;
        EXPECT_NEAR(ring * ring + d.z * d.z, 0.01f, 1e-5f);
    }
}

TEST(ToolGizmoGeometry, ImpactsShowTheirSpreadAcrossTheAim) {
    ToolSettings t;
    t.kind = Kind::Impacts;
    t.spread = ImpactSpread::Uniform;
    t.spreadSize = 0.25;
    t.impactSize = 0.01;
    const glm::vec3 eye(0, 0, 5), at(0, 0, 1), dir(0, 0, -1);
    float widest = 0.0f;
    for (const glm::vec3& p : allPoints(toolGizmo(t, at, eye, dir, eye))) {
        widest = std::max(widest, glm::distance(p, at));
        if (glm::distance(p, at) > 0.02f) {
            EXPECT_NEAR(p.z, at.z, 1e-5f) << "the disc lies across the aim";
        }
    }
    EXPECT_NEAR(widest, 0.25f, 1e-4f);
    // A cone of 10 degrees seen from 4 m: its section where it meets the surface.
    t.spread = ImpactSpread::Cone;
    t.spreadSize = 10.0;
    widest = 0.0f;
    for (const glm::vec3& p : allPoints(toolGizmo(t, at, eye, dir, eye))) widest = std::max(widest, glm::distance(p, at));
    EXPECT_NEAR(widest, 4.0f * std::tan(10.0f * 3.14159265f / 180.0f), 1e-4f);
}

class ToolGizmoTest : public test::GlTest {
protected:
    void SetUp() override {
        test::GlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        scratch_ = std::filesystem::temp_directory_path() / ("hg_gizmo_" + std::to_string(::getpid()));
        SessionSettings settings;
        settings.chunkSize = 16;
        settings.maxLevel = 1;
        settings.viewportHeight = kHeight;
        settings.fovY = glm::radians(double(kFovY));
        // A grey lawn: the tool's green is the only green in the picture
        // (a green lawn's lighter stripes come near the test's threshold).
        const nlohmann::json greyLawn = {{"materials", {{"grey", {{"color", {0.5, 0.5, 0.5}}}}}},
                                         {"ground", {{"material", "grey"}}}};
        session_ = std::make_unique<GardenSession>(loadGarden(test::writeSmallGarden(scratch_, greyLawn)), settings);
        // 3 m in front of ball c (radius 0.6, centre (2, 0.5, 1.1547)), looking along -z.
        session_->navigator().setMode(NavigationMode::Fly);
        session_->navigator().setPose({2.0f, 0.5f, 4.1547f}, 0.0f, 0.0f);
        for (int f = 0; f < 500 && !session_->idle(); ++f) {
            session_->frame(FrameInput(Hands{}, 1.0 / 90.0));
        }
        ASSERT_TRUE(session_->idle());
        view_ = std::make_unique<GardenView>(*renderer_);
        view_->upload(*session_, 1e9);
        // The mouse at the image centre.
        const glm::mat4 projection = glm::perspective(glm::radians(kFovY), 1.0f, 0.05f, 500.0f);
        aim_ = rayThroughPixel({kWidth / 2.0f, kHeight / 2.0f}, {kWidth, kHeight}, session_->view(), projection);
    }
    void TearDown() override {
        view_.reset();
        session_.reset();
        std::filesystem::remove_all(scratch_);
        test::GlTest::TearDown();
    }
    void draw(const std::optional<Pose>& aim) {
        target_->bind();
        view_->render(*session_, {kWidth, kHeight}, glm::radians(kFovY));
        drawToolGizmos(*renderer_, *session_, aim);
        renderer_->endFrame();
        read();
    }
    // The farthest pixel from the image centre that `is` holds, and how many there are.
    std::pair<double, int> extent(const std::function<bool(const test::Rgba&)>& is) const {
        double far = 0.0;
        int n = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                if (is(pixel(x, y))) {
                    far = std::max(far, std::hypot(x + 0.5 - kWidth / 2.0, y + 0.5 - kHeight / 2.0));
                    ++n;
                }
        return {far, n};
    }
    std::filesystem::path scratch_;
    std::unique_ptr<GardenSession> session_;
    std::unique_ptr<GardenView> view_;
    Pose aim_;
};

TEST_F(ToolGizmoTest, TheToolShowsInItsColourAroundTheHitAsLargeAsItsRadius) {
    const auto hit = session_->toolHit(aim_);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->first, session_->findSculpture("c"));
    const double d = glm::distance(hit->second, session_->navigator().eye());
    EXPECT_NEAR(d, 2.4, 0.05);

    session_->tool().kind = Kind::None;
    draw(aim_);
    const std::vector<std::uint8_t> without = color_;
    EXPECT_EQ(extent(test::greenish).second, 0) << "nothing green in the garden without a tool";

    session_->tool().kind = Kind::Add;  // green, on the red ball
    session_->tool().radius = 0.1;
    draw(aim_);
    const auto [small, smallCount] = extent(test::greenish);
    EXPECT_GT(smallCount, 100);
    EXPECT_NEAR(small, discRadiusPixels(0.1, d), 2.0) << "the outline is the sphere's projected disc";
    int changed = 0;
    for (std::size_t i = 0; i < color_.size(); i += 4) changed += color_[i + 1] != without[i + 1];
    EXPECT_GE(changed, smallCount);

    session_->tool().radius = 0.2;
    draw(aim_);
    const auto [large, largeCount] = extent(test::greenish);
    EXPECT_NEAR(large, discRadiusPixels(0.2, d), 2.0);
    EXPECT_NEAR(large / small, 2.0, 0.15) << "twice the radius, twice the size on screen";
    EXPECT_GT(largeCount, smallCount);

    // The pointer on a panel: no tool drawn.
    draw(std::nullopt);
    EXPECT_EQ(extent(test::greenish).second, 0);
}

TEST_F(ToolGizmoTest, TheMirrorPlaneAndTheMoveRingShowOnTheSelection) {
    const auto cyan = [](const test::Rgba& p) { return p.g > p.r + 80 && p.b > p.r + 80; };
    const auto yellow = [](const test::Rgba& p) { return p.r > p.b + 100 && p.g > p.b + 100; };
    // Pixels of the image that `is` holds and the baseline's pixel there did not.
    const auto added = [this](const std::vector<std::uint8_t>& baseline, const std::function<bool(const test::Rgba&)>& is,
                              int& lowestRow, int& offCentre) {
        int n = 0;
        lowestRow = kHeight;
        offCentre = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const std::size_t i = (static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 4;
                const test::Rgba before{baseline[i], baseline[i + 1], baseline[i + 2], baseline[i + 3]};
                if (!is(pixel(x, y)) || is(before)) continue;
                ++n;
                lowestRow = std::min(lowestRow, y);
                offCentre += std::abs(x - kWidth / 2) > 2;
            }
        return n;
    };
    const int c = session_->findSculpture("c");
    session_->tool().kind = Kind::Move;
    draw(aim_);
    const std::vector<std::uint8_t> baseline = color_;
    EXPECT_EQ(extent(cyan).second, 0);

    session_->select(c);
    session_->setMirror(c, centralMirror(session_->sculptures()[static_cast<std::size_t>(c)]));
    draw(aim_);
    // The plane x = 2 through the ball, seen edge on from in front: a
    // vertical line down the middle of the image.
    int top = 0, offCentre = 0;
    EXPECT_GT(added(baseline, cyan, top, offCentre), 50);
    EXPECT_EQ(offCentre, 0);
    // The ring: round the pivot under the ball, below the image's middle.
    EXPECT_GT(added(baseline, yellow, top, offCentre), 50);
    EXPECT_GT(top, kHeight / 2);

    session_->setMirror(c, std::nullopt);
    session_->tool().kind = Kind::Carve;
    draw(aim_);
    EXPECT_EQ(added(baseline, cyan, top, offCentre), 0);
    EXPECT_EQ(added(baseline, yellow, top, offCentre), 0) << "the move gizmo is the move tool's";
    // With the other tools the selection (the sculpture the last stroke
    // edited) is outlined: its box's edges, light grey.
    const auto grey = [](const test::Rgba& p) {
        return p.r > 200 && p.g > 200 && p.b > 200 && std::abs(p.r - p.g) < 12 && std::abs(p.g - p.b) < 12;
    };
    EXPECT_GT(added(baseline, grey, top, offCentre), 100) << "the selection outlined";
    session_->select(-1);
    draw(aim_);
    EXPECT_EQ(added(baseline, grey, top, offCentre), 0) << "nothing selected, no outline";
}

}  // namespace
}  // namespace hg::garden
