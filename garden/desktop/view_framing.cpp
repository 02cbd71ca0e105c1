#include "garden/desktop/view_framing.h"

#include <algorithm>
#include <cmath>

#include "garden/app/garden_session.h"
#include "garden/scene/to_glm.h"

namespace hg::garden {

FramedView gardenFraming(const GardenSession& session, float fovY, float aspect) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Sculpture& s : session.sculptures()) {
        if (s.removed) continue;
        if (!s.volume) {
            lo = glm::min(lo, glm::vec3(s.modelToWorld()[3]));
            hi = glm::max(hi, glm::vec3(s.modelToWorld()[3]));
            continue;
        }
        const frep::Box3& b = s.volume->frame.modelBox;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec4 m(b.lo[0] + (corner & 1) * (b.hi[0] - b.lo[0]), b.lo[1] + ((corner >> 1) & 1) * (b.hi[1] - b.lo[1]),
                              b.lo[2] + ((corner >> 2) & 1) * (b.hi[2] - b.lo[2]), 1.0f);
            const glm::vec3 w(s.modelToWorld() * m);
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
    }
    const Garden& g = session.garden();
    glm::vec3 look = toGlm(g.start.lookAt) - toGlm(g.start.position);
    look.y = 0.0f;
    look = glm::length(look) > 1e-6f ? glm::normalize(look) : glm::vec3(0.0f, 0.0f, -1.0f);
    if (lo.x > hi.x) return {toGlm(g.start.position), std::atan2(look.x, -look.z), 0.0f};  // no sculptures
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 0.5f);
    const float pitch = -25.0f * 3.14159265f / 180.0f;
    const float halfFov = 0.5f * std::min(fovY, fovY * std::max(aspect, 0.1f));
    const float distance = radius / std::sin(halfFov);
    const glm::vec3 dir(look.x * std::cos(pitch), std::sin(pitch), look.z * std::cos(pitch));
    FramedView v;
    v.eye = centre - dir * distance;
    v.yaw = std::atan2(look.x, -look.z);
    v.pitch = pitch;
    return v;
}

void frameGarden(GardenSession& session, float fovY, float aspect) {
    const FramedView v = gardenFraming(session, fovY, aspect);
    session.navigator().setMode(NavigationMode::Fly);
    session.navigator().setPose(v.eye, v.yaw, v.pitch);
}

}  // namespace hg::garden
