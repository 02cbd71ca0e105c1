#include "garden/window/view_lights.h"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "garden/scene/to_glm.h"

namespace hg::garden {

void addGardenLights(const Garden& g, View& v) {
    glm::vec3 ambient(0.0f);
    bool anyAmbient = false;
    std::vector<std::pair<float, PointLight>> points;
    for (const Light& l : g.lights) {
        const glm::vec3 c = glm::vec3(l.color[0], l.color[1], l.color[2]) * static_cast<float>(l.intensity);
        if (l.kind == Light::Kind::Ambient) {
            ambient += c;
            anyAmbient = true;
        } else if (l.kind == Light::Kind::Directional && v.lights.size() < static_cast<std::size_t>(kMaxLights)) {
            v.lights.push_back(DirectionalLight{-toGlm(l.direction), c});
        } else if (l.kind == Light::Kind::Point) {
            const PointLight p{toGlm(l.position), c, static_cast<float>(l.range)};
            points.emplace_back(std::max(0.0f, glm::distance(v.eye, p.position) - p.range), p);
        }
    }
    const std::size_t kept = std::min(points.size(), static_cast<std::size_t>(kMaxPointLights));
    std::partial_sort(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(kept), points.end(),
                      [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < kept; ++i) v.pointLights.push_back(points[i].second);
    if (v.lights.empty() && v.pointLights.empty()) {  // a garden without lights still shows its sculptures
        v.lights.push_back(DirectionalLight{glm::vec3(0.4f, 0.8f, 0.45f), glm::vec3(0.9f)});
        v.lights.push_back(DirectionalLight{glm::vec3(-0.5f, 0.3f, -0.6f), glm::vec3(0.25f)});
    }
    v.ambient = anyAmbient ? ambient : glm::vec3(0.18f);
}

}  // namespace hg::garden
