// One key table (garden/render/key_table.h): every binding looks up to its
// own command and no key does two things; the README's table is the
// table's Markdown, word for word (regenerate it with `hypergarden keys
// --markdown`); `hypergarden keys` and the F1 help read the same rows; the
// desktop settings file remembers the first-run overlay.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <fstream>
#include <set>
#include <sstream>

#include <imgui.h>

#include "../cli_fixture.h"
#include "../garden/garden_test_util.h"
#include "garden/desktop/desktop_settings.h"
#include "garden/render/key_table.h"
#include "garden/render/panels.h"
#include "tests/render/headless_imgui.h"

namespace hg::garden {
namespace {

TEST(KeyTable, EveryBindingLooksUpToItsCommandAndNoKeyDoesTwoThings) {
    std::set<std::pair<int, int>> seen;
    std::size_t bindings = 0;
    for (const KeyRow& row : keyTable()) {
        EXPECT_FALSE(row.keys.empty());
        EXPECT_FALSE(row.does.empty()) << row.keys;
        EXPECT_EQ(row.does.find('|'), std::string::npos) << "a | would break the Markdown table: " << row.keys;
        for (const KeyBinding& b : row.bindings) {
            ++bindings;
            EXPECT_TRUE(seen.insert({b.key, b.mods}).second) << row.keys << ": key " << b.key << " bound twice";
            EXPECT_EQ(keyCommand(b.key, b.mods), b.command) << row.keys;
        }
    }
    EXPECT_GE(bindings, 40u);
    EXPECT_EQ(keyCommand(GLFW_KEY_Z, GLFW_MOD_CONTROL), KeyCommand::Undo);
    EXPECT_EQ(keyCommand(GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT), KeyCommand::Redo);
    EXPECT_FALSE(keyCommand(GLFW_KEY_Z, 0)) << "Z alone is nothing";
    EXPECT_FALSE(keyCommand(GLFW_KEY_1, GLFW_MOD_CONTROL)) << "Ctrl+1 picks no tool";
    EXPECT_EQ(keyCommand(GLFW_KEY_1, GLFW_MOD_SHIFT), KeyCommand::ToolCarve);
    EXPECT_EQ(keysOf(KeyCommand::Forward), std::vector<int>{GLFW_KEY_W});
    EXPECT_EQ(keysOf(KeyCommand::Turn), (std::vector<int>{GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT}));
}

// The README's "| key | does |" table, as it stands in the source tree.
std::string readmeKeyTable() {
    std::ifstream in(std::string(HG_SOURCE_DIR) + "/README.md");
    std::string line, table;
    bool inTable = false;
    while (std::getline(in, line)) {
        if (line == "| key | does |") inTable = true;
        if (!inTable) continue;
        if (line.empty() || line[0] != '|') break;
        table += line + "\n";
    }
    return table;
}

TEST(KeyTable, TheReadmesTableIsTheKeyTable) {
    const std::string readme = readmeKeyTable();
    ASSERT_FALSE(readme.empty()) << "README.md has no | key | does | table";
    EXPECT_EQ(readme, keyTableMarkdown()) << "regenerate the README's table with `hypergarden keys --markdown`";
}

TEST(KeyTable, HelpListsEveryRow) {
    const std::string text = keyTableText();
    for (const KeyRow& row : keyTable()) EXPECT_NE(text.find(row.keys), std::string::npos) << row.keys;
    // The F1 window grows with its rows: a table drawn from the same list.
    createHeadlessImGui(ImVec2(1280, 900));
    bool open = true;
    int vertices = 0;
    for (int f = 0; f < 3; ++f) {
        ImGui::NewFrame();
        drawHelpPanel(open, {640.0f, 900.0f});
        ImGui::Render();
        vertices = ImGui::GetDrawData()->TotalVtxCount;
    }
    std::size_t characters = 0;
    for (const KeyRow& row : keyTable()) characters += row.keys.size() + row.does.size();
    // Four vertices a glyph (spaces draw none): most of the table's text is drawn.
    EXPECT_GT(vertices, static_cast<int>(4 * characters * 3 / 4));
    ImGui::DestroyContext();
}

class KeysCli : public ::hg::test::CliTest {};

TEST_F(KeysCli, PrintsTheTable) {
    auto r = ::hg::test::runHypergarden("keys --markdown");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output, keyTableMarkdown());
    r = ::hg::test::runHypergarden("keys");
    ASSERT_EQ(r.status, 0);
    EXPECT_EQ(r.output, "Keys and mouse in the garden window:\n" + keyTableText());
    r = ::hg::test::runHypergarden("--help");
    EXPECT_NE(r.output.find("hypergarden keys"), std::string::npos) << r.output;
}

class DesktopSettingsFile : public test::ScratchDir {};

TEST_F(DesktopSettingsFile, RemembersTheFirstRunOverlay) {
    const std::string path = (dir / "config" / "desktop.json").string();
    std::string warning;
    EXPECT_FALSE(loadDesktopSettings(path, warning).firstRunDone) << "no file: the overlay shows";
    EXPECT_TRUE(warning.empty());
    DesktopUserSettings s;
    s.firstRunDone = true;
    ASSERT_EQ(saveDesktopSettings(path, s), "");
    EXPECT_TRUE(loadDesktopSettings(path, warning).firstRunDone);
    std::ofstream(path) << R"({"first_run_done": "yes"})";
    EXPECT_FALSE(loadDesktopSettings(path, warning).firstRunDone);
    EXPECT_NE(warning.find("$.first_run_done"), std::string::npos) << warning;
    EXPECT_NE(warning.find(path), std::string::npos) << warning;
    // Where it lives: beside the headset's settings.
    ::setenv("HG_DESKTOP_SETTINGS", "/somewhere/d.json", 1);
    EXPECT_EQ(desktopSettingsPath(), "/somewhere/d.json");
    ::unsetenv("HG_DESKTOP_SETTINGS");
    ::setenv("XDG_CONFIG_HOME", "/config", 1);
    EXPECT_EQ(desktopSettingsPath(), "/config/hypergarden/desktop.json");
    ::unsetenv("XDG_CONFIG_HOME");
}

TEST(FirstRunPanel, ShowsUntilDismissed) {
    createHeadlessImGui(ImVec2(1280, 900));
    ImGuiIO& io = ImGui::GetIO();
    io.KeyMap[ImGuiKey_Enter] = 257;  // as the GLFW backend maps it
    bool open = true;
    for (int f = 0; f < 3; ++f) {
        ImGui::NewFrame();
        EXPECT_FALSE(drawFirstRunPanel(open));
        ImGui::Render();
        // (an auto-sized window shows from its second frame)
        if (f > 0) {
            EXPECT_GT(ImGui::GetDrawData()->TotalVtxCount, 1000) << "frame " << f;
        }
    }
    EXPECT_TRUE(open) << "nothing pressed: it stays";
    io.KeysDown[257] = true;  // Enter, like its Start button
    ImGui::NewFrame();
    EXPECT_TRUE(drawFirstRunPanel(open));
    ImGui::Render();
    io.KeysDown[257] = false;
    EXPECT_FALSE(open);
    ImGui::NewFrame();
    EXPECT_FALSE(drawFirstRunPanel(open)) << "dismissed, it draws nothing";
    ImGui::Render();
    EXPECT_EQ(ImGui::GetDrawData()->TotalVtxCount, 0);
    ImGui::DestroyContext();
}

}  // namespace
}  // namespace hg::garden
