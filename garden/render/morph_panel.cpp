// The Garden panel's morph section (issue 23, "one state, one truth"): the
// triangle widget and the weights line both read the session's weights
// every frame, so a blend picked on the ground triangle shows here at once;
// the widget keeps no point of its own that could go stale.
#include <imgui.h>

#include "garden/app/garden_session.h"
#include "garden/render/morph_triangle.h"
#include "garden/render/panels.h"

namespace hg::garden {

glm::vec2 morphSelectorPoint(const GardenSession& session) {
    const auto& w = session.morphWeights();
    if (!w) return trianglePoint(glm::vec3(1.0f / 3.0f));
    return trianglePoint(glm::vec3(static_cast<float>(w->barycentric[0]), static_cast<float>(w->barycentric[1]),
                                   static_cast<float>(w->barycentric[2])));
}

void drawMorphSection(GardenSession& session) {
    if (!session.hasMorph()) return;
    // Several morphs: the one the triangle steers is picked here (or by
    // selecting its result, or on its triangle on the ground).
    const std::vector<int> morphs = session.morphResults();
    if (morphs.size() > 1) {
        const auto& all = session.sculptures();
        if (ImGui::BeginCombo("morph", all[static_cast<std::size_t>(session.activeMorph())].name.c_str())) {
            for (int r : morphs) {
                const Sculpture& s = all[static_cast<std::size_t>(r)];
                if (!session.morphWeights(r)) continue;  // its sources are missing
                if (ImGui::Selectable(s.name.c_str(), r == session.activeMorph())) session.setActiveMorph(r);
            }
            ImGui::EndCombo();
        }
    }
    const MorphSpec& m = *session.morphSpec();
    const char* labels[3] = {m.sources[0].c_str(), m.sources[1].c_str(), m.sources[2].c_str()};
    glm::vec2 point = morphSelectorPoint(session);
    if (morphTriangleWidget(labels, point)) {
        const glm::vec3 b = triangleWeights(point);
        session.setMorphBarycentric({b.x, b.y, b.z});
    }
    if (const auto& w = session.morphWeights()) ImGui::Text("weights %.2f %.2f %.2f", w->w[0], w->w[1], w->w[2]);
}

}  // namespace hg::garden
