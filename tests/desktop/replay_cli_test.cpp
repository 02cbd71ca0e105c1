// `hypergarden replay` as a user runs it: offscreen with screenshots and
// stats, headless with screenshots skipped, a garden with a missing
// sculpture still plays, and bad scripts and gardens are refused with their
// JSON path; an {"export": ...} command writes a sculpture as the desktop's
// Export panel does.
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../cli_fixture.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"
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
    // The GPU's own time, from the renderer's timer queries: most frames
    // have a measurement (the first few wait for their results).
    std::size_t measured = 0;
    for (const auto& f : j["frames"]) measured += f["gpu_ms"].get<double>() > 0.0 ? 1 : 0;
    EXPECT_GT(measured, j["frames"].size() / 2);
    EXPECT_EQ(j["summary"]["gpu_frames"].get<std::size_t>(), measured);
    EXPECT_GT(j["summary"]["mean_gpu_ms"].get<double>(), 0.0);
    EXPECT_GE(j["summary"]["max_gpu_ms"].get<double>(), j["summary"]["mean_gpu_ms"].get<double>());
    // And pass by pass: the scene and the composite run in every view; the
    // passes that ran add up to the total.
    for (const auto& f : j["frames"]) {
        const double total = f["gpu_ms"].get<double>();
        if (total <= 0.0) continue;
        const auto& pass = f["gpu_pass_ms"];
        EXPECT_GT(pass["scene"].get<double>(), 0.0);
        EXPECT_GT(pass["post"].get<double>(), 0.0);
        double sum = 0.0;
        for (const char* name : {"shadow", "scene", "occlusion", "post"}) sum += std::max(0.0, pass[name].get<double>());
        EXPECT_NEAR(sum, total, 1e-3 * total + 1e-4);
    }
    std::size_t chunks = 0;
    for (const auto& f : j["frames"]) chunks = std::max<std::size_t>(chunks, f["chunks_drawn"].get<std::size_t>());
    EXPECT_GT(chunks, 0u);
    // One view a frame: its shadow map drawn, or kept from the frame before
    // once nothing it shows changes (the garden settled, standing still).
    std::size_t mapsDrawn = 0, mapsKept = 0;
    for (const auto& f : j["frames"]) {
        const auto d = f["shadow_maps_drawn"].get<std::size_t>(), k = f["shadow_maps_kept"].get<std::size_t>();
        EXPECT_LE(d + k, 1u);
        mapsDrawn += d;
        mapsKept += k;
    }
    EXPECT_GT(mapsDrawn, 0u);
    EXPECT_GT(mapsKept, 0u) << "the settled garden keeps its shadow map";
}

// --quality auto: the desktop's governor against the script's budget. A
// budget no renderer meets steps it down; one every renderer meets keeps
// the renderer's preset. The note says what it did.
TEST_F(ReplayCli, TheAutomaticQualityStepsDownWhenTheBudgetIsNotMet) {
    if (!displayAvailable()) GTEST_SKIP() << "no X display: run under xvfb-run -a";
    garden();
    const auto changes = [&](const std::string& budget) {
        std::ofstream(dir / "auto.json") << R"({"garden": "garden.json", "viewport": [160, 120], "budget_ms": )" << budget
                                         << R"(, "steps": [{"until_idle": true, "frames": 3000}, {"frames": 150}]})";
        auto r = ::hg::test::runHypergarden("replay " + path("auto.json") + " --offscreen 160x120 --quality auto");
        EXPECT_EQ(r.status, 0) << r.output;
        const std::size_t at = r.output.find("--quality auto: ");
        EXPECT_NE(at, std::string::npos) << r.output;
        return at == std::string::npos ? -1 : std::atoi(r.output.c_str() + at + 16);
    };
    EXPECT_GE(changes("0.1"), 1) << "a tenth of a millisecond a frame: step down";
    EXPECT_EQ(changes("1000"), 0) << "a second a frame: keep the preset";
}

// --impostor-distance: sculptures farther than it from the eye are drawn
// as impostor cards (reported per frame as impostors_drawn), none with 0.
TEST_F(ReplayCli, FarSculpturesAreImpostorsUnlessTheDistanceIsZero) {
    if (!displayAvailable()) GTEST_SKIP() << "no X display: run under xvfb-run -a";
    const std::string s = script(R"([{"until_idle": true, "frames": 3000}, {"frames": 5}])");
    auto cards = [&](const std::string& distance) {
        auto r = ::hg::test::runHypergarden("replay " + s + " --offscreen 160x120 --impostor-distance " + distance +
                                            " --stats " + path("stats.json"));
        EXPECT_EQ(r.status, 0) << r.output;
        std::ifstream in(dir / "stats.json");
        const nlohmann::json j = nlohmann::json::parse(in);
        return j["frames"].back()["impostors_drawn"].get<std::size_t>();
    };
    EXPECT_GT(cards("1"), 0u) << "within a metre of the start, nothing: every sculpture in view is a card";
    EXPECT_EQ(cards("0"), 0u);
    auto r = ::hg::test::runHypergarden("replay " + s + " --offscreen 160x120 --impostor-distance -3");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("--impostor-distance"), std::string::npos) << r.output;
}

TEST_F(ReplayCli, AnExportCommandWritesTheSculptureAsThePanelDoes) {
    const std::string stl = (dir / "out" / "ball-c.stl").string();
    const std::string hf = (dir / "a.hf").string();
    const std::string s = script(R"([{"frames": 2},
        {"commands": [{"stroke": {"sculpture": "c", "tool": "carve", "radius": 0.1, "path": [[2.45, 0.9, 1.3], [2.5, 0.6, 1.4]]}},
                      {"export": {"sculpture": "c", "path": ")" + stl + R"(", "res": 48}}]},
        {"commands": [{"select": "a"}, {"export": {"path": ")" + hf + R"("}}]}])");
    std::filesystem::create_directories(dir / "out");
    auto r = ::hg::test::runHypergarden("replay " + s + " --headless --stats " + path("stats.json"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("wrote " + stl), std::string::npos) << r.output;
    // A closed mesh of ball c (radius 0.6 m), in millimetres as STL is.
    const poly::StlReadResult read = poly::readStl(stl);
    ASSERT_EQ(read.error, "");
    const poly::MeshReport m = poly::validateMesh(poly::weldByPosition(read.mesh));
    EXPECT_GT(m.triangles, 500u);
    EXPECT_EQ(m.boundaryEdges, 0u);
    EXPECT_NEAR(m.boxMax[1] - m.boxMin[1], 1200.0, 60.0) << "the ball's height in mm";
    // The selected sculpture when none is named; HyperFun with its name.
    std::ifstream hfIn(hf);
    std::stringstream hfText;
    hfText << hfIn.rdbuf();
    EXPECT_NE(hfText.str().find("my_model"), std::string::npos) << hfText.str();
    std::ifstream in(dir / "stats.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_EQ(j["exports"].size(), 2u);
    EXPECT_EQ(j["exports"][0], stl);

    // Refused with the reason: a sculpture that is not there, a format that
    // is not one, an unknown key (with its JSON path).
    r = ::hg::test::runHypergarden("replay " + script(R"([{"commands": [{"export": {"sculpture": "nobody", "path": "x.stl"}}]}])") +
                                   " --headless");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("export: no sculpture named 'nobody'"), std::string::npos) << r.output;
    r = ::hg::test::runHypergarden("replay " + script(R"([{"commands": [{"export": {"sculpture": "c", "path": ")" +
                                                      (dir / "x.docx").string() + R"("}}]}])") + " --headless");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("export: "), std::string::npos) << r.output;
    EXPECT_FALSE(exists("x.docx"));
    r = ::hg::test::runHypergarden("replay " + script(R"([{"commands": [{"export": {"sculptur": "c", "path": "x.stl"}}]}])") +
                                   " --headless");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("$.steps[0].commands[0].export.sculptur"), std::string::npos) << r.output;
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
