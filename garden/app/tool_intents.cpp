// GardenSession's one place for tool intents (garden/hands/tool_intents.h;
// docs/design.md §6): whatever the device, the tool picked, its size and
// strength stepped within the one set of bounds (garden/sculpt/
// tool_settings.h), the reverse and the selection's mirror plane, and the
// selected sculpture scaled: one continuous gesture (a stick push, a burst
// of wheel notches) is one live move, so one undo step and one journalled
// move, whichever device made it.
#include <algorithm>
#include <cmath>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_gizmos.h"
#include "garden/app/tool_intents.h"

namespace hg::garden {

namespace {

// A factor a step can use: positive and finite, else none (1).
double usable(double factor) { return std::isfinite(factor) && factor > 0.0 ? factor : 1.0; }

}  // namespace

ToolSettings::Kind toolKindOf(ToolChoice c) {
    using K = ToolSettings::Kind;
    switch (c) {
        case ToolChoice::None: return K::None;
        case ToolChoice::Carve: return K::Carve;
        case ToolChoice::Add: return K::Add;
        case ToolChoice::Melt: return K::Melt;
        case ToolChoice::Perturb: return K::Perturb;
        case ToolChoice::Impacts: return K::Impacts;
        case ToolChoice::Move: return K::Move;
        case ToolChoice::Sketch: return K::Sketch;
        case ToolChoice::Smooth: return K::Smooth;
        case ToolChoice::Inflate: return K::Inflate;
    }
    return K::None;
}

ToolChoice toolChoiceOf(ToolSettings::Kind k) {
    using K = ToolSettings::Kind;
    switch (k) {
        case K::None: return ToolChoice::None;
        case K::Carve: return ToolChoice::Carve;
        case K::Add: return ToolChoice::Add;
        case K::Melt: return ToolChoice::Melt;
        case K::Perturb: return ToolChoice::Perturb;
        case K::Impacts: return ToolChoice::Impacts;
        case K::Move: return ToolChoice::Move;
        case K::Sketch: return ToolChoice::Sketch;
        case K::Smooth: return ToolChoice::Smooth;
        case K::Inflate: return ToolChoice::Inflate;
    }
    return ToolChoice::None;
}

void GardenSession::applyToolIntents(const Hands& hands) {
    const ToolIntents& in = hands.intents;
    if (in.tool) selectTool(tool_, toolKindOf(*in.tool));
    if (in.reverse) tool_.reverse = !tool_.reverse;

    const bool haveSelection = selected_ >= 0 && !sculptures_[static_cast<std::size_t>(selected_)].missing();
    if (in.mirror != MirrorIntent::Keep && haveSelection) {
        const Sculpture& s = sculptures_[static_cast<std::size_t>(selected_)];
        const bool on = in.mirror == MirrorIntent::On || (in.mirror == MirrorIntent::Toggle && !s.mirror);
        if (on != s.mirror.has_value()) setMirror(selected_, on ? std::optional<MirrorPlane>(centralMirror(s)) : std::nullopt);
    }

    // The move tool's size is the selection's scale.
    double scale = usable(in.selectionScale);
    if (tool_.kind == ToolSettings::Kind::Move) scale *= usable(in.size);
    else scaleToolSize(tool_, usable(in.size));
    scaleToolStrength(tool_, usable(in.strength));

    // The selection's scale: live while the gesture goes on, one move when
    // it ends. A pulled trigger is the tools' (the move tool's drag, a
    // stroke): the scaling ends there.
    const bool triggered = hands.tool.tracked && hands.tool.trigger > 0.5f;
    const bool scaling = haveSelection && !triggered && scale != 1.0;
    const bool goingOn = haveSelection && !triggered && (scale != 1.0 || in.held);
    if (intentScaling_ && (!goingOn || liveMove_ != selected_)) {
        intentScaling_ = false;
        if (!moveDrag_) endLiveMove();  // a drag's live move is the drag's to end
    }
    if (!scaling) return;
    Placement p = sculptures_[static_cast<std::size_t>(selected_)].placement;
    p.scale = std::clamp(p.scale * scale, kMinSculptureScale, kMaxSculptureScale);
    if (!intentScaling_ && p.scale == sculptures_[static_cast<std::size_t>(selected_)].placement.scale) return;
    if (moveDrag_) return;  // cannot happen without a trigger; the drag keeps its move
    intentScaling_ = moveSculptureLive(selected_, p).empty();
}

}  // namespace hg::garden
