// The panel on the navigation hand (docs/design.md §8, issue 13): a board above the
// hand, pointed at with the tool hand's aim ray and worked with its
// trigger. What is on it (labelled buttons, the tool's parameters, the
// morph triangle) is xr/hand_panel_ui.h's; this is the board's place and
// where the ray meets it, pure math. While the ray is on the board, or the
// trigger went down there and is still held, the trigger works the panel,
// not the tool.
#pragma once

#include <array>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "garden/hands/hand_state.h"

namespace hg::xr {

class HandPanel {
public:
    static constexpr float kWidth = 0.32f, kHeight = 0.20f;  // metres (stage)
    static constexpr float kAboveHand = 0.14f;               // the board's centre above the grip

    // Follows the navigation hand (world pose of its grip; `scale`: world
    // metres per stage metre); hidden while it is untracked.
    void place(const garden::HandState& navigation, float scale);
    bool shown() const { return shown_; }
    // Where the aim ray meets the board in front: (0, 0) its top left,
    // (1, 1) its bottom right (image order, as the panel is drawn).
    std::optional<glm::vec2> pointedAt(const garden::Pose& aim) const;
    // One frame of the tool hand.
    void update(const garden::HandState& tool);
    std::optional<glm::vec2> hovered() const { return hovered_; }
    // The trigger is the panel's this frame (on the board, or held since it
    // went down there).
    bool ownsTrigger() const { return hovered_.has_value() || held_; }
    // The trigger went down on the board and is still down: the panel's
    // mouse button.
    bool pressing() const { return held_; }

    // The world point of board point `uv` (tests aim at it; drawing).
    glm::vec3 at(const glm::vec2& uv) const;
    // The corners, world: top left, top right, bottom right, bottom left.
    std::array<glm::vec3, 4> corners() const;

private:
    bool shown_ = false;
    glm::vec3 center_{0.0f}, right_{1.0f, 0.0f, 0.0f}, up_{0.0f, 1.0f, 0.0f}, normal_{0.0f, 0.0f, 1.0f};
    float width_ = kWidth, height_ = kHeight;
    std::optional<glm::vec2> hovered_;
    bool triggerWasDown_ = false, held_ = false;
};

}  // namespace hg::xr
