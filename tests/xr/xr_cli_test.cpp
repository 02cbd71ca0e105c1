// `hypergarden --xr` as a user runs it: without a runtime a clear message
// and its own exit status (the desktop one command away); with the mock
// runtime it runs N frames into a session folder; with the Khronos core
// validation layer enabled the session runs with no validation error.
#include <filesystem>
#include <fstream>

#include "../cli_fixture.h"
#include "../garden/session_garden.h"
#include "mock_xr_fixture.h"
#include "xr/xr_garden.h"

namespace hg::xr::test {
namespace {

class XrCli : public ::hg::test::CliTest {
protected:
    void SetUp() override {
        ::hg::test::CliTest::SetUp();
        useMockRuntime();
    }
    void TearDown() override {
        ::unsetenv("XR_ENABLE_API_LAYERS");
        ::hg::test::CliTest::TearDown();
    }
};

bool coreValidationInstalled() {
    return std::filesystem::exists("/usr/share/openxr/1/api_layers/explicit.d/XrApiLayer_core_validation.x86_64-linux-gnu.json");
}

TEST_F(XrCli, NoRuntimeSaysSoAndPointsToTheDesktop) {
    ::setenv("XR_RUNTIME_JSON", (dir / "no_such_runtime.json").c_str(), 1);
    const auto r = ::hg::test::runHypergarden("--xr --frames 3");
    EXPECT_EQ(r.status, kExitNoRuntime) << r.output;
    EXPECT_NE(r.output.find("error: no OpenXR runtime"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("run hypergarden without --xr for the desktop"), std::string::npos) << r.output;
}

TEST_F(XrCli, RunsFramesIntoASessionFolder) {
    HG_REQUIRE_DISPLAY();
    const std::string garden = garden::test::writeSmallGarden(dir / "garden");
    const auto r = ::hg::test::runHypergarden("--xr --frames 6 --garden " + path("garden/garden.json") + " --session " +
                                              path("session"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("OpenXR runtime: Hypergarden mock runtime"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("xr: 6 frames"), std::string::npos) << r.output;
    EXPECT_TRUE(exists("session/garden.json")) << "the session folder was made";
}

TEST_F(XrCli, CoreValidationLayerFindsNoErrors) {
    HG_REQUIRE_DISPLAY();
    if (!coreValidationInstalled()) GTEST_SKIP() << "openxr-layer-corevalidation is not installed";
    garden::test::writeSmallGarden(dir);
    // A carve with the right hand while the left squeezes: every action read.
    std::ofstream(dir / "carve.json") << R"({"garden": "garden.json", "steps": [
      {"frames": 2, "commands": [{"sculpt_tool": {"kind": "carve", "radius": 0.12}}]},
      {"frames": 6, "tool": {"aim": {"position": [0.3, 1.2, -0.4], "direction": [-0.03, -0.07, -1]}, "trigger": 1},
       "navigation": {"aim": {"position": [-0.3, 1.0, -0.3]}, "squeeze": 1, "thumbstick": [0.9, 0.2]}},
      {"frames": 3}]})";
    ::setenv("HG_MOCK_XR_SCRIPT", (dir / "carve.json").c_str(), 1);
    ::setenv("XR_ENABLE_API_LAYERS", "XR_APILAYER_LUNARG_core_validation", 1);
    // The Debian layer (1.0.20) predates XR_EXT_local_floor: the runtime
    // does not offer it here (the next test offers it).
    ::setenv("HG_MOCK_XR_NO_LOCAL_FLOOR", "1", 1);
    const auto r = ::hg::test::runHypergarden("--xr --script " + path("carve.json"));
    ::unsetenv("HG_MOCK_XR_NO_LOCAL_FLOOR");
    // An unknown layer would fail xrCreateInstance: status 0 says it ran.
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("VALID_ERROR"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("xr: "), std::string::npos) << r.output;
}

TEST_F(XrCli, ALayerThatRefusesLocalFloorLeavesTheStage) {
    HG_REQUIRE_DISPLAY();
    if (!coreValidationInstalled()) GTEST_SKIP() << "openxr-layer-corevalidation is not installed";
    // The runtime offers XR_EXT_local_floor; the 1.0.20 layer calls its
    // enum invalid and refuses the space: the session runs on the stage.
    garden::test::writeSmallGarden(dir);
    ::setenv("XR_ENABLE_API_LAYERS", "XR_APILAYER_LUNARG_core_validation", 1);
    const auto r = ::hg::test::runHypergarden("--xr --frames 6 --garden " + path("garden.json"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("VUID-XrReferenceSpaceCreateInfo-referenceSpaceType-parameter"), std::string::npos)
        << "the layer's refusal: " << r.output;
    EXPECT_NE(r.output.find("xr: 6 frames"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("space STAGE"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace hg::xr::test
