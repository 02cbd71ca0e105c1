// content/gardens/scan.json drawn: its scanned sculptures (the phantom's
// skull and skin, issue 22) are shown like the others, at their depth.
#include "../render/gl_fixture.h"
#include "garden/app/garden_session.h"
#include "garden/window/garden_view.h"

namespace hg::garden {
namespace {

class ScanViewTest : public test::GlTest {};

TEST_F(ScanViewTest, TheScannedSculpturesAreDrawnAtTheirDepth) {
    SessionSettings settings;
    settings.chunkSize = 16;
    settings.maxLevel = 1;
    settings.viewportHeight = kHeight;
    settings.fovY = glm::radians(double(kFovY));
    settings.sculptureResolution = 64;
    GardenSession session(loadGarden(std::string(HG_SOURCE_DIR) + "/content/gardens/scan.json"), settings);
    for (const char* name : {"skull", "head"}) {
        const int index = session.findSculpture(name);
        ASSERT_GE(index, 0) << name;
        const Sculpture& s = session.sculptures()[static_cast<std::size_t>(index)];
        ASSERT_TRUE(s.onShow()) << name << ": " << s.error;
        ASSERT_TRUE(s.scanned());
        // 3 m in front of its centre, looking along -z at it.
        const glm::vec3 c = s.worldCentre();
        session.navigator().setMode(NavigationMode::Fly);
        session.navigator().setPose(c + glm::vec3(0.0f, 0.0f, 3.0f), 0.0f, 0.0f);
        for (int f = 0; f < 500 && !session.idle(); ++f) session.frame(FrameInput(Hands{}, 1.0 / 90.0));
        ASSERT_TRUE(session.idle());
        GardenView view(*renderer_);
        view.upload(session, 1e9);
        target_->bind();
        view.render(session, {kWidth, kHeight}, glm::radians(kFovY));
        renderer_->endFrame();
        read();
        // Its surface (or, through the skull's eye sockets, its inside) is
        // within a metre of its centre, 3 m away: not the sky.
        int near = 0;
        for (int dy = -10; dy <= 10; dy += 5)
            for (int dx = -10; dx <= 10; dx += 5) {
                const double d = eyeDepth(depth(kWidth / 2 + dx, kHeight / 2 + dy));
                near += d > 1.5 && d < 4.0;
            }
        EXPECT_GE(near, 20) << name << ": the sculpture covers the middle of the view";
        EXPECT_EQ(depth(kWidth / 2, 2), 1.0f) << "sky at the top";
    }
}

}  // namespace
}  // namespace hg::garden
