#include "garden/render/morph_triangle.h"

#include "garden/morph/morph_weights.h"

namespace hg::garden {

const std::array<glm::vec2, 3>& morphTriangleCorners() {
    static const std::array<glm::vec2, 3> corners{glm::vec2(0.0f, 0.0f), glm::vec2(1.0f, 0.0f),
                                                  glm::vec2(0.5f, kMorphTriangleHeight)};
    return corners;
}

glm::vec3 triangleWeights(const glm::vec2& p) {
    // With c0 at the origin and c1 on the x axis the solve is closed form.
    const float w2 = p.y / kMorphTriangleHeight;
    const float w1 = p.x - 0.5f * w2;
    return {1.0f - w1 - w2, w1, w2};
}

glm::vec2 trianglePoint(const glm::vec3& w) {
    const float sum = w.x + w.y + w.z;
    const glm::vec3 n = sum != 0.0f ? w / sum : glm::vec3(1.0f / 3.0f);
    const auto& c = morphTriangleCorners();
    return n.x * c[0] + n.y * c[1] + n.z * c[2];
}

glm::vec2 clampToTriangle(const glm::vec2& p) {
    // The selector's clamp (garden/morph) on the widget's own corners.
    MorphTriangle t;
    const auto& c = morphTriangleCorners();
    for (std::size_t i = 0; i < 3; ++i) t.corners[i] = {c[i].x, c[i].y};
    const Point2 q = clampToTriangle(t, {p.x, p.y});
    return {static_cast<float>(q[0]), static_cast<float>(q[1])};
}

MorphTriangleLayout morphTriangleLayout(const glm::vec2& cursor, float side, float lineHeight) {
    // A label line above the apex and one below the base; half a line of
    // padding on each side for the labels that overhang the corners.
    const float pad = 0.5f * lineHeight;
    MorphTriangleLayout layout;
    layout.side = side;
    layout.origin = cursor + glm::vec2(pad + side * 0.25f, lineHeight + pad);
    layout.size = glm::vec2(side * 1.5f + 2.0f * pad, side * kMorphTriangleHeight + 2.0f * (lineHeight + pad));
    return layout;
}

glm::vec2 triangleToScreen(const MorphTriangleLayout& layout, const glm::vec2& local) {
    return layout.origin + layout.side * glm::vec2(local.x, kMorphTriangleHeight - local.y);
}

glm::vec2 screenToTriangle(const MorphTriangleLayout& layout, const glm::vec2& screen) {
    const glm::vec2 d = (screen - layout.origin) / layout.side;
    return {d.x, kMorphTriangleHeight - d.y};
}

}  // namespace hg::garden
