// The desktop's keys and mouse in one table (docs/desktop.md "Keys"): what
// the window binds (garden/desktop/desktop_keys.cpp looks every key press
// up here), what the F1 help lists, what `hypergarden keys` prints and what
// the README's table must read (tests/render/key_table_test.cpp compares
// them). A key that is not here does nothing in the window.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace hg::garden {

// What a key asks for.
enum class KeyCommand {
    Forward, Back, Left, Right, Down, Up,  // held: walking, flying
    Turn,                                  // held: the move tool turns (Shift)
    Fly, FrameGarden, Orbit, Detail,
    ToolNone, ToolCarve, ToolAdd, ToolMelt, ToolPerturb, ToolImpacts, ToolMove, ToolSketch, ToolSmooth, ToolInflate,
    Smaller, Larger, Reverse, Mirror,
    Undo, Redo, UndoSelected, History,
    ClayView, Wireframe,
    Headset, Screenshot, Help, Stats, Escape,
};

// One key with its modifiers (GLFW's key code and GLFW_MOD_* bits; 0: no
// Ctrl, whatever Shift does).
struct KeyBinding {
    int key = 0;
    int mods = 0;
    KeyCommand command = KeyCommand::Escape;
};

// A row of the table: the keys (or mouse) as the user reads them, what they
// do, and the bindings behind them (none for the mouse's rows).
struct KeyRow {
    std::string keys;
    std::string does;
    std::vector<KeyBinding> bindings;
};

const std::vector<KeyRow>& keyTable();

// The command of a GLFW key press with its modifier bits, none when the
// key means nothing in the window. A binding with no modifiers takes the
// key without Ctrl (Shift allowed: it is held to turn); one with Ctrl takes
// exactly its Ctrl and Shift.
std::optional<KeyCommand> keyCommand(int glfwKey, int glfwMods);

// The keys bound to a held command (walking, Shift), for polling.
std::vector<int> keysOf(KeyCommand command);

// The table as Markdown (the README's "| key | does |" table, header
// included) and as aligned plain text (`hypergarden keys`).
std::string keyTableMarkdown();
std::string keyTableText();

}  // namespace hg::garden
