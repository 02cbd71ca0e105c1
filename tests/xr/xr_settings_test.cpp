// The headset's user settings file (xr/xr_settings.h): written and read
// back (turning and the seated height too), the defaults without a file
// and for keys an older file lacks, a bad file or value named with its
// place and the defaults kept, the path from the environment.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/write_faults.h"
#include "xr/xr_settings.h"

namespace hg::xr {
namespace {

class XrSettings : public ::testing::Test {
protected:
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              ("hg_xr_settings_" + std::to_string(::getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::filesystem::path dir;
};

TEST_F(XrSettings, SavedSettingsReadBackAndTheFolderIsMade) {
    const std::string path = (dir / "hypergarden" / "xr.json").string();
    std::string warning = "x";
    const XrUserSettings none = loadXrSettings(path, warning);
    EXPECT_FALSE(none.leftHanded);
    EXPECT_FALSE(none.seated);
    EXPECT_EQ(warning, "") << "no file yet: the defaults, quietly";
    XrUserSettings s;
    s.leftHanded = true;
    ASSERT_EQ(saveXrSettings(path, s), "");
    XrUserSettings back = loadXrSettings(path, warning);
    EXPECT_TRUE(back.leftHanded);
    EXPECT_FALSE(back.seated);
    s.leftHanded = false;
    s.seated = true;
    ASSERT_EQ(saveXrSettings(path, s), "");
    back = loadXrSettings(path, warning);
    EXPECT_FALSE(back.leftHanded);
    EXPECT_TRUE(back.seated);
    for (const auto& e : std::filesystem::directory_iterator(dir / "hypergarden"))
        EXPECT_EQ(e.path().filename(), "xr.json") << "no temporary file left behind";
}

TEST_F(XrSettings, ABadFileSaysWhereAndKeepsTheDefaults) {
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "xr.json").string();
    std::ofstream(path) << R"({"left_handed": true, "seated": "yes"})";
    std::string warning;
    const XrUserSettings s = loadXrSettings(path, warning);
    EXPECT_FALSE(s.leftHanded) << "nothing half-read";
    EXPECT_NE(warning.find(path), std::string::npos) << warning;
    EXPECT_NE(warning.find("$.seated"), std::string::npos) << warning;
    std::ofstream(path) << "{\n  \"seated\": tru\n}";
    loadXrSettings(path, warning);
    EXPECT_NE(warning.find("line 2"), std::string::npos) << warning;
}

TEST_F(XrSettings, TurningAndTheSeatedHeightReadBack) {
    const std::string path = (dir / "xr.json").string();
    XrUserSettings s;
    s.smoothTurn = true;
    s.snapDegrees = 45;
    s.seatedHeightOffset = 0.35;
    ASSERT_EQ(saveXrSettings(path, s), "");
    std::string warning;
    const XrUserSettings back = loadXrSettings(path, warning);
    EXPECT_EQ(warning, "");
    EXPECT_TRUE(back.smoothTurn);
    EXPECT_EQ(back.snapDegrees, 45);
    EXPECT_DOUBLE_EQ(back.seatedHeightOffset, 0.35);
    EXPECT_FALSE(back.leftHanded);
}

TEST_F(XrSettings, AnOlderFileWithoutTheNewKeysReadsWithTheirDefaults) {
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "xr.json").string();
    std::ofstream(path) << R"({"left_handed": true, "seated": true})";
    std::string warning;
    const XrUserSettings s = loadXrSettings(path, warning);
    EXPECT_EQ(warning, "");
    EXPECT_TRUE(s.leftHanded);
    EXPECT_TRUE(s.seated);
    const XrUserSettings defaults;
    EXPECT_EQ(s.smoothTurn, defaults.smoothTurn);
    EXPECT_EQ(s.snapDegrees, 30);
    EXPECT_DOUBLE_EQ(s.seatedHeightOffset, 0.5);
}

TEST_F(XrSettings, TurningAndHeightOutOfRangeAreNamedWithTheirPlace) {
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "xr.json").string();
    for (const auto& [text, place] : {std::pair<const char*, const char*>{R"({"snap_degrees": 20})", "$.snap_degrees"},
                                      {R"({"snap_degrees": 30.5})", "$.snap_degrees"},
                                      {R"({"seated_height_offset": -0.1})", "$.seated_height_offset"},
                                      {R"({"seated_height_offset": 3})", "$.seated_height_offset"},
                                      {R"({"smooth_turn": 1})", "$.smooth_turn"}}) {
        std::ofstream(path) << text;
        std::string warning;
        const XrUserSettings s = loadXrSettings(path, warning);
        EXPECT_NE(warning.find(path), std::string::npos) << text << ": " << warning;
        EXPECT_NE(warning.find(place), std::string::npos) << text << ": " << warning;
        EXPECT_EQ(s.snapDegrees, 30) << text;
        EXPECT_DOUBLE_EQ(s.seatedHeightOffset, 0.5) << text;
    }
}

TEST_F(XrSettings, ThePathFollowsTheEnvironment) {
    ::setenv("HG_XR_SETTINGS", "/somewhere/xr.json", 1);
    EXPECT_EQ(xrSettingsPath(), "/somewhere/xr.json");
    ::unsetenv("HG_XR_SETTINGS");
    ::setenv("XDG_CONFIG_HOME", "/config", 1);
    EXPECT_EQ(xrSettingsPath(), "/config/hypergarden/xr.json");
    ::unsetenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    if (home) {
        EXPECT_EQ(xrSettingsPath(), std::string(home) + "/.config/hypergarden/xr.json");
    }
}

// A settings write that fails (the write seam, every errno) says why and
// keeps the settings the file held.
TEST_F(XrSettings, AFailedWriteKeepsTheOldSettingsAndSaysWhy) {
    const std::string path = (dir / "xr.json").string();
    XrUserSettings s;
    s.seated = true;
    ASSERT_EQ(saveXrSettings(path, s), "");
    for (int error : {ENOSPC, EIO, EDQUOT, EROFS, EFBIG}) {
        io::FaultPlan p;
        p.anySite = false;
        p.site = io::WriteSite::Settings;
        p.error = error;
        io::setFaultPlan(p);
        XrUserSettings changed;
        changed.leftHanded = true;
        const std::string why = saveXrSettings(path, changed);
        io::setFaultPlan(std::nullopt);
        EXPECT_NE(why.find(std::strerror(error)), std::string::npos) << why;
        std::string warning;
        const XrUserSettings kept = loadXrSettings(path, warning);
        EXPECT_TRUE(kept.seated);
        EXPECT_FALSE(kept.leftHanded);
        EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
    }
}

}  // namespace
}  // namespace hg::xr
