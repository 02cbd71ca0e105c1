// The desktop's Export panel: the selected sculpture written next to the
// session (or into the folder typed), HyperFun at once and a mesh on a
// worker thread while the garden goes on, which Cancel stops with nothing
// written; refusals say why and write nothing.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <imgui.h>

#include "garden/app/garden_session.h"
#include "garden/desktop/export_panel.h"
#include "garden/export/hyperfun_export.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"
#include "tests/garden/session_garden.h"
#include "tests/render/headless_imgui.h"

namespace hg::garden {
namespace {

class ExportPanelTest : public test::SmallGarden {
protected:
    std::unique_ptr<GardenSession> open() {
        SessionSettings settings;
        settings.maxLevel = 0;
        return std::make_unique<GardenSession>(loadGarden(writeGarden()), settings);
    }
    static void finish(ExportPanel& panel) {
        const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (panel.busy() && std::chrono::steady_clock::now() < giveUp)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        ASSERT_FALSE(panel.busy());
    }
    static std::string read(const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
};

TEST_F(ExportPanelTest, TheSelectedSculptureIsWrittenNextToTheSessionInThePickedFormat) {
    auto session = open();
    const int c = session->findSculpture("c");
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Carve, {{1.7, 0.9, 1.5}, {2.3, 0.9, 1.5}}, 0.1), "");
    ExportPanel panel((dir / "session").string());

    ASSERT_TRUE(panel.start(*session, c, ".hf", 0)) << panel.status();
    finish(panel);
    EXPECT_EQ(panel.status().rfind("wrote ", 0), 0u) << panel.status();
    const std::filesystem::path hf = panel.lastPath();
    EXPECT_EQ(hf.parent_path(), dir / "session" / "exports");
    EXPECT_EQ(read(hf.string()), exportHyperFun(*session, c).text);

    ASSERT_TRUE(panel.start(*session, c, ".stl", 48)) << panel.status();
    // The garden goes on while the mesh is made: the session is not read again.
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Add, {{1.7, 0.3, 1.5}, {2.3, 0.3, 1.5}}, 0.1), "");
    finish(panel);
    EXPECT_EQ(panel.status().rfind("wrote ", 0), 0u) << panel.status();
    const poly::StlReadResult stl = poly::readStl(panel.lastPath());
    ASSERT_EQ(stl.error, "");
    EXPECT_TRUE(poly::validateMesh(poly::weldByPosition(stl.mesh)).ok());
}

TEST_F(ExportPanelTest, WithoutASelectionOrWithAMissingSculptureNothingIsWritten) {
    auto session = open();
    ExportPanel panel((dir / "session").string());
    EXPECT_FALSE(panel.start(*session, -1, ".stl", 0));
    EXPECT_NE(panel.status().find("select a sculpture"), std::string::npos) << panel.status();
    EXPECT_FALSE(panel.start(*session, session->findSculpture("lost"), ".hf", 0));
    EXPECT_NE(panel.status().find("missing"), std::string::npos) << panel.status();
    const std::filesystem::path exports = dir / "session" / "exports";
    EXPECT_TRUE(!std::filesystem::exists(exports) || std::filesystem::is_empty(exports));
}

TEST_F(ExportPanelTest, AFolderOfTheUsersOwnAndCancelLeavesNothing) {
    auto session = open();
    const int c = session->findSculpture("c");
    ExportPanel panel((dir / "session").string());
    EXPECT_EQ(std::filesystem::path(panel.exportFolder()), dir / "session" / "exports");
    panel.setFolder((dir / "prints" / "week 2").string());
    panel.setFileName("ball");
    ASSERT_TRUE(panel.start(*session, c, ".hf", 0)) << panel.status();
    finish(panel);
    EXPECT_EQ(std::filesystem::path(panel.lastPath()), dir / "prints" / "week 2" / "ball.hf");
    EXPECT_TRUE(std::filesystem::exists(panel.lastPath())) << "the folder is made";

    // A mesh of many tiles, cancelled as soon as it starts: no file, no
    // temporary, and the panel says so; the next export runs as usual.
    panel.setFileName("big");
    ASSERT_TRUE(panel.start(*session, c, ".stl", 1024)) << panel.status();
    const std::string big = panel.lastPath();
    panel.cancel();
    finish(panel);
    EXPECT_NE(panel.status().find("cancelled"), std::string::npos) << panel.status();
    EXPECT_FALSE(std::filesystem::exists(big));
    for (const auto& e : std::filesystem::directory_iterator(dir / "prints" / "week 2"))
        EXPECT_EQ(e.path().filename().string().find("big"), std::string::npos) << e.path();
    panel.cancel();  // nothing under way: nothing happens
    panel.setFileName("small");
    ASSERT_TRUE(panel.start(*session, c, ".stl", 32)) << panel.status();
    finish(panel);
    EXPECT_EQ(panel.status().rfind("wrote ", 0), 0u) << panel.status();
}

// A name of the user's own (kept to letters, digits, - and _), and a
// status line that belongs to the sculpture it was about: drawn for another
// selection, it starts clean.
TEST_F(ExportPanelTest, TheFileTakesTheGivenNameAndAnErrorGoesWithANewSelection) {
    auto session = open();
    const int c = session->findSculpture("c");
    ExportPanel panel((dir / "session").string());
    panel.setFileName("my piece/v2");
    ASSERT_TRUE(panel.start(*session, c, ".hf", 0)) << panel.status();
    finish(panel);
    EXPECT_EQ(std::filesystem::path(panel.lastPath()), dir / "session" / "exports" / "my_piece_v2.hf");
    EXPECT_TRUE(std::filesystem::exists(panel.lastPath()));

    EXPECT_FALSE(panel.start(*session, session->findSculpture("lost"), ".hf", 0));
    EXPECT_NE(panel.status().find("missing"), std::string::npos);
    createHeadlessImGui(ImVec2(1280, 720));
    const auto frame = [&] {
        ImGui::NewFrame();
        ImGui::Begin("Garden");
        panel.draw(*session);
        ImGui::End();
        ImGui::Render();
    };
    session->select(session->findSculpture("lost"));
    frame();
    EXPECT_NE(panel.status().find("missing"), std::string::npos) << "still about the sculpture selected";
    session->select(c);
    frame();
    EXPECT_EQ(panel.status(), "") << "another sculpture: the old error is gone";
    ImGui::DestroyContext();
}

}  // namespace
}  // namespace hg::garden
