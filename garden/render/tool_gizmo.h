// Tool gizmos (docs/design.md §6): the tool in hand drawn where its aim ray meets a
// sculpture, at its live size and shape (a wire sphere of the stroke
// radius, the perturbation's ellipsoid or torus, the impacts' spread), the
// move tool's ring and axes on the selected sculpture, and the selected
// sculpture's mirror plane. The geometry is plain line lists (tested without
// GL); drawToolGizmos draws them with the renderer's lines.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "garden/app/sculpture.h"
#include "garden/hands/hand_state.h"
#include "garden/render/renderer.h"
#include "garden/sculpt/tool_settings.h"

namespace hg::garden {

class GardenSession;

// One line list of a gizmo. Faint parts (the back of a sphere inside the
// sculpture, the mirror plane's grid) are drawn over everything, the rest
// depth tested.
struct GizmoLines {
    std::vector<glm::vec3> points;
    LineMode mode = LineMode::Loop;
    glm::vec4 color{1.0f};
    bool overEverything = false;
};

// The colour of the tool as it acts now (carve reversed is add, a
// perturbation reversed pushes): sRGB, opaque.
glm::vec4 toolColor(const ToolSettings& tool);

// The tool's gizmo at `at` (world), the aim ray coming from `aimOrigin`
// along the unit `aimDirection`, seen from `eye`. Empty for none and move.
std::vector<GizmoLines> toolGizmo(const ToolSettings& tool, const glm::vec3& at, const glm::vec3& aimOrigin,
                                  const glm::vec3& aimDirection, const glm::vec3& eye);
// The move tool's ring and axes on a sculpture (sculpture_gizmos.h's ring).
std::vector<GizmoLines> moveGizmo(const Sculpture& s);
// The sculpture's mirror plane as a gridded quad over its model box; empty
// without a mirror.
std::vector<GizmoLines> mirrorGizmo(const Sculpture& s);

// The selected sculpture (the one the last stroke edited) outlined: the
// edges of its box in the world, and faintly through whatever hides them.
std::vector<GizmoLines> selectionGizmo(const Sculpture& s);

// Draws the gizmos of this frame after the garden (GardenView::render):
// the selected sculpture's mirror plane, the move gizmo on the selection
// while the move tool is in hand, and the tool where `aim` (the tool hand's
// ray; none while the pointer is on a panel) meets a sculpture.
void drawToolGizmos(Renderer& renderer, const GardenSession& session, const std::optional<Pose>& aim);
// The same with the point where `aim` meets a sculpture already found
// (GardenSession::toolHit; none: it meets none), so a headset's two eyes
// share one ray cast.
void drawToolGizmos(Renderer& renderer, const GardenSession& session, const std::optional<Pose>& aim,
                    const std::optional<glm::vec3>& hit);

}  // namespace hg::garden
