// Home on the desktop: the view that frames the whole garden, so a user who
// got lost (or a garden whose start looks at one corner) sees every
// sculpture at once.
#pragma once

#include <glm/vec3.hpp>

namespace hg::garden {

class GardenSession;

struct FramedView {
    glm::vec3 eye{0.0f};
    float yaw = 0.0f, pitch = 0.0f;  // the navigator's angles
};

// Looking the way the garden's start looks (turned level), pitched down
// 25 degrees, far enough back that a sphere around every sculpture's box
// (missing ones at their place) fits the vertical field of view `fovY` and
// a horizontal one of `fovY * aspect`.
FramedView gardenFraming(const GardenSession& session, float fovY, float aspect);

// The session's navigator put there, flying (walking would pull the eye
// down to eye height).
void frameGarden(GardenSession& session, float fovY, float aspect);

}  // namespace hg::garden
