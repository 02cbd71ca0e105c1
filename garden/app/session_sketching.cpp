// The sketch tool (seed 003; docs/sketching.md): the tool hand's button,
// pressed while its ray meets a sculpture, starts an outline on the plane
// through that point facing the hand (on the desktop the mouse ray's
// origin is the eye, so the plane faces the viewer); while it is held the
// ray's point on that plane is added; on release the outline becomes one
// SketchAction, joined to the sculpture (reverse: cut from it). Begun in
// the air, the plane stands kAirSketchDistance along the ray and the
// outline becomes a new sculpture (an AddAction, mode `new`). The same for
// the desktop's mouse and the headset's tool hand: both are hands.
#include "garden/app/garden_session.h"

#include <glm/geometric.hpp>

namespace hg::garden {

namespace {

// Points closer than this to the last one (metres) add nothing: the
// outline is resampled anyway, and a still hand should not pile them up.
constexpr float kSketchStep = 0.002f;
// Metres along the ray to the plane of a sketch begun in the air: within
// reach of a hand in the headset, a sculpture's size away on the desktop.
constexpr float kAirSketchDistance = 1.5f;

}  // namespace

void GardenSession::sketchWithHands(const HandState& h) {
    const bool held = h.tracked && h.trigger > 0.5f && tool_.kind == ToolSettings::Kind::Sketch;
    if (!sketch_.drawing) {
        if (!held) {
            toolArmed_ = true;
            return;
        }
        if (!toolArmed_) return;  // one sketch per press
        toolArmed_ = false;
        const auto hit = toolHit(h.aim);
        const auto use = tool_.sketchUse;
        if (!hit && (use == ToolSettings::SketchUse::Join || use == ToolSettings::SketchUse::Cut)) {
            sketchMessage_ = "begin the outline on a sculpture: it is joined to or cut from the one it starts on";
            return;
        }
        if (!hit && use == ToolSettings::SketchUse::Model && selected_ < 0) {
            sketchMessage_ = "begin the model's outline on a sculpture, or select one first";
            return;
        }
        sketch_.drawing = true;
        sketch_.sculpture = hit ? hit->first : -1;
        sketch_.origin = hit ? hit->second : h.aim.position + kAirSketchDistance * h.aim.forward();
        sketch_.normal = -h.aim.forward();
        sketch_.points = {sketch_.origin};
        return;
    }
    if (held) {
        // Where the ray meets the plane, in front of the hand.
        const glm::vec3 d = h.aim.forward();
        const float along = glm::dot(d, sketch_.normal);
        if (std::abs(along) < 1e-4f) return;  // the ray runs along the plane
        const float t = glm::dot(sketch_.origin - h.aim.position, sketch_.normal) / along;
        if (!(t > 0.0f)) return;
        const glm::vec3 p = h.aim.position + t * d;
        if (glm::length(p - sketch_.points.back()) >= kSketchStep) sketch_.points.push_back(p);
        return;
    }
    // Released: the outline becomes an action (or a refusal that says why).
    toolArmed_ = true;
    SketchDraw done = std::move(sketch_);
    sketch_ = SketchDraw{};
    std::vector<std::array<double, 3>> points;
    for (const glm::vec3& p : done.points) points.push_back({p.x, p.y, p.z});
    const std::array<double, 3> normal{done.normal.x, done.normal.y, done.normal.z};
    using Use = ToolSettings::SketchUse;
    if (tool_.sketchUse == Use::Model) {
        const int around = done.sculpture >= 0 ? done.sculpture : selected_;
        const ActionOrWhy a = modelFromWorld(around, "", points, normal);
        sketchMessage_ = a.action ? apply(*a.action) : a.why;
        return;
    }
    if (done.sculpture < 0 || tool_.sketchUse == Use::New) {
        const ActionOrWhy a = sketchNewFromWorld("", points, normal);
        sketchMessage_ = a.action ? apply(*a.action) : a.why;
        if (sketchMessage_.empty()) select(static_cast<int>(sculptures_.size()) - 1);
        return;
    }
    const bool cut = (tool_.sketchUse == Use::Cut) != tool_.reverse;
    sketchMessage_ = applySketch(done.sculpture, cut ? SketchMode::Cut : SketchMode::Add, points, normal);
}

}  // namespace hg::garden
