// What the hand panel (xr/hand_panel.h) shows, drawn with Dear ImGui into a
// texture of its own and put on the board as a quad: the tools as labelled
// buttons, the tool's parameters (the session's ToolSettings, as the
// desktop's tool panel edits them), the morph triangle, undo and redo, the
// left-handed and seated switches, and the interaction profile's name. The tool hand's ray on the board is
// ImGui's mouse, its trigger the left button. The layout is fixed so that
// tests (and users' muscle memory) find things in the same place.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "xr/xr_settings.h"

namespace hg::garden {
class GardenSession;
}

namespace hg::xr {

class HandPanel;

enum class PanelButton { ToolNone, Carve, Add, Melt, Perturb, Impacts, Undo, Redo, Count };

// The panel's texture, pixels; the board's aspect (HandPanel) matches.
constexpr int kPanelPixelsX = 512, kPanelPixelsY = 320;

// The board point (0..1, top left first) at the centre of a button.
glm::vec2 panelButtonCenter(PanelButton b);
const char* panelButtonLabel(PanelButton b);
// The board point of the morph triangle where the blend has these weights.
glm::vec2 panelMorphPoint(const glm::vec3& weights);
// The board point of the left-handed or the seated check box.
enum class PanelToggle { LeftHanded, Seated };
glm::vec2 panelToggleCenter(PanelToggle t);

class HandPanelUi {
public:
    // Needs the current GL context (3.3 core); keeps the ImGui context that
    // was current (the mirror's) current after each call.
    HandPanelUi();
    ~HandPanelUi();
    HandPanelUi(const HandPanelUi&) = delete;
    HandPanelUi& operator=(const HandPanelUi&) = delete;

    // One frame of the panel into its texture: `panel` gives the mouse
    // (its hovered point) and the button (pressing); the controls act on
    // the session at once. True when the user changed `user` (left-handed,
    // seated) on the panel.
    bool update(garden::GardenSession& session, const HandPanel& panel, const std::string& profile,
                XrUserSettings& user, float dt);
    // The texture on the board, over whatever is bound (the eye's
    // framebuffer), not depth tested: the panel is never hidden.
    void draw(const HandPanel& panel, const glm::mat4& viewProjection) const;

private:
    struct Gl;
    std::unique_ptr<Gl> gl_;
    void* context_ = nullptr;  // ImGuiContext
};

}  // namespace hg::xr
