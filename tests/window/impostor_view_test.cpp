// Impostors (garden/render/impostor_atlas.h, impostor_cards.h; the view's
// choice in garden/window/garden_view.cpp): a sculpture beyond the
// impostor distance is drawn as a card that looks like its meshes (the
// same silhouette, colours and depth, from the front, from above and for
// a turned placement), casts the same shadow, is shared by copies of one
// source while an edited copy gets its own, follows an edit, and lets a
// garden of hundreds of sculptures draw in a few calls and a fraction of
// the triangles.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <glm/gtc/matrix_transform.hpp>

#include "../render/gl_fixture.h"
#include "garden/action/action.h"
#include "garden/app/garden_session.h"
#include "garden/scene/scale_garden.h"
#include "garden/window/garden_view.h"
#include "tests/test_folder.h"

namespace hg::garden {
namespace {

namespace fs = std::filesystem;

// A stem, a cap and an arm to one side (+x): a silhouette that shows a
// wrong turn or a wrong frame at once.
const char* const kMushroom =
    "mushroom(x[3], a[1]) {\n"
    "  stem = 0.09 - (x[1]^2 + x[3]^2);\n"
    "  stem = stem & x[2] & (1.2 - x[2]);\n"
    "  cap = 0.25 - (x[1]^2 + (x[2] - 1.2)^2 + x[3]^2);\n"
    "  arm = 0.04 - ((x[1] - 0.55)^2 + (x[2] - 0.6)^2 + x[3]^2);\n"
    "  mushroom = stem | cap | arm;\n"
    "}\n";

class ImpostorViewTest : public test::GlTest {
protected:
    static constexpr float kNarrowFov = 4.0f;  // degrees: a sculpture 36 m away fills the view

    void SetUp() override {
        test::GlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        folder_ = std::make_unique<hg::test::TestFolder>("hg_impostor_view");
        fs::create_directories(folder_->path);
        std::ofstream(folder_->path / "mushroom.hf") << kMushroom;
    }
    void TearDown() override {
        folder_.reset();
        test::GlTest::TearDown();
    }

    // A garden of mushrooms at `positions` (x, z; yaw degrees), red.
    // With `shades`, sculpture i is in a red of its own (impostors are per material).
    std::string writeGarden(const std::vector<glm::vec3>& placements, bool shades = false) const {
        std::ofstream out(folder_->path / "garden.json");
        out << R"({"version": 1, "name": "far", "materials": {"red": {"color": [0.85, 0.12, 0.1], "roughness": 0.5})";
        for (std::size_t i = 0; i < placements.size(); ++i)
            out << R"(, "red)" << i << R"(": {"color": [0.85, 0.12, )" << 0.02 * static_cast<double>(i) << "]}";
        out << "},"
            << R"( "lights": [{"type": "directional", "direction": [-0.6, -0.7, -0.35], "intensity": 1.0},)"
            << R"( {"type": "ambient", "color": [1, 1, 1], "intensity": 0.25}], "sculptures": [)";
        for (std::size_t i = 0; i < placements.size(); ++i)
            out << (i ? ", " : "") << R"({"name": "m)" << i << R"(", "file": "mushroom.hf", "resolution": 48,)"
                << R"( "box": {"min": [-0.75, -0.05, -0.6], "max": [0.8, 1.75, 0.6]}, "material": "red)"
                << (shades ? std::to_string(i) : std::string()) << R"(",)"
                << R"( "placement": {"position": [)" << placements[i].x << ", 0, " << placements[i].y
                << R"(], "yaw": )" << placements[i].z << "}}";
        out << "]}";
        return (folder_->path / "garden.json").string();
    }

    SessionSettings settings(float fovDegrees) const {
        SessionSettings s;
        s.chunkSize = 16;
        s.maxLevel = 2;
        s.viewportHeight = kHeight;
        s.fovY = glm::radians(double(fovDegrees));
        s.remeshChunksPerFrame = 4096;
        return s;
    }

    static void settle(GardenSession& session) {
        for (int f = 0; f < 3000 && !session.idle(); ++f) session.frame(FrameInput(Hands{}, 1.0 / 90.0));
        ASSERT_TRUE(session.idle());
    }

    // Eye placed in the session (its levels follow it) and in the view.
    void place(GardenSession& session, const glm::vec3& eye, const glm::vec3& at) {
        const glm::vec3 d = glm::normalize(at - eye);
        session.navigator().setMode(NavigationMode::Fly);
        session.navigator().setPose(eye, std::atan2(d.x, -d.z), std::asin(d.y));
        eye_ = eye;
        at_ = at;
    }

    RenderStats draw(GardenView& view, const GardenSession& session, float fovDegrees) {
        target_->bind();
        const glm::mat4 v = glm::lookAt(eye_, at_, glm::vec3(0, 1, 0));
        const glm::mat4 p = glm::perspective(glm::radians(fovDegrees), float(kWidth) / float(kHeight), kNear, kFar);
        view.render(session, {kWidth, kHeight}, v, p, eye_);
        const RenderStats stats = renderer_->endFrame();
        read();
        return stats;
    }

    // Drawn with the meshes, then as cards (one render asks for the
    // impostors, the next upload bakes them).
    struct Pair {
        std::vector<std::uint8_t> meshColor, cardColor;
        std::vector<float> meshDepth, cardDepth;
        RenderStats mesh, asking, card;  // asking: the first with cards wanted, before any bake
    };
    Pair meshAndCard(GardenView& view, const GardenSession& session, RenderQuality q, float fovDegrees) {
        Pair out;
        renderer_->setQuality(q);
        view.setImpostorDistance(0.0f);
        view.upload(session, 1e9);
        out.mesh = draw(view, session, fovDegrees);
        out.meshColor = color_;
        out.meshDepth = depth_;
        view.setImpostorDistance(30.0f);
        out.asking = draw(view, session, fovDegrees);
        view.upload(session, 1e9);
        out.card = draw(view, session, fovDegrees);
        out.cardColor = color_;
        out.cardDepth = depth_;
        return out;
    }

    static test::Rgba at(const std::vector<std::uint8_t>& c, int x, int y) {
        const std::size_t i = 4 * (static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x));
        return {c[i], c[i + 1], c[i + 2], c[i + 3]};
    }

    // With HG_IMPOSTOR_DUMP set, the two pictures side by side (meshes
    // left, card right) as a PPM, to look at.
    static void dump(const std::string& path, const Pair& p) {
        if (!std::getenv("HG_IMPOSTOR_DUMP")) return;
        std::ofstream out(path, std::ios::binary);
        out << "P6 " << 2 * kWidth << " " << kHeight << " 255\n";
        for (int y = 0; y < kHeight; ++y)
            for (int half = 0; half < 2; ++half)
                for (int x = 0; x < kWidth; ++x) {
                    const test::Rgba q = at(half ? p.cardColor : p.meshColor, x, y);
                    out << char(q.r) << char(q.g) << char(q.b);
                }
    }

    // The red pixels of both pictures: overlap over union, and the mean
    // difference of colour (0..255 a channel) where both are red.
    struct Likeness {
        int mesh = 0, card = 0;
        double overlap = 0.0, colourDifference = 0.0, depthDifference = 0.0;
    };
    static Likeness likeness(const Pair& p) {
        Likeness l;
        int both = 0, either = 0;
        double colour = 0.0, depth = 0.0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const test::Rgba a = at(p.meshColor, x, y), b = at(p.cardColor, x, y);
                const bool ra = test::reddish(a), rb = test::reddish(b);
                l.mesh += ra;
                l.card += rb;
                either += ra || rb;
                if (!(ra && rb)) continue;
                ++both;
                colour += (std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b)) / 3.0;
                const std::size_t i = static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x);
                depth += std::abs(eyeDepth(p.meshDepth[i]) - eyeDepth(p.cardDepth[i]));
            }
        l.overlap = either ? double(both) / either : 0.0;
        l.colourDifference = both ? colour / both : 255.0;
        l.depthDifference = both ? depth / both : 1e9;
        return l;
    }

    std::unique_ptr<hg::test::TestFolder> folder_;
    glm::vec3 eye_{0.0f}, at_{0.0f};
};

// From the front, from above and for a turned placement: the card covers
// the mesh's pixels, in its colours, at its depth (the sculpture fills
// most of the view through a narrow lens 36 m away).
TEST_F(ImpostorViewTest, AFarSculptureAsACardLooksLikeItsMeshes) {
    struct Case {
        const char* what;
        float yaw;
        glm::vec3 eye;
    };
    const Case cases[] = {{"front", 0.0f, {0.0f, 1.0f, 36.0f}},
                          {"from above, turned", 65.0f, {20.0f, 14.0f, 27.0f}},
                          {"from the side", 0.0f, {36.0f, 0.9f, 2.0f}}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        GardenSession session(loadGarden(writeGarden({{0.0f, 0.0f, c.yaw}})), settings(kNarrowFov));
        place(session, c.eye, {0.0f, 0.85f, 0.0f});
        settle(session);
        GardenView view(*renderer_);
        const Pair p = meshAndCard(view, session, test::plainQuality(), kNarrowFov);
        if (&c == &cases[0]) {
            EXPECT_EQ(p.asking.impostorsDrawn, 0u) << "none baked yet: the meshes are drawn";
        }
        EXPECT_GT(p.mesh.chunksDrawn, 0u);
        EXPECT_EQ(p.card.impostorsDrawn, 1u);
        EXPECT_EQ(p.card.chunksDrawn, 0u);
        EXPECT_LE(p.card.trianglesDrawn, 4u) << "the ground and one card";
        const Likeness l = likeness(p);
        dump(std::string("/tmp/impostor_") + c.what + ".ppm", p);
        std::printf("%s: overlap %.3f colour %.2f depth %.3f m (%d / %d)\n", c.what, l.overlap, l.colourDifference,
                    l.depthDifference, l.mesh, l.card);
        EXPECT_GT(l.mesh, 6000) << "the sculpture fills much of the view";
        // (Through this lens a frame's texel spans about 2.6 pixels: the
        // card's outline is coarser than the meshes'.)
        EXPECT_GT(l.overlap, 0.9) << l.mesh << " red pixels of the meshes, " << l.card << " of the card";
        EXPECT_LT(l.colourDifference, 10.0);
        EXPECT_LT(l.depthDifference, 0.05) << "metres, where both show the sculpture";
    }
}

// The sun's shadow of a card falls where the meshes' did (35 m away,
// within the shadow's 40 m): the ground pixels the shadow darkens agree.
TEST_F(ImpostorViewTest, ACardCastsTheSculpturesShadow) {
    GardenSession session(loadGarden(writeGarden({{0.0f, 0.0f, 0.0f}})), settings(kNarrowFov));
    place(session, {0.0f, 2.5f, 35.0f}, {-0.8f, 0.5f, 0.0f});
    settle(session);
    GardenView view(*renderer_);
    RenderQuality lit = test::plainQuality();
    lit.shadows = true;
    const Pair shadowed = meshAndCard(view, session, lit, kNarrowFov);
    RenderQuality unlit = test::plainQuality();
    const Pair plain = meshAndCard(view, session, unlit, kNarrowFov);
    ASSERT_EQ(shadowed.card.impostorsDrawn, 1u);
    dump("/tmp/impostor_shadow.ppm", shadowed);
    // Shadowed: not red, and at most 80% as bright as without the shadow.
    auto shade = [&](const std::vector<std::uint8_t>& with, const std::vector<std::uint8_t>& without) {
        std::vector<bool> s(static_cast<std::size_t>(kWidth * kHeight));
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const test::Rgba a = at(with, x, y), b = at(without, x, y);
                s[static_cast<std::size_t>(y * kWidth + x)] =
                    !test::reddish(a) && !test::reddish(b) && a.sum() < 0.8 * b.sum();
            }
        return s;
    };
    const std::vector<bool> mesh = shade(shadowed.meshColor, plain.meshColor);
    const std::vector<bool> card = shade(shadowed.cardColor, plain.cardColor);
    int m = 0, c = 0, both = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        m += mesh[i];
        c += card[i];
        both += mesh[i] && card[i];
    }
    EXPECT_GT(m, 300) << "the meshes' shadow is in view";
    EXPECT_GT(both, 0.75 * m) << m << " shadowed by the meshes, " << c << " by the card";
    EXPECT_LT(c, 1.3 * m);
}

// Copies of one source in one material share an impostor; an edited copy
// gets its own, showing the edit, and the others keep theirs.
TEST_F(ImpostorViewTest, CopiesShareOneImpostorAndAnEditedCopyHasItsOwn) {
    GardenSession session(loadGarden(writeGarden({{-3.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 40.0f}, {3.0f, 0.0f, 90.0f}})),
                          settings(10.0f));
    place(session, {0.0f, 1.7f, 45.0f}, {0.0f, 0.8f, 0.0f});
    settle(session);
    GardenView view(*renderer_);
    renderer_->setQuality(test::plainQuality());
    view.upload(session, 1e9);
    draw(view, session, 10.0f);
    view.upload(session, 1e9);
    RenderStats s = draw(view, session, 10.0f);
    EXPECT_EQ(s.impostorsDrawn, 3u);
    ASSERT_NE(renderer_->impostorAtlas(), nullptr);
    EXPECT_EQ(renderer_->impostorAtlas()->count(), 1u);
    EXPECT_EQ(renderer_->impostorAtlas()->bakes(), 1u);
    const int redBefore = count(test::reddish);

    // Carve most of the cap off the middle copy.
    Perturbation cut;
    cut.center = {0.0, 1.45, 0.0};
    cut.radii = {0.6, 0.4, 0.6};
    cut.strength = -20.0;
    ASSERT_EQ(session.apply(PerturbAction{"m1", cut}), "");
    settle(session);
    s = draw(view, session, 10.0f);
    EXPECT_EQ(s.impostorsDrawn, 2u) << "the edited copy's meshes until its own is baked";
    view.upload(session, 1e9);
    s = draw(view, session, 10.0f);
    EXPECT_EQ(s.impostorsDrawn, 3u);
    EXPECT_EQ(renderer_->impostorAtlas()->count(), 2u);
    EXPECT_LT(count(test::reddish), redBefore - 100) << "the card shows the cut";
}

// Six impostors (one material each) grow the atlas from four layers to
// eight: the layers baked before move into the new textures, so each
// impostor is baked once and every sculpture is drawn as a card.
TEST_F(ImpostorViewTest, TheAtlasGrowsWithoutBakingAgain) {
    std::vector<glm::vec3> row;
    for (int i = 0; i < 6; ++i) row.push_back({-7.5f + 3.0f * static_cast<float>(i), 0.0f, 0.0f});
    GardenSession session(loadGarden(writeGarden(row, true)), settings(20.0f));
    place(session, {0.0f, 1.7f, 45.0f}, {0.0f, 0.8f, 0.0f});
    settle(session);
    GardenView view(*renderer_);
    renderer_->setQuality(test::plainQuality());
    RenderStats s;
    for (int f = 0; f < 6; ++f) {
        view.upload(session, 1e9);
        s = draw(view, session, 20.0f);
    }
    EXPECT_EQ(s.impostorsDrawn, 6u);
    ASSERT_NE(renderer_->impostorAtlas(), nullptr);
    EXPECT_EQ(renderer_->impostorAtlas()->layers(), 8u);
    EXPECT_EQ(renderer_->impostorAtlas()->count(), 6u);
    EXPECT_EQ(renderer_->impostorAtlas()->bakes(), 6u) << "none baked again when the atlas grew";
    EXPECT_GT(count(test::reddish), 600) << "the cards show their sculptures";
}

// Hundreds of small sculptures: beyond the distance they go out as cards
// of one shared impostor, in one instanced call, with a fraction of the
// triangles, and the picture keeps its sculptures.
TEST_F(ImpostorViewTest, AGardenOfHundredsDrawsFarSculpturesAsCards) {
    ScaleGardenSpec spec;
    spec.count = 400;
    spec.spacing = 3.0;
    spec.resolution = 24;
    writeGarden({{0.0f, 0.0f, 0.0f}});
    GardenSession session(loadScaleGarden((folder_->path / "garden.json").string(), spec), settings(45.0f));
    settle(session);
    eye_ = session.navigator().eye();
    at_ = eye_ + session.navigator().forward() * 10.0f;
    GardenView view(*renderer_);
    const Pair p = meshAndCard(view, session, test::plainQuality(), 45.0f);
    EXPECT_GT(p.card.impostorsDrawn, 100u);
    EXPECT_EQ(renderer_->impostorAtlas()->count(), 1u) << "copies of one source share";
    EXPECT_GT(p.mesh.trianglesDrawn, p.card.trianglesDrawn + 20 * p.card.impostorsDrawn)
        << p.card.trianglesDrawn << " against " << p.mesh.trianglesDrawn;
    EXPECT_LE(p.card.drawCalls, p.mesh.drawCalls + 1) << "the cards in one call";
    const Likeness l = likeness(p);
    EXPECT_GT(l.overlap, 0.8) << l.mesh << " red pixels of the meshes, " << l.card << " of the cards";
}

}  // namespace
}  // namespace hg::garden
