// The selection a deformable model makes (issue 22, docs/sketching.md
// "Deformable model"), as FRep so that whatever is made with it exports
// exactly: the union (max) of balls covering the mesh's interior. The
// field is plain arithmetic (+ - * sqrt max) with constants, written in
// HyperFun the same way, so the exported text evaluates to the same values.
#pragma once

#include <cmath>
#include <vector>

#include "garden/deform/deform_mesh.h"

namespace hg::garden::deform {

struct SelectionBall {
    glm::dvec3 centre{0.0};
    double radius = 0.0;  // model units
};

// Greedy medial balls from the interior's distance field (sampled at
// `voxelSize`): the deepest interior point not yet covered gets the
// largest ball that stays inside the mesh, until the balls cover all but
// `uncovered` of the interior's voxels or there are `maxBalls`. Centres and
// radii are the values sketch::hfConstant gives (what HyperFun reads back
// from sketch::hfDecimal's text). Empty for an empty or open mesh.
std::vector<SelectionBall> selectionBalls(const DeformMesh& mesh, double voxelSize, int maxBalls = 256,
                                          double uncovered = 0.03);

// The selection's field at p: max over the balls, in list order, of
// radius - sqrt(dx*dx + dy*dy + dz*dz) (>= 0 inside); -1e30 with no ball.
inline double selectionField(const std::vector<SelectionBall>& balls, glm::dvec3 p) {
    double f = -1e30;
    for (const SelectionBall& b : balls) {
        const double dx = p.x - b.centre.x, dy = p.y - b.centre.y, dz = p.z - b.centre.z;
        const double ball = b.radius - std::sqrt(dx * dx + dy * dy + dz * dz);
        f = ball > f ? ball : f;  // HyperFun's max(f, ball) with f first
    }
    return f;
}

}  // namespace hg::garden::deform
