// The lights a frame draws from a garden's lights (garden/desktop/view_lights):
// point lights nearest the visitor first, caps, colours times intensities,
// and defaults for a garden that has none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "garden/window/view_lights.h"

namespace hg::garden {
namespace {

Light pointAt(double x, double range, double intensity = 1.0) {
    Light l;
    l.kind = Light::Kind::Point;
    l.position = {x, 2.0, 0.0};
    l.range = range;
    l.intensity = intensity;
    return l;
}

TEST(ViewLights, PointLightsNearestTheVisitorAreDrawnUpToTheCap) {
    // Twelve lamps along x every 5 m, each reaching 3 m; the visitor at
    // x = 31 is nearest the lamps at 30, 35, 25, 40, ...
    Garden g;
    for (int i = 0; i < 12; ++i) g.lights.push_back(pointAt(5.0 * i, 3.0));
    View v;
    v.eye = glm::vec3(31.0f, 2.0f, 0.0f);
    addGardenLights(g, v);
    ASSERT_EQ(v.pointLights.size(), static_cast<std::size_t>(kMaxPointLights));
    std::vector<float> xs;
    for (const PointLight& p : v.pointLights) xs.push_back(p.position.x);
    std::sort(xs.begin(), xs.end());
    const std::vector<float> nearest = {15, 20, 25, 30, 35, 40, 45, 50};
    EXPECT_EQ(xs, nearest);
    // Point lights alone are enough: no default sun is added.
    EXPECT_TRUE(v.lights.empty());
}

TEST(ViewLights, ColoursAreScaledByIntensityAndAmbientsAddUp) {
    Garden g;
    Light warm = pointAt(0.0, 7.0, 20.0);
    warm.color = {1.0f, 0.5f, 0.25f};
    g.lights.push_back(warm);
    Light a;
    a.kind = Light::Kind::Ambient;
    a.intensity = 0.1;
    g.lights.push_back(a);
    g.lights.push_back(a);
    Light sun;
    sun.kind = Light::Kind::Directional;
    sun.direction = {0.0, -1.0, 0.0};
    g.lights.push_back(sun);
    View v;
    addGardenLights(g, v);
    ASSERT_EQ(v.pointLights.size(), 1u);
    EXPECT_FLOAT_EQ(v.pointLights[0].color.g, 10.0f);
    EXPECT_FLOAT_EQ(v.pointLights[0].range, 7.0f);
    EXPECT_NEAR(v.ambient.r, 0.2f, 1e-6);
    ASSERT_EQ(v.lights.size(), 1u);
    EXPECT_FLOAT_EQ(v.lights[0].direction.y, 1.0f) << "towards the light";
}

TEST(ViewLights, AGardenWithoutLightsStillShowsItsSculptures) {
    Garden g;
    View v;
    addGardenLights(g, v);
    EXPECT_FALSE(v.lights.empty());
    EXPECT_GT(v.ambient.r, 0.0f);
    EXPECT_TRUE(v.pointLights.empty());
}

}  // namespace
}  // namespace hg::garden
