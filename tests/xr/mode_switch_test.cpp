// Switching between the desktop and the headset without a restart
// (garden/desktop/desktop_app.h, xr/xr_garden.h headsetFromDesktop): the
// desktop window's garden goes into the mock runtime's headset, is carved
// there by the scripted right hand, and the desktop goes on with the carved
// grid and its own view; no runtime leaves the desktop running with the
// message; closing the window in the headset ends the program; `--xr` goes
// to the desktop on the same garden.
#include "xr_carve_script.h"
#include "xr_garden_fixture.h"

#include "garden/app/garden_session.h"
#include "garden/desktop/desktop_app.h"
#include "garden/replay/replay_runner.h"
#include "garden/session/open_session.h"
#include "voxel/volume.h"
#include "xr/xr_garden.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace hg::xr::test {
namespace {

class ModeSwitch : public XrGarden {
protected:
    garden::DesktopOptions desktop(int frames) {
        garden::DesktopOptions d;
        d.garden = gardenFile;
        d.width = 320;
        d.height = 240;
        d.vsync = false;
        d.frames = frames;
        return d;
    }
    // The headset's own options, as the command line makes them.
    static XrOptions headsetOptions() {
        XrOptions x;
        x.mirror = true;
        return x;
    }
};

TEST_F(ModeSwitch, TheDesktopGardenIsCarvedInTheHeadsetAndTheDesktopGoesOnWithIt) {
    // What the headless replay of the same strokes carves.
    const garden::ReplayScript parsed = garden::loadReplayScript(script(kCarveSteps));
    garden::GardenLoad load = garden::loadGarden(gardenFile);
    ASSERT_TRUE(load.ok()) << load.error;
    garden::GardenSession replay(std::move(load));
    ASSERT_TRUE(garden::runReplay(parsed, replay, nullptr, {}).ok());
    const int a = replay.findSculpture("a");
    ASSERT_EQ(replay.editCount(a), 1u);

    // The runtime ends the headset session after the strokes.
    ::setenv("HG_MOCK_XR_SCRIPT", script(kCarveSteps).c_str(), 1);
    ::setenv("HG_MOCK_XR_EVENTS", "30:exit", 1);
    std::vector<XrRunInfo> runs;
    garden::DesktopOptions d = desktop(6);
    d.headset = headsetFromDesktop(headsetOptions(), [&](const XrRunInfo& i) { runs.push_back(i); });
    std::vector<int> frames;
    glm::vec3 eyeBefore(0.0f);
    d.onFrame = [&](garden::GardenSession& s, int frame) {
        frames.push_back(frame);
        if (frame == 2) {
            // The desktop holds the carving tool when it goes into the headset.
            s.tool().kind = garden::ToolSettings::Kind::Carve;
            s.tool().radius = 0.12;
            EXPECT_EQ(s.editCount(a), 0u);
            eyeBefore = s.navigator().eye();
            return true;
        }
        if (frame == 3) {
            EXPECT_EQ(s.editCount(a), 1u) << "the headset's stroke is the desktop's garden's";
            EXPECT_EQ(garden::test::differingVoxels(*replay.sculptures()[static_cast<std::size_t>(a)].volume,
                                                    *s.sculptures()[static_cast<std::size_t>(a)].volume),
                      0);
            EXPECT_EQ(s.navigator().mode(), garden::NavigationMode::Walk) << "the desktop's own view again";
            EXPECT_EQ(s.navigator().eye(), eyeBefore);
            EXPECT_NEAR(s.scheduler().settings().budgetMs, 11.1, 1e-9) << "the desktop's budget again";
        }
        return false;
    };
    ASSERT_EQ(garden::runDesktopGarden(d), 0);
    EXPECT_EQ(frames, (std::vector<int>{0, 1, 2, 3, 4, 5})) << "the desktop went on after the headset";
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_GE(runs[0].focusedFrames, parsed.totalFrames());
    EXPECT_GT(runs[0].framesRendered, 0);
    EXPECT_FALSE(runs[0].lost);
}

TEST_F(ModeSwitch, NoRuntimeLeavesTheDesktopRunning) {
    ::setenv("XR_RUNTIME_JSON", (dir / "no_such_runtime.json").c_str(), 1);
    garden::DesktopOptions d = desktop(4);
    std::string message;
    const garden::HeadsetEntry entry = headsetFromDesktop(headsetOptions());
    d.headset = [&](garden::GardenSession& s, garden::GardenWindow& w, std::string& m) {
        const garden::HeadsetReturn r = entry(s, w, m);
        message = m;
        return r;
    };
    int last = -1;
    d.onFrame = [&](garden::GardenSession&, int frame) {
        last = frame;
        return frame == 1;
    };
    ASSERT_EQ(garden::runDesktopGarden(d), 0);
    EXPECT_EQ(last, 3) << "the desktop's frames all ran";
    EXPECT_NE(message.find("no OpenXR runtime"), std::string::npos) << message;
    EXPECT_NE(message.find("the desktop goes on"), std::string::npos) << message;
}

TEST_F(ModeSwitch, TheDesktopCanGoIntoTheHeadsetTwice) {
    // Each headset run ends when the user asks for the desktop (F9's path).
    XrOptions x = headsetOptions();
    x.askDesktop = [](int submitted) { return submitted >= 6; };
    std::vector<XrRunInfo> runs;
    garden::DesktopOptions d = desktop(6);
    d.headset = headsetFromDesktop(x, [&](const XrRunInfo& i) { runs.push_back(i); });
    d.onFrame = [&](garden::GardenSession&, int frame) { return frame == 1 || frame == 3; };
    ASSERT_EQ(garden::runDesktopGarden(d), 0);
    ASSERT_EQ(runs.size(), 2u);
    for (const XrRunInfo& r : runs) {
        EXPECT_GE(r.framesSubmitted, 6);
        EXPECT_GT(r.framesRendered, 0);
        EXPECT_EQ(r.endReason.empty(), false);
    }
}

TEST_F(ModeSwitch, ClosingTheWindowInTheHeadsetEndsTheProgram) {
    // The mirror is the desktop's window: closing it while in the headset
    // ends the headset session, then the desktop without another frame.
    XrOptions x = headsetOptions();
    x.onFrame = [](const garden::FrameStats&, int focused) {
        if (focused == 4) glfwSetWindowShouldClose(glfwGetCurrentContext(), GLFW_TRUE);
    };
    std::vector<XrRunInfo> runs;
    garden::DesktopOptions d = desktop(50);
    d.headset = headsetFromDesktop(x, [&](const XrRunInfo& i) { runs.push_back(i); });
    int last = -1;
    d.onFrame = [&](garden::GardenSession&, int frame) {
        last = frame;
        return frame == 1;
    };
    ASSERT_EQ(garden::runDesktopGarden(d), 0);
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_GE(runs[0].focusedFrames, 5);
    EXPECT_LT(runs[0].framesSubmitted, 50) << "the headset session ended when the window closed";
    EXPECT_EQ(last, 1) << "no desktop frame after the headset";
}

TEST_F(ModeSwitch, TheHeadsetGoesToTheDesktopOnTheSameGarden) {
    // `--xr`: the right hand carves, then the user asks for the desktop,
    // which shows the carved garden; closing it ends the run.
    ::setenv("HG_MOCK_XR_SCRIPT", script(kCarveSteps).c_str(), 1);
    XrOptions x = headsetOptions();
    x.garden = gardenFile;
    // After the strokes (21 focused frames from the second submitted one),
    // before the script's end would end the run.
    x.askDesktop = [](int submitted) { return submitted >= 20; };
    garden::DesktopOptions d = desktop(3);
    int desktopFrames = 0;
    d.onFrame = [&](garden::GardenSession& s, int) {
        ++desktopFrames;
        EXPECT_EQ(s.navigator().mode(), garden::NavigationMode::Walk) << "the desktop walks";
        return false;
    };
    x.desktop = garden::desktopAfterHeadset(d);
    x.script = script(kCarveSteps);
    XrRunInfo info;
    std::size_t edits = 0;
    ASSERT_EQ(runXrGarden(x,
                          [&](garden::GardenSession& s, const XrRunInfo& i) {
                              info = i;
                              edits = s.editCount(s.findSculpture("a"));
                          }),
              0);
    EXPECT_EQ(desktopFrames, 3);
    EXPECT_EQ(edits, 1u);
    EXPECT_EQ(info.endReason.empty(), false);
}

}  // namespace
}  // namespace hg::xr::test
