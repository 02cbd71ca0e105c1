#include "garden/render/key_table.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <sstream>

namespace hg::garden {

namespace {

using C = KeyCommand;

std::vector<KeyBinding> digits() {
    const C tools[] = {C::ToolNone,    C::ToolCarve, C::ToolAdd,    C::ToolMelt,   C::ToolPerturb,
                       C::ToolImpacts, C::ToolMove,  C::ToolSketch, C::ToolSmooth, C::ToolInflate};
    std::vector<KeyBinding> b;
    for (int d = 0; d < 10; ++d) {
        b.push_back({GLFW_KEY_0 + d, 0, tools[d]});
        b.push_back({GLFW_KEY_KP_0 + d, 0, tools[d]});
    }
    return b;
}

std::vector<KeyRow> makeTable() {
    const int ctrl = GLFW_MOD_CONTROL, shift = GLFW_MOD_SHIFT;
    return {
        {"W A S D, Q / E", "walk (or fly) forward, left, back, right; down / up",
         {{GLFW_KEY_W, 0, C::Forward}, {GLFW_KEY_A, 0, C::Left}, {GLFW_KEY_S, 0, C::Back}, {GLFW_KEY_D, 0, C::Right},
          {GLFW_KEY_Q, 0, C::Down}, {GLFW_KEY_E, 0, C::Up}}},
        {"right button drag", "look", {}},
        {"middle button drag",
         "draw a gesture: V sketch a new sculpture, U join, arch cut, Z select (the next sketch is a model to shrink onto "
         "a sculpture); while selecting, circle clockwise to shrink the model, counter-clockwise to grow it",
         {}},
        {"wheel",
         "walking speed; with the move tool and a selection, the selection's scale (notches less than 0.4 s apart: one "
         "undo step)",
         {}},
        {"space", "fly / walk", {{GLFW_KEY_SPACE, 0, C::Fly}}},
        {"Home", "frame the garden: every sculpture in view, flying", {{GLFW_KEY_HOME, 0, C::FrameGarden}}},
        {"O", "orbit the selected sculpture", {{GLFW_KEY_O, 0, C::Orbit}}},
        {"G", "the detail sphere (full detail around it) where the mouse points, or away", {{GLFW_KEY_G, 0, C::Detail}}},
        {"left button",
         "the tool: sculpt the sculpture under the mouse at the press (that one only; it becomes the selection), or with "
         "no tool pick the blend on the ground triangle",
         {}},
        {"0 1 2 3 4 5 6 7 8 9",
         "the tool: none (the morph selector), carve, add, soft carve, perturb, impacts, move, sketch (hold the button "
         "on a sculpture and draw an outline; released, it is inflated and joined, R: cut), smooth, inflate (R: deflate)",
         digits()},
        {"[ / ]",
         "the tool's size x0.8 / x1.25 (stroke radius, perturbation scale, impact size, within the bounds the headset's "
         "stick keeps too; the move tool: the selection's scale)",
         {{GLFW_KEY_LEFT_BRACKET, 0, C::Smaller}, {GLFW_KEY_RIGHT_BRACKET, 0, C::Larger}}},
        {"R", "reverse (carve <-> add, pull <-> push, inflate <-> deflate, a sketch joined <-> cut)", {{GLFW_KEY_R, 0, C::Reverse}}},
        {"M", "the selected sculpture's mirror plane on / off", {{GLFW_KEY_M, 0, C::Mirror}}},
        {"Shift + drag", "with the move tool: turn the sculpture (as does dragging its ring)",
         {{GLFW_KEY_LEFT_SHIFT, 0, C::Turn}, {GLFW_KEY_RIGHT_SHIFT, 0, C::Turn}}},
        {"Ctrl+Z, Ctrl+Shift+Z (Ctrl+Y)", "undo, redo (over every sculpture, in the order the actions were made)",
         {{GLFW_KEY_Z, ctrl, C::Undo}, {GLFW_KEY_Z, ctrl | shift, C::Redo}, {GLFW_KEY_Y, ctrl, C::Redo}}},
        {"Ctrl+Alt+Z", "undo the selected sculpture's last action only, the others' left as they are",
         {{GLFW_KEY_Z, ctrl | GLFW_MOD_ALT, C::UndoSelected}}},
        {"H", "the history panel: every action with its sculpture; undo, redo, undo on the selection",
         {{GLFW_KEY_H, 0, C::History}}},
        {"C", "the clay view: every sculpture in one neutral matte material with cavity shading (grooves darker, ridges "
              "lighter; the Garden panel switches it), to judge its form; again: the materials",
         {{GLFW_KEY_C, 0, C::ClayView}}},
        {"X", "the wireframe overlay: the sculptures' triangle edges over them, on / off", {{GLFW_KEY_X, 0, C::Wireframe}}},
        {"F9", "this garden into the OpenXR headset; back at the desktop when its session ends (or F9 in the mirror)",
         {{GLFW_KEY_F9, 0, C::Headset}}},
        {"F12", "screenshot into the session's screenshots/ (else ~/Pictures/hypergarden); the window says where", {{GLFW_KEY_F12, 0, C::Screenshot}}},
        {"F1", "the key list on screen", {{GLFW_KEY_F1, 0, C::Help}}},
        {"F3", "the frame statistics panel open / collapsed (collapsed at the start)", {{GLFW_KEY_F3, 0, C::Stats}}},
        {"Esc",
         "closes an open drop-down, pop-up or the help first; else quits, asking first when something is not saved (no "
         "session folder, or a failed save)",
         {{GLFW_KEY_ESCAPE, 0, C::Escape}}},
    };
}

}  // namespace

const std::vector<KeyRow>& keyTable() {
    static const std::vector<KeyRow> table = makeTable();
    return table;
}

std::optional<KeyCommand> keyCommand(int glfwKey, int glfwMods) {
    const int held = glfwMods & (GLFW_MOD_CONTROL | GLFW_MOD_SHIFT | GLFW_MOD_ALT | GLFW_MOD_SUPER);
    for (const KeyRow& row : keyTable())
        for (const KeyBinding& b : row.bindings) {
            if (b.key != glfwKey) continue;
            const bool matches = b.mods == 0 ? (held & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER)) == 0 : held == b.mods;
            if (matches) return b.command;
        }
    return std::nullopt;
}

std::vector<int> keysOf(KeyCommand command) {
    std::vector<int> keys;
    for (const KeyRow& row : keyTable())
        for (const KeyBinding& b : row.bindings)
            if (b.command == command) keys.push_back(b.key);
    return keys;
}

std::string keyTableMarkdown() {
    std::ostringstream out;
    out << "| key | does |\n|---|---|\n";
    for (const KeyRow& r : keyTable()) out << "| " << r.keys << " | " << r.does << " |\n";
    return out.str();
}

std::string keyTableText() {
    std::size_t width = 0;
    for (const KeyRow& r : keyTable()) width = std::max(width, r.keys.size());
    std::ostringstream out;
    for (const KeyRow& r : keyTable()) out << "  " << r.keys << std::string(width - r.keys.size() + 2, ' ') << r.does << "\n";
    return out.str();
}

}  // namespace hg::garden
