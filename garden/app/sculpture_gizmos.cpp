#include "garden/app/sculpture_gizmos.h"

#include <algorithm>
#include <cmath>

#include "voxel/volume.h"

namespace hg::garden {

namespace {
// The ring sits this much outside the box's farthest corner.
constexpr float kRingMargin = 1.1f;
}  // namespace

MoveRing moveRing(const Sculpture& s) {
    MoveRing r;
    r.centre = glm::vec3(s.modelToWorld()[3]);
    // The farthest corner of the model box from the vertical through the
    // pivot (the model origin), in metres: unchanged by the yaw.
    double reach = 0.5;  // a missing sculpture: its 1 m marker
    if (s.volume) {
        const frep::Box3& b = s.volume->frame.modelBox;
        reach = 0.0;
        for (double x : {b.lo[0], b.hi[0]})
            for (double z : {b.lo[2], b.hi[2]}) reach = std::max(reach, std::hypot(x, z) * s.scale());
    }
    r.radius = kRingMargin * static_cast<float>(reach);
    return r;
}

bool grabsMoveRing(const MoveRing& ring, const glm::vec3& p) {
    const float d = std::hypot(p.x - ring.centre.x, p.z - ring.centre.z);
    return std::fabs(d - ring.radius) <= kMoveRingGrab * ring.radius;
}

MirrorPlane centralMirror(const Sculpture& s) {
    MirrorPlane m;
    if (s.volume) {
        const frep::Box3& b = s.volume->frame.modelBox;
        m.point = {0.5 * (b.lo[0] + b.hi[0]), 0.5 * (b.lo[1] + b.hi[1]), 0.5 * (b.lo[2] + b.hi[2])};
    }
    m.normal = {1.0, 0.0, 0.0};
    return m;
}

}  // namespace hg::garden
