// What the user asked of the tool this frame (docs/design.md §6), beside the
// hands and as device-neutral as they are: the desktop's keys and wheel,
// the headset's tool stick and replay scripts all produce these, and one
// garden function (GardenSession::applyToolIntents,
// garden/app/tool_intents.cpp) applies them with one set of bounds
// (garden/sculpt/tool_settings.h) and one undo granularity. Nothing here
// knows a device or a ToolSettings.
#pragma once

#include <optional>

namespace hg::garden {

// The tools, in the order of ToolSettings::Kind (the desktop's digit keys).
enum class ToolChoice { None, Carve, Add, Melt, Perturb, Impacts, Move, Sketch, Smooth, Inflate };

// What becomes of the selected sculpture's mirror plane.
enum class MirrorIntent { Keep, Toggle, On, Off };

struct ToolIntents {
    std::optional<ToolChoice> tool;  // pick this tool (before the steps below apply)
    // Factors for this frame, 1 for none: the size of the tool in hand (the
    // stroke radius, the perturbation's radii together, the impact size;
    // with the move tool the selected sculpture's scale) and its strength
    // (the perturbation's, sign kept; the impacts' compaction volume).
    double size = 1.0;
    double strength = 1.0;
    bool reverse = false;            // toggle the reverse (carve <-> add, pull <-> push)
    MirrorIntent mirror = MirrorIntent::Keep;  // the selected sculpture's mirror plane
    double selectionScale = 1.0;     // factor on the selected sculpture's scale this frame
    // A continuous gesture is still under way (the stick held out of its
    // dead zone, a burst of wheel notches): the selection's scaling goes on
    // as one live move, journalled and undone as one when a frame comes
    // with neither a scale factor nor `held`.
    bool held = false;

    bool any() const {
        return tool || size != 1.0 || strength != 1.0 || reverse || mirror != MirrorIntent::Keep ||
               selectionScale != 1.0 || held;
    }
};

}  // namespace hg::garden
