#include "xr/hand_panel.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace hg::xr {

namespace {

constexpr float kTriggerDown = 0.5f;
constexpr int kRows = (kPanelButtons + HandPanel::kColumns - 1) / HandPanel::kColumns;
constexpr float kGap = 0.08f;  // of a cell, around each button

}  // namespace

void HandPanel::place(const garden::HandState& navigation, float scale) {
    shown_ = navigation.tracked;
    if (!shown_) {
        hovered_.reset();
        return;
    }
    const garden::Pose& g = navigation.grip;
    right_ = g.right();
    up_ = g.up();
    normal_ = glm::cross(right_, up_);  // the grip's +z: towards the user when the hand points away
    width_ = kWidth * scale;
    height_ = kHeight * scale;
    center_ = g.position + up_ * (kAboveHand * scale);
}

glm::vec3 HandPanel::corner(float u, float v) const {
    return center_ + right_ * ((u - 0.5f) * width_) + up_ * ((v - 0.5f) * height_);
}

std::optional<PanelButton> HandPanel::pointedAt(const garden::Pose& aim) const {
    if (!shown_) return std::nullopt;
    const glm::vec3 d = aim.forward();
    const float facing = glm::dot(d, normal_);
    if (facing > -1e-4f) return std::nullopt;  // from behind, or along the board
    const float t = glm::dot(center_ - aim.position, normal_) / facing;
    if (t <= 0.0f) return std::nullopt;
    const glm::vec3 p = aim.position + d * t - center_;
    const float u = glm::dot(p, right_) / width_ + 0.5f, v = glm::dot(p, up_) / height_ + 0.5f;
    if (u < 0.0f || u >= 1.0f || v < 0.0f || v >= 1.0f) return std::nullopt;
    const int column = static_cast<int>(u * kColumns), row = kRows - 1 - static_cast<int>(v * kRows);  // row 0 on top
    const int index = row * kColumns + column;
    if (index >= kPanelButtons) return std::nullopt;
    return static_cast<PanelButton>(index);
}

std::optional<PanelButton> HandPanel::update(const garden::HandState& tool) {
    hovered_ = tool.tracked ? pointedAt(tool.aim) : std::nullopt;
    const bool down = tool.tracked && tool.trigger > kTriggerDown;
    const bool pressed = down && !triggerWasDown_;
    triggerWasDown_ = down;
    return pressed ? hovered_ : std::nullopt;
}

std::vector<glm::vec3> HandPanel::outline(PanelButton b) const {
    const int index = static_cast<int>(b), column = index % kColumns, row = index / kColumns;
    const float u0 = (static_cast<float>(column) + kGap) / kColumns, u1 = (static_cast<float>(column) + 1.0f - kGap) / kColumns;
    const float v1 = 1.0f - (static_cast<float>(row) + kGap) / kRows, v0 = 1.0f - (static_cast<float>(row) + 1.0f - kGap) / kRows;
    return {corner(u0, v0), corner(u1, v0), corner(u1, v1), corner(u0, v1)};
}

glm::vec4 HandPanel::colorOf(PanelButton b) {
    switch (b) {
        case PanelButton::ToolNone: return {0.9f, 0.85f, 0.2f, 1.0f};  // the morph selector's yellow
        case PanelButton::Carve: return {0.9f, 0.25f, 0.2f, 1.0f};
        case PanelButton::Add: return {0.25f, 0.8f, 0.3f, 1.0f};
        case PanelButton::Melt: return {0.95f, 0.55f, 0.15f, 1.0f};
        case PanelButton::Perturb: return {0.3f, 0.5f, 0.95f, 1.0f};
        case PanelButton::Impacts: return {0.7f, 0.35f, 0.9f, 1.0f};
        case PanelButton::Undo: return {0.85f, 0.85f, 0.85f, 1.0f};
        case PanelButton::Redo: return {0.55f, 0.55f, 0.55f, 1.0f};
        case PanelButton::Count: break;
    }
    return {1.0f, 1.0f, 1.0f, 1.0f};
}

}  // namespace hg::xr
