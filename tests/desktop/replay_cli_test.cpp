// `hypergarden replay` as a user runs it: offscreen with screenshots and
// stats, headless with screenshots skipped, a garden with a missing
// sculpture still plays, and bad scripts and gardens are refused with their
// JSON path.
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../cli_fixture.h"
#include "../garden/session_garden.h"

namespace hg::garden {
namespace {

class ReplayCli : public ::hg::test::CliTest {
protected:
    std::string garden() { return test::writeSmallGarden(dir); }
    std::string script(const std::string& steps) {
        garden();
        std::ofstream(dir / "walk.json") << R"({"garden": "garden.json", "viewport": [160, 120], "steps": )" << steps << "}";
        return path("walk.json");
    }
    static bool displayAvailable() {
        const char* d = std::getenv("DISPLAY");
        return d && *d;
    }
};

TEST_F(ReplayCli, OffscreenWritesScreenshotsAndStats) {
    if (!displayAvailable()) GTEST_SKIP() << "no X display: run under xvfb-run -a";
    const std::string s = script(R"([{"frames": 10, "navigation": {"thumbstick": [0, 1]}},
        {"commands": [{"morph": [0.5, 0]}]}, {"until_idle": true, "frames": 3000},
        {"commands": [{"screenshot": "end.png"}]}])");
    auto r = ::hg::test::runHypergarden("replay " + s + " --offscreen 160x120 --screenshot-every 5 --screenshot-dir " +
                                        path("shots") + " --stats " + path("stats.json") + " --morph-samples 3000");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("replayed"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("sculpture 'lost' is missing"), std::string::npos) << r.output;
    std::ifstream png(dir / "shots" / "end.png", std::ios::binary);
    ASSERT_TRUE(png) << "the script's screenshot";
    char sig[8] = {};
    png.read(sig, 8);
    EXPECT_EQ(std::string(sig + 1, 3), "PNG");
    EXPECT_TRUE(exists("shots/frame_000005.png"));
    std::ifstream in(dir / "stats.json");
    nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_GT(j["frames"].size(), 11u);
    std::size_t drawn = 0;
    for (const auto& f : j["frames"]) drawn = std::max<std::size_t>(drawn, f["triangles_drawn"].get<std::size_t>());
    EXPECT_GT(drawn, 100u) << "offscreen frames draw the sculptures";
    EXPECT_GT(j["summary"]["mean_stage_ms"]["render"].get<double>(), 0.0);
}

TEST_F(ReplayCli, HeadlessSkipsScreenshotsAndSaysSo) {
    const std::string s = script(R"([{"frames": 3}, {"commands": [{"screenshot": "x.png"}]}])");
    auto r = ::hg::test::runHypergarden("replay " + s + " --headless --screenshot-dir " + path("shots"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("screenshot 'x.png' skipped (headless)"), std::string::npos) << r.output;
    EXPECT_FALSE(exists("shots/x.png"));
}

TEST_F(ReplayCli, BadScriptsAndGardensAreRefusedWithTheirPath) {
    std::string s = script(R"([{"navigation": {"thumbstik": [0, 1]}}])");
    auto r = ::hg::test::runHypergarden("replay " + s + " --headless");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("$.steps[0].navigation.thumbstik: unknown key"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("thumbstick"), std::string::npos) << "suggests the right key";

    std::ofstream(dir / "garden.json") << R"({"version": 1, "sculptures": [{"name": "x", "file": "ball.hf", "resolution": -4}]})";
    std::ofstream(dir / "walk.json") << R"({"garden": "garden.json", "steps": [{"frames": 1}]})";
    r = ::hg::test::runHypergarden("replay " + path("walk.json") + " --headless");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("$.sculptures[0].resolution"), std::string::npos) << r.output;

    r = ::hg::test::runHypergarden("replay " + path("walk.json") + " --offscreen 12x12");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--offscreen expects WIDTHxHEIGHT"), std::string::npos) << r.output;
    r = ::hg::test::runHypergarden("replay " + path("nope.json") + " --headless");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("cannot read the script file"), std::string::npos) << r.output;
}

TEST_F(ReplayCli, TheDesktopWindowOpensTheGardenAndDrawsItsOverlay) {
    if (!displayAvailable()) GTEST_SKIP() << "no X display: run under xvfb-run -a";
    garden();
    auto r = ::hg::test::runHypergarden("--garden " + path("garden.json") + " --frames 20 --no-vsync --width 320 --height 240" +
                                        " --exit-screenshot " + path("window.png"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("sculpture 'lost' is missing"), std::string::npos) << r.output;
    ASSERT_TRUE(exists("window.png"));
    EXPECT_GT(std::filesystem::file_size(dir / "window.png"), 2000u) << "a drawn frame, not a blank one";
    // A garden file that is refused: exit 2 and the JSON path.
    std::ofstream(dir / "bad.json") << R"({"version": 1, "sculptures": [{"name": "x"}]})";
    r = ::hg::test::runHypergarden("--garden " + path("bad.json") + " --frames 1");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("$.sculptures[0]"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace hg::garden
