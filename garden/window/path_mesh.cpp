#include "garden/window/path_mesh.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace hg::garden {

poly::Mesh pathMesh(const PathSpec& path, double groundHeight) {
    poly::Mesh m;
    std::vector<glm::vec2> p;
    for (const Vec2& q : path.points) {
        const glm::vec2 v(static_cast<float>(q[0]), static_cast<float>(q[1]));
        if (p.empty() || glm::length(v - p.back()) > 1e-6f) p.push_back(v);
    }
    const bool closed = path.closed && p.size() > 2 && glm::length(p.back() - p.front()) > 1e-6f;
    if (path.closed && p.size() > 2 && !closed) p.pop_back();  // the last point written again as the first
    const std::size_t n = p.size();
    if (n < 2) return m;

    const float y = static_cast<float>(groundHeight) + 0.01f, h = static_cast<float>(path.width) * 0.5f;
    // The left of segment i (from p[i] to p[i + 1]) seen from above.
    auto side = [&](std::size_t i) {
        const glm::vec2 d = glm::normalize(p[(i + 1) % n] - p[i]);
        return glm::vec2(-d.y, d.x);
    };
    for (std::size_t i = 0; i < n; ++i) {
        const bool first = i == 0 && !closed, last = i + 1 == n && !closed;
        const glm::vec2 before = first ? side(0) : side((i + n - 1) % n);
        const glm::vec2 after = last ? side(n - 2) : side(i);
        // The mitre: along the two sides' bisector, as far as keeps both
        // edges h from their segments' lines.
        const glm::vec2 sum = before + after;
        const float length = glm::length(sum);
        glm::vec2 offset = before * h;
        if (length > 1e-6f) {
            const glm::vec2 bisector = sum / length;
            const float along = std::min(h / std::max(glm::dot(bisector, after), 1e-6f), kPathMitreLimit * h);
            offset = bisector * along;
        }
        for (const glm::vec2& c : {p[i] - offset, p[i] + offset}) {
            m.positions.insert(m.positions.end(), {c.x, y, c.y});
            m.normals.insert(m.normals.end(), {0.0f, 1.0f, 0.0f});
        }
    }
    const std::size_t segments = closed ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i) {
        const auto a = static_cast<std::uint32_t>(2 * i), b = static_cast<std::uint32_t>(2 * ((i + 1) % n));
        // Counter-clockwise seen from above (+y): right of a, left of a, left of b, right of b.
        m.indices.insert(m.indices.end(), {a, a + 1, b + 1, a, b + 1, b});
    }
    return m;
}

}  // namespace hg::garden
