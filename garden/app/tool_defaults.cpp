#include "garden/app/tool_defaults.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "garden/app/garden_session.h"

namespace hg::garden {

int sculptureInView(const GardenSession& session) {
    const glm::vec3 eye = session.navigator().eye(), forward = session.navigator().forward();
    int best = -1;
    float bestCos = 0.0f;  // in front: less than 90 degrees off the centre line
    for (std::size_t i = 0; i < session.sculptures().size(); ++i) {
        const Sculpture& s = session.sculptures()[i];
        if (!s.onShow()) continue;  // missing, removed, or still loading (no box yet)
        const glm::vec3 to = s.worldCentre() - eye;
        const float d = glm::length(to);
        if (d < 1e-6f) continue;
        const float c = glm::dot(to / d, forward);
        if (c > bestCos) {
            bestCos = c;
            best = static_cast<int>(i);
        }
    }
    return best;
}

void sizeToolsToView(GardenSession& session) {
    const int i = sculptureInView(session);
    if (i < 0) return;
    const Sculpture& s = session.sculptures()[static_cast<std::size_t>(i)];
    const frep::Box3& b = s.volume->frame.modelBox;
    const double size = s.scale() * std::sqrt((b.hi[0] - b.lo[0]) * (b.hi[0] - b.lo[0]) + (b.hi[1] - b.lo[1]) * (b.hi[1] - b.lo[1]) +
                                            (b.hi[2] - b.lo[2]) * (b.hi[2] - b.lo[2]));
    ToolSettings& t = session.tool();
    t.radius = kStartRadiusShare * size;
    for (ToolSettings::Kept& k : t.kept) k.radius = 0.0;  // every stroke tool starts from it
    const double largest = std::max({t.radii[0], t.radii[1], t.radii[2]});
    if (largest > 0.0) t.perturbScale = kStartPerturbShare * size / largest;
    t.impactSize = kStartImpactShare * size;
    clampToolSettings(t);
}

}  // namespace hg::garden
