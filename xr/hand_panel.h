// The panel on the navigation hand (DESIGN §8, issue 13): a small board
// above the hand with the tools (none, carve, add, melt, perturb, impacts)
// and undo / redo, pointed at with the tool hand's aim ray and pressed with
// its trigger. While the ray is on the panel the trigger works the panel,
// not the tool. Geometry and hits are pure math; the app draws the
// outlines (no labels yet: each tool has its colour).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "garden/hands/hand_state.h"

namespace hg::xr {

enum class PanelButton { ToolNone, Carve, Add, Melt, Perturb, Impacts, Undo, Redo, Count };
constexpr int kPanelButtons = static_cast<int>(PanelButton::Count);

class HandPanel {
public:
    static constexpr float kWidth = 0.24f, kHeight = 0.12f;  // metres (stage)
    static constexpr float kAboveHand = 0.12f;               // the board's centre above the grip
    static constexpr int kColumns = 4;

    // Follows the navigation hand (world pose of its grip; `scale`: world
    // metres per stage metre); hidden while it is untracked.
    void place(const garden::HandState& navigation, float scale);
    bool shown() const { return shown_; }
    // The button under the aim ray, if the ray meets the board in front.
    std::optional<PanelButton> pointedAt(const garden::Pose& aim) const;
    // One frame of the tool hand: the button pressed this frame (trigger
    // going down on it), if any. `pointing()` then says whether the trigger
    // belongs to the panel this frame.
    std::optional<PanelButton> update(const garden::HandState& tool);
    bool pointing() const { return hovered_.has_value(); }
    std::optional<PanelButton> hovered() const { return hovered_; }

    // A button's outline (four corners, world) and colour, for drawing.
    std::vector<glm::vec3> outline(PanelButton b) const;
    static glm::vec4 colorOf(PanelButton b);

private:
    glm::vec3 corner(float u, float v) const;  // u, v in [0, 1] across the board

    bool shown_ = false;
    glm::vec3 center_{0.0f}, right_{1.0f, 0.0f, 0.0f}, up_{0.0f, 1.0f, 0.0f}, normal_{0.0f, 0.0f, 1.0f};
    float width_ = kWidth, height_ = kHeight;
    std::optional<PanelButton> hovered_;
    bool triggerWasDown_ = false;
};

}  // namespace hg::xr
