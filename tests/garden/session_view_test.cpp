// A session remembers the view (issue 23): DIR/view.json written from the
// navigator and read back into another, the pose the same; a session
// without one opens at the garden's start; a broken one is named with its
// place and changes nothing.
#include <gtest/gtest.h>

#include "garden/app/navigator.h"
#include "garden/session/session_view.h"
#include "garden_test_util.h"

namespace hg::garden {
namespace {

class SessionViewTest : public test::ScratchDir {};

TEST_F(SessionViewTest, TheViewIsWrittenAndReadBack) {
    Navigator left;
    left.setMode(NavigationMode::Fly);
    left.setPose({1.25f, 2.5f, -3.75f}, 0.7f, -0.3f);
    ASSERT_EQ(writeSessionView(dir.string(), left), "");
    Navigator reopened;
    std::string warning;
    ASSERT_TRUE(readSessionView(dir.string(), reopened, warning)) << warning;
    EXPECT_EQ(warning, "");
    EXPECT_EQ(reopened.mode(), NavigationMode::Fly);
    EXPECT_NEAR(reopened.eye().x, 1.25f, 1e-5f);
    EXPECT_NEAR(reopened.eye().y, 2.5f, 1e-5f);
    EXPECT_NEAR(reopened.eye().z, -3.75f, 1e-5f);
    EXPECT_NEAR(reopened.yaw(), 0.7f, 1e-5f);
    EXPECT_NEAR(reopened.pitch(), -0.3f, 1e-5f);

    // Walking stays walking (at eye height).
    left.setMode(NavigationMode::Walk);
    ASSERT_EQ(writeSessionView(dir.string(), left), "");
    ASSERT_TRUE(readSessionView(dir.string(), reopened, warning));
    EXPECT_EQ(reopened.mode(), NavigationMode::Walk);
}

TEST_F(SessionViewTest, NoViewOpensAtTheStartAndABrokenOneIsNamed) {
    Navigator n;
    n.setPose({4.0f, 1.7f, 4.0f}, 0.1f, 0.0f);
    std::string warning = "stale";
    EXPECT_FALSE(readSessionView(dir.string(), n, warning));
    EXPECT_EQ(warning, "") << "a session without a view yet is not a fault";
    write(kSessionViewFile, R"({"mode": "fly", "eye": [1, 2], "yaw": 0, "pitch": 0})");
    EXPECT_FALSE(readSessionView(dir.string(), n, warning));
    EXPECT_NE(warning.find("view.json"), std::string::npos) << warning;
    EXPECT_NE(warning.find("$.eye"), std::string::npos) << warning;
    EXPECT_NEAR(n.eye().x, 4.0f, 1e-6f) << "left as it was";
    write(kSessionViewFile, R"({"mode": "swim", "eye": [1, 2, 3], "yaw": 0, "pitch": 0})");
    EXPECT_FALSE(readSessionView(dir.string(), n, warning));
    EXPECT_NE(warning.find("$.mode"), std::string::npos) << warning;
    write(kSessionViewFile, "{\"mode\": \"fly\",");
    EXPECT_FALSE(readSessionView(dir.string(), n, warning));
    EXPECT_NE(warning.find("view.json"), std::string::npos) << warning;
}

}  // namespace
}  // namespace hg::garden
