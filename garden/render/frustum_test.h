// Where a box lies against a view frustum: the view's whole-sculpture and
// per-chunk culling (garden/window/garden_view.cpp) and the visibility
// test's "wholly in view" (visibility_queries.cpp) ask the same question.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace hg::garden {

enum class InView { Outside, Partly, Wholly };

// The box lo..hi seen through `modelViewProjection` (clip space: every
// corner tested against the six planes). Outside only when all eight
// corners are beyond one plane: conservative, so nothing visible is lost.
// Wholly when every corner is inside every plane.
inline InView frustumTest(const glm::mat4& modelViewProjection, const glm::vec3& lo, const glm::vec3& hi) {
    int outside[6] = {0, 0, 0, 0, 0, 0};
    bool allInside = true;
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 p = modelViewProjection * glm::vec4(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z, 1.0f);
        const bool out[6] = {p.x < -p.w, p.x > p.w, p.y < -p.w, p.y > p.w, p.z < -p.w, p.z > p.w};
        for (int k = 0; k < 6; ++k) {
            outside[k] += out[k];
            allInside = allInside && !out[k];
        }
    }
    for (int n : outside)
        if (n == 8) return InView::Outside;
    return allInside ? InView::Wholly : InView::Partly;
}

}  // namespace hg::garden
