// Where a sculpture's gizmos are (docs/design.md §6), shared by the session (what
// the move tool grabs, where the mirror plane goes) and the renderer (what
// it draws), so what is drawn is what the hand can grab.
#pragma once

#include <glm/vec3.hpp>

#include "garden/app/sculpture.h"

namespace hg::garden {

// The move tool's ring: a horizontal circle around the placement's pivot
// (its position: turns and scales are about it) at the pivot's height, just
// outside the sculpture's model box.
struct MoveRing {
    glm::vec3 centre{0.0f};
    float radius = 1.0f;  // metres
};
MoveRing moveRing(const Sculpture& s);

// How far from the ring a pointer still grabs it, as a fraction of the radius.
constexpr float kMoveRingGrab = 0.15f;
// Whether a point in the ring's plane grabs it.
bool grabsMoveRing(const MoveRing& ring, const glm::vec3& pointInPlane);

// The mirror plane the desktop toggles (M, the tool panel): through the
// centre of the sculpture's model box, normal to its model x axis.
MirrorPlane centralMirror(const Sculpture& s);

}  // namespace hg::garden
