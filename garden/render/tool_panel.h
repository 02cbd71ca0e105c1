// The tool panel's widgets, shared by the desktop's tool panel
// (drawToolPanel, panels.h) and the headset's hand panel
// (xr/hand_panel_ui.h): ImGui calls on the session's ToolSettings and its
// sculpting API, inside the caller's window. One set of widgets, so both
// panels offer the same parameters and act through the same (journalled,
// undoable) session calls.
#pragma once

namespace hg::garden {

class GardenSession;
struct ToolSettings;

// How the widgets look where they are drawn.
struct ToolWidgetLook {
    float fieldWidth = 180.0f;
    // The desktop's keys named in the labels ("radius (m)  [ ]",
    // "reverse (R)"); off where there is no keyboard.
    bool keyHints = true;
    // 0: a choice is a combo box and the seed a text field (mouse and
    // keyboard). > 0: pointer only (a ray and a trigger): a choice is a row
    // of buttons this many pixels wide, the seed is stepped with - and +,
    // and the selection's buttons are this wide.
    float choiceWidth = 0.0f;
};

// The parameters of the tool in hand (carve, add, melt: radius, softness;
// perturb: shape, radii, strength, scale; impacts: shape, size,
// compaction, spread and its size, count, seed) and its reverse; nothing
// for the morph (none) and move tools, whose hints differ per device.
// Values the user sets are kept within the tools' one set of bounds
// (clampToolSettings, garden/sculpt/tool_settings.h).
void toolParameters(ToolSettings& tool, const ToolWidgetLook& look);

// The selected sculpture: its name, mirror plane, edit count with a button
// that discards the edits, and placement; a hint when none is selected.
void selectionSection(GardenSession& session, const ToolWidgetLook& look);

// One of `count` names: a combo box, or (look.choiceWidth > 0) a row of
// buttons, the chosen one lit, followed by `label`. True when it changed.
bool chooseOne(const char* label, int& index, const char* const names[], int count, const ToolWidgetLook& look);

}  // namespace hg::garden
