// A garden for runXrGarden against the mock runtime (xr_garden_test.cpp,
// hand_panel_pages_test.cpp): the small garden (sculpture 'a', a ball of
// radius 0.5 at (0, 0.5, -2.31)) seen from the origin along -z, so the
// stage is the world; scripts written beside it; the hand panel pressed by
// a scripted right hand.
#pragma once

#include "mock_xr_fixture.h"

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "../garden/session_garden.h"
#include "garden/hands/hand_state.h"
#include "garden/render/renderer.h"
#include "xr/hand_panel.h"
#include "xr/xr_garden.h"

namespace hg::xr::test {

class XrGarden : public garden::test::SmallGarden {
protected:
    void SetUp() override {
        garden::test::SmallGarden::SetUp();
        HG_REQUIRE_DISPLAY();
        useMockRuntime();
        ::setenv("HG_MOCK_XR_READBACK", (dir / "readback").c_str(), 1);
        // The viewer at the origin looking along -z: the stage is the world.
        // No morph, so nothing depends on how far a time-budgeted blend got.
        gardenFile = writeGarden(nlohmann::json::parse(
            R"({"start": {"position": [0, 1.7, 0], "look_at": [0, 1.7, -1]}, "morph": null})"));
    }
    std::string script(const std::string& steps) {
        const std::string path = (dir / "carve.json").string();
        std::ofstream(path) << R"({"garden": "garden.json", "steps": )" << steps << "}";
        return path;
    }
    // A run of `frames` frames on the garden, without the mirror window.
    XrOptions framesRun(int frames) const {
        XrOptions o;
        o.garden = gardenFile;
        o.frames = frames;
        o.mirror = false;
        return o;
    }
    nlohmann::json readback() {
        std::ifstream in(dir / "readback" / "frames.json");
        return nlohmann::json::parse(in);
    }
    std::string gardenFile;
};

// A script step's hands (JSON): the left hand at `hand` (no turn), the
// right hand's ray straight at the panel's board point `uv` from 0.3 m in
// front of it.
inline std::string atPanel(const glm::vec3& hand, const glm::vec2& uv, bool trigger, int frames) {
    HandPanel p;
    garden::HandState h;
    h.tracked = true;
    h.grip.position = hand;
    p.place(h, 1.0f);
    const glm::vec3 at = p.at(uv) + glm::vec3(0.0f, 0.0f, 0.3f);
    const auto vec = [](const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}).dump(); };
    return R"({"frames": )" + std::to_string(frames) + R"(, "navigation": {"aim": {"position": )" + vec(hand) +
           R"(}}, "tool": {"aim": {"position": )" + vec(at) + R"(, "direction": [0, 0, -1]}, "trigger": )" +
           (trigger ? "1" : "0") + "}}";
}

// Points at a button, pulls and lets go (ImGui's buttons press on release).
inline std::string pressPanel(const glm::vec3& hand, const glm::vec2& uv) {
    return atPanel(hand, uv, false, 2) + ", " + atPanel(hand, uv, true, 3) + ", " + atPanel(hand, uv, false, 2);
}

const glm::vec3 kPanelHand(-0.2f, 1.0f, -0.4f);

// The clear sky in row y of an eye's RGBA image (w pixels wide): the row's
// darkest pixel (clouds are brighter) is blue and no brighter than the sRGB
// clear colour the renderer gives the horizon; the sky deepens overhead,
// and a second sRGB encoding in the swapchain would brighten it past that.
inline void expectClearSkyInRow(const unsigned char* px, int w, int y) {
    const unsigned char* darkest = nullptr;
    int darkestSum = 1 << 30;
    for (int x = 0; x < w; ++x) {
        const unsigned char* p = px + (static_cast<std::size_t>(y) * w + x) * 4;
        if (p[0] + p[1] + p[2] < darkestSum) {
            darkestSum = p[0] + p[1] + p[2];
            darkest = p;
        }
    }
    ASSERT_NE(darkest, nullptr);
    const garden::View sky;
    for (int c = 0; c < 3; ++c) EXPECT_LE(darkest[c], sky.clearColor[c] * 255.0f + 1.0f) << "row " << y << ", channel " << c;
    EXPECT_GT(darkest[2], darkest[0] + 30) << "row " << y << ": blue sky";
}

}  // namespace hg::xr::test
