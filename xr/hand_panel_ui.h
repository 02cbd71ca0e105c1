// What the hand panel (xr/hand_panel.h) shows, drawn with Dear ImGui on a
// board in the world (garden/render/ui_board.h: a texture of its own put on
// the panel as a quad). Always on top: the tools and undo, redo as labelled
// buttons, and three page buttons below them; under those the page: "tool"
// (the tool's parameters, the widgets the desktop's tool panel draws
// (garden/render/tool_panel.h), in their pointer-only look; for the morph
// tool the morph triangle), "sculpture" (previous and next sculpture, and
// the desktop's selection section: mirror plane, edit count and "discard
// edits", placement), "settings" (the user's settings: left-handed, seated
// and its height offset, smooth turning, the snap angle; the interaction
// profile's name). The tool hand's ray on the board is ImGui's mouse, its
// trigger the left button. The layout is fixed so that tests (and users'
// muscle memory) find things in the same place.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "garden/render/ui_board.h"
#include "xr/xr_settings.h"

namespace hg::garden {
class GardenSession;
}

namespace hg::xr {

class HandPanel;

enum class PanelButton { ToolNone, Carve, Add, Melt, Perturb, Impacts, Move, Sketch, Smooth, Inflate, Undo, Redo, Count };

// The panel's texture, pixels; the board's aspect (HandPanel) matches.
constexpr int kPanelPixelsX = 512, kPanelPixelsY = 320;

// The board point (0..1, top left first) at the centre of a button.
glm::vec2 panelButtonCenter(PanelButton b);
const char* panelButtonLabel(PanelButton b);
// The board point of the morph triangle where the blend has these weights.
glm::vec2 panelMorphPoint(const glm::vec3& weights);
// The pages under the buttons, and the board point of a page's button.
enum class PanelPage { Tool, Sculpture, Settings, History, Count };
glm::vec2 panelPageCenter(PanelPage p);
// The board point of a check box: on the settings page (left-handed,
// seated, smooth turning) or the sculpture page (the selection's mirror
// plane, with a sculpture selected).
enum class PanelToggle { LeftHanded, Seated, SmoothTurn, Mirror };
glm::vec2 panelToggleCenter(PanelToggle t);
// The board point of a choice's option (a row of buttons): the perturb
// tool's shape (ellipsoid, torus) and the impact tool's shape (sphere, V
// chisel, square punch) and spread (uniform disc, gaussian, cone) on the
// tool page with that tool in hand; the snap angle (kSnapAngles, in order)
// on the settings page.
enum class PanelChoice { PerturbShape, ImpactShape, ImpactSpread, SnapAngle };
glm::vec2 panelChoiceCenter(PanelChoice c, int option);
// The board point of a button on the sculpture page ("discard edits" with
// a sculpture selected).
// (the history page's undo of the selected sculpture's last action only).
enum class PanelAction { PreviousSculpture, NextSculpture, DiscardEdits, UndoSelected };
glm::vec2 panelActionCenter(PanelAction a);
// The board point on the settings page's seated height slider that sets
// it to `metres` (0 to kMaxSeatedHeightOffset).
glm::vec2 panelSeatedOffsetPoint(double metres);

class HandPanelUi {
public:
    // Needs the current GL context (3.3 core); keeps the ImGui context that
    // was current (the mirror's) current after each call.
    HandPanelUi();
    HandPanelUi(const HandPanelUi&) = delete;
    HandPanelUi& operator=(const HandPanelUi&) = delete;

    // One frame of the panel into its texture: `panel` gives the mouse
    // (its hovered point) and the button (pressing); the controls act on
    // the session at once. True when the user changed `user` on the panel.
    bool update(garden::GardenSession& session, const HandPanel& panel, const std::string& profile,
                XrUserSettings& user, float dt);
    // The texture on the board, over whatever is bound (the eye's
    // framebuffer), not depth tested: the panel is never hidden.
    void draw(const HandPanel& panel, const glm::mat4& viewProjection) const;

private:
    garden::UiBoard board_;
    PanelPage page_ = PanelPage::Tool;

    void toolPage(garden::GardenSession& session);
    void sculpturePage(garden::GardenSession& session);
    bool settingsPage(const std::string& profile, XrUserSettings& user);
    void historyPage(garden::GardenSession& session);
};

}  // namespace hg::xr
