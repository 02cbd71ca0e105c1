// The morph selector's geometry, apart from ImGui so it can be tested as
// plain functions. The triangle's local frame has its corners at
//   c0 = (0, 0), c1 = (1, 0), c2 = (0.5, sqrt(3)/2)
// (equilateral, unit sides, y up); a point inside is a blend of the three
// key sculptures with its barycentric weights (w0, w1, w2).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace hg::garden {

constexpr float kMorphTriangleHeight = 0.866025403784f;  // sqrt(3) / 2

const std::array<glm::vec2, 3>& morphTriangleCorners();

// Barycentric weights of `p` (they sum to 1; all >= 0 inside).
glm::vec3 triangleWeights(const glm::vec2& p);
// The point with weights `w` (normalized to sum 1 first).
glm::vec2 trianglePoint(const glm::vec3& w);
// The nearest point of the closed triangle: `p` itself when inside.
glm::vec2 clampToTriangle(const glm::vec2& p);

// Where the widget puts the triangle on screen: ImGui's y grows downwards,
// so local (0, 0) is the bottom-left corner at origin + (0, side * height).
struct MorphTriangleLayout {
    glm::vec2 origin;   // top-left of the triangle's bounding box, pixels
    float side;         // pixels per local unit
    glm::vec2 size;     // the whole widget, labels included, from the cursor
};
MorphTriangleLayout morphTriangleLayout(const glm::vec2& cursor, float side, float lineHeight);
glm::vec2 triangleToScreen(const MorphTriangleLayout& layout, const glm::vec2& local);
glm::vec2 screenToTriangle(const MorphTriangleLayout& layout, const glm::vec2& screen);

}  // namespace hg::garden
