// The save banner (garden/render/save_banner.cpp) on a real session folder,
// driven headless: nothing while everything is saved; after a journal
// write fails (the write seam, ENOSPC) the red banner shows and its Retry
// button, clicked with a synthetic mouse once the disk has room, writes
// what was held and the banner goes. And the screenshot write site: a
// failed write is a message naming the file and the reason, and no file.
#include <gtest/gtest.h>

#include <imgui.h>
#include <imgui_internal.h>

#include <cerrno>
#include <filesystem>
#include <optional>

#include "../garden/session_garden.h"
#include "garden/render/panels.h"
#include "garden/render/screenshot.h"
#include "garden/session/open_session.h"
#include "headless_imgui.h"
#include "io/write_faults.h"
#include "tests/disk_full.h"

namespace hg::garden {
namespace {

class SaveBannerTest : public test::SmallGarden {
protected:
    void SetUp() override {
        test::SmallGarden::SetUp();
        createHeadlessImGui(ImVec2(1280, 720));
    }
    void TearDown() override {
        io::setFaultPlan(std::nullopt);
        ImGui::DestroyContext();
        test::SmallGarden::TearDown();
    }
    // One frame; whether the banner showed and the item hovered.
    bool frame(GardenSession& s, ImVec2 mouse, bool down, ImGuiID* hovered = nullptr) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = mouse;
        io.MouseDown[0] = down;
        ImGui::NewFrame();
        const bool shown = drawSaveBanner(s, {320.0f, 10.0f}, 640.0f);
        if (hovered) *hovered = ImGui::GetCurrentContext()->HoveredId;
        ImGui::Render();
        return shown;
    }
    std::optional<ImVec2> findRetry(GardenSession& s) {
        const ImGuiWindow* w = ImGui::FindWindowByName("##save banner");
        if (!w) return std::nullopt;
        const ImGuiID id = ImHashStr("Retry saving", 0, w->ID);
        for (float y = w->Pos.y; y < w->Pos.y + w->Size.y; y += 3.0f)
            for (float x = w->Pos.x; x < w->Pos.x + w->Size.x; x += 6.0f) {
                ImGuiID h = 0;
                frame(s, {x, y}, false, &h);
                if (h == id) return ImVec2(x, y);
            }
        return std::nullopt;
    }
};

TEST_F(SaveBannerTest, AFailedWriteShowsTheBannerAndRetryClearsIt) {
    OpenedSession o = openSession({(dir / "session").string(), writeGarden()}, test::smallSessionSettings());
    ASSERT_EQ(o.error, "");
    GardenSession& s = *o.session;
    const auto stroke = [&](double y) {
        ASSERT_EQ(s.applyStroke(s.findSculpture("a"), StrokeTool::Carve, {{-0.2, y, -1.8}, {0.2, y, -1.8}}, 0.06), "");
    };
    stroke(0.6);
    EXPECT_FALSE(frame(s, {0, 0}, false));
    EXPECT_FALSE(frame(s, {0, 0}, false));
    io::setFaultPlan(::hg::test::diskFullAt(io::WriteSite::Journal));
    stroke(0.65);
    stroke(0.7);
    EXPECT_TRUE(frame(s, {0, 0}, false));
    EXPECT_TRUE(frame(s, {0, 0}, false));  // an auto-sized window settles on its second frame
    const ImGuiWindow* w = ImGui::FindWindowByName("##save banner");
    ASSERT_TRUE(w);
    EXPECT_TRUE(w->Active);
    EXPECT_GT(w->Size.y, 40.0f);  // the headline and the button
    std::optional<ImVec2> retry = findRetry(s);
    ASSERT_TRUE(retry);
    // Clicked while the disk is still full: still not saved.
    frame(s, *retry, true);
    frame(s, *retry, false);
    EXPECT_EQ(s.journal()->saveStatus().state, SaveStatus::State::NotSaved);
    EXPECT_EQ(s.journal()->saveStatus().unsaved, 2u);
    // Room again: the click writes both, in order, and the banner goes.
    io::setFaultPlan(std::nullopt);
    frame(s, *retry, true);
    frame(s, *retry, false);
    EXPECT_TRUE(s.journal()->saveStatus().saved());
    EXPECT_FALSE(frame(s, {0, 0}, false));
    EXPECT_EQ(readJournal(o.recorder->paths().journal).records.size(), 3u);
}

TEST_F(SaveBannerTest, AReadOnlySessionShowsItsBannerWithoutRetry) {
    const std::string folder = (dir / "session").string();
    {
        OpenedSession o = openSession({folder, writeGarden()}, test::smallSessionSettings());
        ASSERT_EQ(o.error, "");
        ASSERT_EQ(o.session->applyStroke(o.session->findSculpture("a"), StrokeTool::Carve, {{-0.2, 0.6, -1.8}}, 0.06), "");
    }
    {
        const std::string json = actionJson(RedoAction{});
        char crc[16];
        std::snprintf(crc, sizeof crc, "%08x ", crc32(json));
        std::ofstream(SessionPaths(folder).journal, std::ios::app | std::ios::binary) << crc << json << "\n";
    }
    OpenedSession o = openSession({folder, writeGarden()}, test::smallSessionSettings());
    ASSERT_EQ(o.error, "");
    EXPECT_TRUE(frame(*o.session, {0, 0}, false));
    EXPECT_TRUE(frame(*o.session, {0, 0}, false));
    EXPECT_FALSE(findRetry(*o.session));
}

TEST_F(SaveBannerTest, AFailedScreenshotWriteIsToldAndLeavesNoFile) {
    const std::vector<std::uint8_t> rgba(16 * 16 * 4, 200);
    const std::string path = (dir / "shot.png").string();
    for (int error : {ENOSPC, EIO, EDQUOT, EROFS, EFBIG}) {
        io::FaultPlan p;
        p.anySite = false;
        p.site = io::WriteSite::Screenshot;
        p.error = error;
        io::setFaultPlan(p);
        const std::string why = writePng(path, 16, 16, rgba);
        EXPECT_NE(why.find(std::strerror(error)), std::string::npos) << why;
        EXPECT_NE(why.find(path), std::string::npos) << why;
        EXPECT_FALSE(std::filesystem::exists(path));
    }
    io::setFaultPlan(std::nullopt);
    EXPECT_EQ(writePng(path, 16, 16, rgba), "");
    EXPECT_TRUE(std::filesystem::exists(path));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);  // no temporary left
}

}  // namespace
}  // namespace hg::garden
