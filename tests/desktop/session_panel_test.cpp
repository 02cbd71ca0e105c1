// Sessions remember the view, and the desktop's Session section (issue 23):
// the recent sessions kept under $XDG_CONFIG_HOME/hypergarden (newest
// first, once each, at most kRecentSessions); Duplicate and Save As copy
// the session with the current view; a desktop run on a session writes its
// view when it closes and the next run opens there. The config folder is
// the test's own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include <imgui.h>
#include <imgui_internal.h>

#include "garden/app/garden_session.h"
#include "garden/desktop/desktop_app.h"
#include "garden/desktop/recent_sessions.h"
#include "garden/desktop/session_panel.h"
#include "garden/session/open_session.h"
#include "garden/session/session_view.h"
#include "tests/garden/session_garden.h"
#include "tests/render/gl_fixture.h"
#include "tests/render/headless_imgui.h"

namespace hg::garden {
namespace {

class SessionPanelTest : public test::SmallGarden {
protected:
    void SetUp() override {
        SmallGarden::SetUp();
        if (const char* x = std::getenv("XDG_CONFIG_HOME")) savedConfig = x;
        ::setenv("XDG_CONFIG_HOME", (dir / "config").c_str(), 1);
        ::unsetenv("HG_RECENT_SESSIONS");
    }
    void TearDown() override {
        if (savedConfig) ::setenv("XDG_CONFIG_HOME", savedConfig->c_str(), 1);
        else ::unsetenv("XDG_CONFIG_HOME");
        SmallGarden::TearDown();
    }
    // A small window on session folder `session` for `frames` frames, its
    // desktop settings file the test's own.
    DesktopOptions smallWindow(const std::string& garden, const std::string& session, int frames) const {
        DesktopOptions o;
        o.garden = garden;
        o.session = (dir / session).string();
        o.width = 320;
        o.height = 240;
        o.vsync = false;
        o.frames = frames;
        o.settingsPath = (dir / "desktop.json").string();
        return o;
    }
    std::optional<std::string> savedConfig;
};

TEST_F(SessionPanelTest, RecentSessionsAreKeptInTheConfigFolderNewestFirstOnceEach) {
    const std::string path = recentSessionsPath();
    EXPECT_EQ(std::filesystem::path(path), dir / "config" / "hypergarden" / "recent-sessions.json");
    std::string warning;
    EXPECT_TRUE(loadRecentSessions(path, warning).empty());
    for (int i = 0; i < 10; ++i) ASSERT_EQ(rememberSession(path, (dir / ("s" + std::to_string(i))).string()), "");
    ASSERT_EQ(rememberSession(path, (dir / "s5").string()), "");
    std::vector<std::string> list = loadRecentSessions(path, warning);
    ASSERT_EQ(list.size(), kRecentSessions);
    EXPECT_EQ(std::filesystem::path(list[0]), dir / "s5");
    EXPECT_EQ(std::filesystem::path(list[1]), dir / "s9");
    EXPECT_EQ(std::count(list.begin(), list.end(), list[0]), 1);
    // A relative folder is kept absolute.
    const auto here = std::filesystem::current_path();
    std::filesystem::current_path(dir);
    ASSERT_EQ(rememberSession(path, "rel"), "");
    std::filesystem::current_path(here);
    EXPECT_EQ(std::filesystem::path(loadRecentSessions(path, warning)[0]), dir / "rel");
    // A broken file: named, and an empty list.
    write("config/hypergarden/recent-sessions.json", R"({"sessions": [1]})");
    EXPECT_TRUE(loadRecentSessions(path, warning).empty());
    EXPECT_NE(warning.find("$.sessions[0]"), std::string::npos) << warning;
}

TEST_F(SessionPanelTest, DuplicateAndSaveAsCopyTheSessionWithTheView) {
    const std::string garden = writeGarden();
    OpenedSession opened = openSession({(dir / "mine").string(), garden}, test::smallSessionSettings());
    ASSERT_EQ(opened.error, "");
    GardenSession& s = *opened.session;
    const int c = s.findSculpture("c");
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Carve, {{2.45, 0.9, 1.3}, {2.5, 0.6, 1.4}}, 0.1), "");
    s.navigator().setMode(NavigationMode::Fly);
    s.navigator().setPose({1.0f, 3.0f, 2.0f}, 0.4f, -0.2f);
    SessionPanel panel(recentSessionsPath());
    panel.opened(opened.recorder->paths().dir);
    ASSERT_EQ(panel.recent().size(), 1u);

    ASSERT_EQ(panel.duplicate(s, *opened.recorder, (dir / "copy").string()), "");
    EXPECT_NE(panel.status().find("copied the session"), std::string::npos);
    Navigator n;
    std::string warning;
    ASSERT_TRUE(readSessionView((dir / "copy").string(), n, warning)) << warning;
    EXPECT_NEAR(n.eye().y, 3.0f, 1e-5f);
    EXPECT_EQ(folderKind((dir / "copy").string()), FolderKind::Session);

    EXPECT_EQ(panel.saveAs(s, *opened.recorder, (dir / "copy").string()), "") << "not an empty folder";
    EXPECT_NE(panel.status().find("not a new or empty folder"), std::string::npos) << panel.status();
    EXPECT_EQ(panel.saveAs(s, *opened.recorder, (dir / "as").string()), (dir / "as").string());
    OpenedSession as = openSession({(dir / "as").string(), garden}, test::smallSessionSettings());
    ASSERT_EQ(as.error, "");
    EXPECT_EQ(as.session->editCount(c), 1u);
}

TEST_F(SessionPanelTest, ADesktopRunKeepsTheViewAndTheNextOpensThere) {
    HG_REQUIRE_DISPLAY();
    DesktopOptions o = smallWindow(writeGarden(), "week", 3);
    o.onFrame = [](GardenSession& s, int frame) {
        if (frame == 0) {
            s.navigator().setMode(NavigationMode::Fly);
            s.navigator().setPose({-1.5f, 2.25f, 3.0f}, 1.0f, 0.25f);
        }
        return false;
    };
    ASSERT_EQ(runDesktopGarden(o), 0);
    EXPECT_TRUE(std::filesystem::exists(dir / "week" / kSessionViewFile));
    std::string warning;
    const std::vector<std::string> recent = loadRecentSessions(recentSessionsPath(), warning);
    ASSERT_EQ(recent.size(), 1u);
    EXPECT_EQ(std::filesystem::path(recent[0]), dir / "week");

    std::optional<glm::vec3> eye;
    float yaw = 0.0f;
    o.onFrame = [&](GardenSession& s, int frame) {
        if (frame == 0) {
            eye = s.navigator().eye();
            yaw = s.navigator().yaw();
        }
        return false;
    };
    ASSERT_EQ(runDesktopGarden(o), 0);
    ASSERT_TRUE(eye);
    EXPECT_NEAR(eye->x, -1.5f, 1e-4f);
    EXPECT_NEAR(eye->y, 2.25f, 1e-4f);
    EXPECT_NEAR(eye->z, 3.0f, 1e-4f);
    EXPECT_NEAR(yaw, 1.0f, 1e-4f);
}


// The panel layout goes with the session: a panel moved and collapsed in
// one run stands there, collapsed, in the next run on the same session (a
// real window and ImGui context each time); a session whose view.json has
// no layout opens with the defaults.
TEST_F(SessionPanelTest, APanelMovedInASessionIsWhereItWasWhenTheSessionReopens) {
    HG_REQUIRE_DISPLAY();
    DesktopOptions o = smallWindow(writeGarden(), "layout", 3);
    std::optional<ImVec2> defaultPos;
    o.onFrame = [&](GardenSession&, int frame) {
        ImGuiWindow* garden = ImGui::FindWindowByName("Garden");
        if (frame == 0 && garden) defaultPos = garden->Pos;
        if (frame == 1) {
            ImGui::SetWindowPos("Garden", ImVec2(131.0f, 47.0f));
            ImGui::SetWindowCollapsed("Garden", true);
        }
        return false;
    };
    ASSERT_EQ(runDesktopGarden(o), 0);
    ASSERT_TRUE(defaultPos);
    ASSERT_FALSE(defaultPos->x == 131.0f && defaultPos->y == 47.0f) << "the test must move it";
    std::string warning;
    Navigator n;
    std::optional<std::string> panels;
    ASSERT_TRUE(readSessionView((dir / "layout").string(), n, warning, nullptr, &panels)) << warning;
    ASSERT_TRUE(panels);
    EXPECT_NE(panels->find("[Window][Garden]"), std::string::npos) << *panels;

    std::optional<ImVec2> pos;
    bool collapsed = false;
    o.onFrame = [&](GardenSession&, int frame) {
        if (frame == 0)
            if (ImGuiWindow* garden = ImGui::FindWindowByName("Garden")) {
                pos = garden->Pos;
                collapsed = garden->Collapsed;
            }
        return false;
    };
    ASSERT_EQ(runDesktopGarden(o), 0);
    ASSERT_TRUE(pos);
    EXPECT_EQ(pos->x, 131.0f);
    EXPECT_EQ(pos->y, 47.0f);
    EXPECT_TRUE(collapsed);

    // A view.json from before layouts were kept: the defaults.
    ASSERT_EQ(writeSessionView((dir / "layout").string(), n), "");
    ASSERT_EQ(runDesktopGarden(o), 0);
    ASSERT_TRUE(pos);
    EXPECT_EQ(pos->x, defaultPos->x);
    EXPECT_EQ(pos->y, defaultPos->y);
    EXPECT_FALSE(collapsed);
}

// Going on in another session from a running window (Save As, a recent
// session): it is opened, this one closed (its lock released, its view
// kept), and the window goes on with the other's garden and edits.
TEST_F(SessionPanelTest, TheWindowGoesOnInAnotherSessionAndClosesThisOne) {
    HG_REQUIRE_DISPLAY();
    const std::string garden = writeGarden();
    const std::string other = (dir / "other").string();
    {
        OpenedSession b = openSession({other, garden}, test::smallSessionSettings());
        ASSERT_EQ(b.error, "");
        ASSERT_EQ(b.session->applyStroke(b.session->findSculpture("c"), StrokeTool::Carve,
                                         {{2.45, 0.9, 1.3}, {2.5, 0.6, 1.4}}, 0.1),
                  "");
    }
    DesktopOptions o = smallWindow(garden, "first", 4);
    bool asked = false;
    o.goToSession = [&](int frame) {
        if (frame != 1 || asked) return std::string();
        asked = true;
        return other;
    };
    std::vector<std::size_t> edits;
    std::string firstOpenAgain = "not tried";
    o.onFrame = [&](GardenSession& s, int) {
        edits.push_back(s.editCount(s.findSculpture("c")));
        // In the other session (its stroke shows), the first is closed.
        if (edits.back() == 1u && firstOpenAgain == "not tried")
            firstOpenAgain = openSession({(dir / "first").string(), garden}, test::smallSessionSettings()).error;
        return false;
    };
    ASSERT_EQ(runDesktopGarden(o), 0);
    ASSERT_GE(edits.size(), 6u) << "frames in both sessions";
    EXPECT_EQ(edits.front(), 0u) << "the first session has no edits";
    EXPECT_EQ(edits.back(), 1u) << "the other session's stroke";
    EXPECT_EQ(firstOpenAgain, "") << "the first session was closed: its lock is free";
    EXPECT_TRUE(std::filesystem::exists(dir / "first" / kSessionViewFile)) << "its view kept";
    std::string warning;
    const std::vector<std::string> recent = loadRecentSessions(recentSessionsPath(), warning);
    ASSERT_EQ(recent.size(), 2u);
    EXPECT_EQ(std::filesystem::path(recent[0]), dir / "other");
    EXPECT_EQ(std::filesystem::path(recent[1]), dir / "first");
}

// The section drawn through ImGui without a window: its buttons, clicked
// with a synthetic mouse, copy and name the folder to go on in.
class SessionPanelClicks : public SessionPanelTest {
protected:
    void SetUp() override {
        SessionPanelTest::SetUp();
        createHeadlessImGui(ImVec2(1280, 720));
    }
    void TearDown() override {
        ImGui::DestroyContext();
        SessionPanelTest::TearDown();
    }
    // One frame; the item hovered and what draw() returned.
    std::pair<ImGuiID, std::string> frame(ImVec2 mouse, bool down) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = mouse;
        io.MouseDown[0] = down;
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::Begin("Garden", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::SetNextItemOpen(true);
        const std::string goTo = panel->draw(*session, recorder);
        ImGui::End();
        const ImGuiID hovered = ImGui::GetCurrentContext()->HoveredId;
        ImGui::Render();
        return {hovered, goTo};
    }
    // Clicks the item `id`: what draw() returned on the release; none when
    // the item is not shown.
    std::optional<std::string> click(ImGuiID id) {
        for (int i = 0; i < 2; ++i) frame({0, 0}, false);  // an auto-sized window shows from its second frame
        const ImGuiWindow* w = ImGui::FindWindowByName("Garden");
        for (float y = w->Pos.y; y < w->Pos.y + w->Size.y; y += 3.0f)
            for (float x = w->Pos.x; x < w->Pos.x + w->Size.x; x += 4.0f)
                if (frame({x, y}, false).first == id) {
                    frame({x, y}, true);
                    return frame({x, y}, false).second;
                }
        return std::nullopt;
    }
    static ImGuiID idOf(const char* label, const std::string& scope = "") {
        const ImGuiID window = ImGui::FindWindowByName("Garden")->ID;
        return ImHashStr(label, 0, scope.empty() ? window : ImHashStr(scope.c_str(), 0, window));
    }
    std::unique_ptr<GardenSession> session;
    const SessionRecorder* recorder = nullptr;
    std::unique_ptr<SessionPanel> panel;
};

TEST_F(SessionPanelClicks, OpenNamesARecentSessionAndSaveAsTheCopy) {
    const std::string garden = writeGarden();
    const std::string other = (dir / "other").string();
    ASSERT_EQ(openSession({other, garden}, test::smallSessionSettings()).error, "");
    OpenedSession opened = openSession({(dir / "mine").string(), garden}, test::smallSessionSettings());
    ASSERT_EQ(opened.error, "");
    ASSERT_EQ(rememberSession(recentSessionsPath(), other), "");
    panel = std::make_unique<SessionPanel>(recentSessionsPath());
    panel->opened(opened.recorder->paths().dir);
    recorder = opened.recorder.get();
    session = std::move(opened.session);
    frame({0, 0}, false);
    const std::string otherAbsolute = std::filesystem::absolute(other).lexically_normal().string();
    const auto opens = click(idOf("open", otherAbsolute));
    ASSERT_TRUE(opens) << "the other session is listed with an open button";
    EXPECT_EQ(*opens, otherAbsolute);

    panel->setFolder((dir / "saved").string());
    const auto saves = click(idOf("Save As"));
    ASSERT_TRUE(saves);
    EXPECT_EQ(*saves, (dir / "saved").string());
    EXPECT_EQ(folderKind((dir / "saved").string()), FolderKind::Session);
    opened.session = std::move(session);
}

TEST_F(SessionPanelClicks, WithoutASessionFolderOpeningAnotherWaitsForUnsavedWork) {
    const std::string garden = writeGarden();
    const std::string other = (dir / "other").string();
    ASSERT_EQ(openSession({other, garden}, test::smallSessionSettings()).error, "");
    ASSERT_EQ(rememberSession(recentSessionsPath(), other), "");
    panel = std::make_unique<SessionPanel>(recentSessionsPath());
    session = std::make_unique<GardenSession>(loadGarden(garden), test::smallSessionSettings());
    frame({0, 0}, false);
    const ImGuiID open = idOf("open", std::filesystem::absolute(other).lexically_normal().string());
    EXPECT_FALSE(click(idOf("Save As"))) << "no Save As without a session folder";
    // Nothing made here yet: another session may be opened.
    auto opens = click(open);
    ASSERT_TRUE(opens);
    EXPECT_FALSE(opens->empty());
    // A stroke that no folder holds: the button is disabled.
    const int c = session->findSculpture("c");
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Carve, {{2.45, 0.9, 1.3}, {2.5, 0.6, 1.4}}, 0.1), "");
    opens = click(open);
    EXPECT_TRUE(!opens || opens->empty()) << "disabled: the stroke would be lost";
}

}  // namespace
}  // namespace hg::garden
