#include "xr/hand_panel.h"

#include <glm/geometric.hpp>

namespace hg::xr {

namespace {
constexpr float kTriggerDown = 0.5f;
}

void HandPanel::place(const garden::HandState& navigation, float scale) {
    shown_ = navigation.tracked;
    if (!shown_) {
        hovered_.reset();
        held_ = false;
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

glm::vec3 HandPanel::at(const glm::vec2& uv) const {
    return center_ + right_ * ((uv.x - 0.5f) * width_) + up_ * ((0.5f - uv.y) * height_);
}

std::array<glm::vec3, 4> HandPanel::corners() const {
    return {at({0.0f, 0.0f}), at({1.0f, 0.0f}), at({1.0f, 1.0f}), at({0.0f, 1.0f})};
}

std::optional<glm::vec2> HandPanel::pointedAt(const garden::Pose& aim) const {
    if (!shown_) return std::nullopt;
    const glm::vec3 d = aim.forward();
    const float facing = glm::dot(d, normal_);
    if (facing > -1e-4f) return std::nullopt;  // from behind, or along the board
    const float t = glm::dot(center_ - aim.position, normal_) / facing;
    if (t <= 0.0f) return std::nullopt;
    const glm::vec3 p = aim.position + d * t - center_;
    const glm::vec2 uv(glm::dot(p, right_) / width_ + 0.5f, 0.5f - glm::dot(p, up_) / height_);
    if (uv.x < 0.0f || uv.x >= 1.0f || uv.y < 0.0f || uv.y >= 1.0f) return std::nullopt;
    return uv;
}

void HandPanel::update(const garden::HandState& tool) {
    hovered_ = tool.tracked ? pointedAt(tool.aim) : std::nullopt;
    const bool down = tool.tracked && tool.trigger > kTriggerDown;
    if (!down) held_ = false;
    else if (!triggerWasDown_ && hovered_) held_ = true;  // only a pull that starts on the board
    if (!shown_) held_ = false;
    triggerWasDown_ = down;
}

}  // namespace hg::xr
