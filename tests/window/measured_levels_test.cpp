// Levels by measured error (polygonizer/realtime/chunk_errors.h, used by the
// session's level selection): a smooth sculpture seen from a few metres is
// drawn with fewer triangles than the voxel-size rule gives (its thin ring
// keeps its level), and the picture is the same but for a few pixels.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <glm/gtc/matrix_transform.hpp>

#include "../render/gl_fixture.h"
#include "garden/app/garden_session.h"
#include "garden/window/garden_view.h"
#include "tests/test_folder.h"

namespace hg::garden {
namespace {

namespace fs = std::filesystem;

// A smooth body (two blended balls) wearing a thin ring 1.2 voxels
// across at 96^3: what a coarse level would lose.
const char* const kBody =
    "body(x[3], a[1]) {\n"
    "  lower = 0.3 - (x[1]^2 + (x[2] - 0.55)^2 + x[3]^2);\n"
    "  upper = 0.12 - (x[1]^2 + (x[2] - 1.15)^2 + x[3]^2);\n"
    "  ring = 0.0001 - ((sqrt(x[1]^2 + x[3]^2) - 0.62)^2 + (x[2] - 0.53)^2);\n"
    "  body = lower | upper | ring;\n"
    "}\n";

class MeasuredLevelsTest : public test::GlTest {
protected:
    void SetUp() override {
        test::GlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        folder_ = std::make_unique<hg::test::TestFolder>("hg_measured_levels");
        fs::create_directories(folder_->path);
        std::ofstream(folder_->path / "body.hf") << kBody;
        std::ofstream(folder_->path / "garden.json")
            << R"({"version": 1, "name": "levels", "materials": {"clay": {"color": [0.7, 0.55, 0.45]}},)"
            << R"( "lights": [{"type": "directional", "direction": [-0.5, -0.7, -0.5], "intensity": 1.0},)"
            << R"( {"type": "ambient", "color": [1, 1, 1], "intensity": 0.25}], "sculptures": [)"
            << R"({"name": "body", "file": "body.hf", "resolution": 96, "material": "clay",)"
            << R"( "box": {"min": [-0.7, -0.05, -0.7], "max": [0.7, 1.6, 0.7]}, "placement": {"position": [0, 0, 0]}}]})";
    }
    void TearDown() override {
        folder_.reset();
        test::GlTest::TearDown();
    }

    struct Shot {
        std::vector<std::uint8_t> picture;
        RenderStats stats;
    };

    // The garden settled at the eye, then drawn from it.
    Shot shoot(double levelErrorPixels, const glm::vec3& eye) {
        SessionSettings s;
        s.chunkSize = 16;
        s.maxLevel = 2;
        s.viewportHeight = kHeight;
        s.fovY = glm::radians(double(kFovY));
        s.remeshChunksPerFrame = 4096;
        s.levelErrorPixels = levelErrorPixels;
        GardenSession session(loadGarden((folder_->path / "garden.json").string()), s);
        session.navigator().setMode(NavigationMode::Fly);
        session.navigator().setPose(eye, 0.0f, 0.0f);
        // A frame at least: the levels for the eye are chosen in one.
        for (int f = 0; f < 3000 && (f < 2 || !session.idle()); ++f) session.frame(FrameInput(Hands{}, 1.0 / 90.0));
        EXPECT_TRUE(session.idle());
        // A renderer of its own: the other shot's chunks have the same keys and versions.
        Renderer renderer;
        renderer.setQuality(test::plainQuality());
        GardenView view(renderer);
        view.upload(session, 1e9);
        target_->bind();
        const glm::vec3 at(0.0f, 0.75f, 0.0f);
        const glm::mat4 v = glm::lookAt(eye, at, glm::vec3(0, 1, 0));
        const glm::mat4 p = glm::perspective(glm::radians(kFovY), float(kWidth) / float(kHeight), kNear, kFar);
        view.render(session, {kWidth, kHeight}, v, p, eye);
        Shot shot;
        shot.stats = renderer.endFrame();
        read();
        shot.picture = color_;
        return shot;
    }

    std::unique_ptr<hg::test::TestFolder> folder_;
};

TEST_F(MeasuredLevelsTest, ASmoothSculptureDrawsFewerTrianglesForThePicture) {
    // 3.2 m away: a voxel (1.5 cm) is about 1.5 pixels, so the voxel-size
    // rule keeps level 0 wherever the body faces the eye.
    const glm::vec3 eye(0.0f, 1.0f, 3.2f);
    const Shot bySize = shoot(0.0, eye);
    const Shot byError = shoot(0.5, eye);
    int differ = 0, body = 0;
    for (std::size_t i = 0; i < bySize.picture.size(); i += 4) {
        int most = 0;
        for (std::size_t c = 0; c < 3; ++c)
            most = std::max(most, std::abs(int(bySize.picture[i + c]) - int(byError.picture[i + c])));
        differ += most > 24;
        body += bySize.picture[i] > bySize.picture[i + 2] + 30;  // the clay's warm pixels
    }
    std::printf("triangles drawn: %zu by voxel size, %zu by measured error; pixels differing by more than 24 levels: %d "
                "of %d on the sculpture\n",
                bySize.stats.trianglesDrawn, byError.stats.trianglesDrawn, differ, body);
    ASSERT_GT(body, 5000) << "the sculpture fills much of the view";
    // The ring keeps level 0 (a coarse level loses it), the smooth body takes level 1.
    EXPECT_LT(double(byError.stats.trianglesDrawn), 0.8 * double(bySize.stats.trianglesDrawn)) << "fewer triangles";
    EXPECT_LT(differ, body / 100) << "and the same picture but for a few edge pixels";
}

}  // namespace
}  // namespace hg::garden
