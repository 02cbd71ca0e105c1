#include "garden/render/shapes.h"

#include <cmath>
#include <stdexcept>

namespace hg::garden {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

poly::Mesh uvSphereMesh(float radius, int slices, int stacks) {
    if (slices < 3 || stacks < 2) throw std::invalid_argument("uvSphereMesh: at least 3 slices and 2 stacks");
    poly::Mesh mesh;
    const int columns = slices + 1;
    for (int i = 0; i <= stacks; ++i) {
        // Exact poles and seam, so the repeated vertices coincide bit for bit.
        const double theta = kPi * i / stacks;
        const double sinTheta = (i == 0 || i == stacks) ? 0.0 : std::sin(theta);
        const double cosTheta = i == 0 ? 1.0 : i == stacks ? -1.0 : std::cos(theta);
        for (int j = 0; j <= slices; ++j) {
            const double phi = 2.0 * kPi * (j % slices) / slices;
            const float n[3] = {static_cast<float>(sinTheta * std::cos(phi)), static_cast<float>(cosTheta),
                                static_cast<float>(sinTheta * std::sin(phi))};
            for (float c : n) {
                mesh.normals.push_back(c);
                mesh.positions.push_back(radius * c);
            }
        }
    }
    auto at = [columns](int i, int j) { return static_cast<std::uint32_t>(i * columns + j); };
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            // With y up and phi turning from +x towards +z, (a, d, c) and
            // (a, c, b) wind counter-clockwise seen from outside; the pole
            // rows would each give one degenerate triangle.
            if (i != 0) mesh.indices.insert(mesh.indices.end(), {a, d, c});
            if (i != stacks - 1) mesh.indices.insert(mesh.indices.end(), {a, c, b});
        }
    }
    return mesh;
}

std::vector<glm::vec3> circlePoints(const glm::vec3& center, float radius, const glm::vec3& u, const glm::vec3& v,
                                    int segments) {
    std::vector<glm::vec3> points;
    points.reserve(static_cast<std::size_t>(segments));
    for (int k = 0; k < segments; ++k) {
        const double a = 2.0 * kPi * k / segments;
        points.push_back(center + radius * (static_cast<float>(std::cos(a)) * u + static_cast<float>(std::sin(a)) * v));
    }
    return points;
}

}  // namespace hg::garden
