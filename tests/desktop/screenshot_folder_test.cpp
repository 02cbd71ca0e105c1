// Where F12 screenshots go (screenshotFolder): the folder the user named,
// else the session's screenshots/ folder, else ~/Pictures/hypergarden;
// made when missing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "garden/desktop/desktop_app.h"
#include "tests/garden/garden_test_util.h"

namespace hg::garden {
namespace {

class ScreenshotFolderTest : public test::ScratchDir {};

TEST_F(ScreenshotFolderTest, NamedThenSessionThenPictures) {
    DesktopOptions o;
    o.screenshotDir = (dir / "shots").string();
    o.session = (dir / "session").string();
    EXPECT_EQ(screenshotFolder(o), o.screenshotDir);
    EXPECT_TRUE(std::filesystem::is_directory(dir / "shots"));
    o.screenshotDir.clear();
    EXPECT_EQ(std::filesystem::path(screenshotFolder(o)), dir / "session" / "screenshots");
    EXPECT_TRUE(std::filesystem::is_directory(dir / "session" / "screenshots"));
    o.session.clear();
    const char* home = std::getenv("HOME");
    const std::string saved = home ? home : "";
    ::setenv("HOME", (dir / "home").string().c_str(), 1);
    EXPECT_EQ(std::filesystem::path(screenshotFolder(o)), dir / "home" / "Pictures" / "hypergarden");
    EXPECT_TRUE(std::filesystem::is_directory(dir / "home" / "Pictures" / "hypergarden"));
    if (home) ::setenv("HOME", saved.c_str(), 1);
    else ::unsetenv("HOME");
}

}  // namespace
}  // namespace hg::garden
