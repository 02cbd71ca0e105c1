// The selection as a union of balls: it fills the deformed mesh's interior
// and stays inside it.
#include <gtest/gtest.h>

#include <cstdio>

#include "garden/deform/deformable_model.h"
#include "garden/deform/selection.h"
#include "tests/deform/deform_grids.h"
#include "voxel/volume.h"

namespace hg::garden::deform {
namespace {

using namespace hg::test::deform;

struct Cover {
    double inside = 0.0, selected = 0.0, selectedInside = 0.0;  // volumes
    double worstOutside = 0.0;  // the farthest selected sample outside the mesh
};

// The ball union and an inside test sampled on a grid of `h` over `lo..hi`.
Cover coverOf(const std::vector<SelectionBall>& balls, const std::function<double(glm::dvec3)>& insideBy,
              glm::dvec3 lo, glm::dvec3 hi, double h) {
    Cover c;
    const double cell = h * h * h;
    for (double z = lo.z; z <= hi.z; z += h)
        for (double y = lo.y; y <= hi.y; y += h)
            for (double x = lo.x; x <= hi.x; x += h) {
                const glm::dvec3 p(x, y, z);
                const double f = insideBy(p);  // > 0 inside the mesh, about a distance
                const bool selected = selectionField(balls, p) >= 0.0;
                if (f > 0.0) c.inside += cell;
                if (selected) c.selected += cell;
                if (selected && f > 0.0) c.selectedInside += cell;
                if (selected && f <= 0.0) c.worstOutside = std::max(c.worstOutside, -f);
            }
    return c;
}

TEST(Selection, BallsFillASphereMesh) {
    const double voxel = 0.02;
    const DeformMesh mesh = sphereMesh(glm::dvec3(0.013, -0.007, 0.004), 0.6, 5);
    const std::vector<SelectionBall> balls = selectionBalls(mesh, voxel);
    // The icosphere's faces lie within 0.0003 of its sphere.
    const auto inside = [](glm::dvec3 p) { return 0.6 - glm::length(p - glm::dvec3(0.013, -0.007, 0.004)); };
    const Cover c = coverOf(balls, inside, glm::dvec3(-0.7), glm::dvec3(0.7), 0.01);
    std::printf("sphere: %zu balls, selected %.4f of %.4f inside (%.2f%%), worst outside %.4f\n", balls.size(),
                c.selectedInside, c.inside, 100.0 * c.selectedInside / c.inside, c.worstOutside);
    ASSERT_FALSE(balls.empty());
    EXPECT_LE(balls.size(), 256u);
    EXPECT_GT(c.selectedInside, 0.98 * c.inside);
    EXPECT_LE(c.worstOutside, voxel);
}

// A model shrink-wrapped onto two lobes: its selection is the lobes.
TEST(Selection, BallsFillAWrappedModel) {
    const double voxel = 0.02;
    const voxel::Volume volume = gridOf(kTwoLobes, 0.6, voxel);
    DeformableModel model(sphereMesh(glm::dvec3(0.0), 0.75, 4), 0.05);
    model.deform(volume, DeformMode::Shrink, 120);
    const std::vector<SelectionBall> balls = selectionBalls(model.mesh(), voxel);
    const auto lobes = [](glm::dvec3 p) {
        return std::max(0.3 - glm::length(p + glm::dvec3(0.2, 0, 0)), 0.3 - glm::length(p - glm::dvec3(0.2, 0, 0)));
    };
    const Cover c = coverOf(balls, lobes, glm::dvec3(-0.6), glm::dvec3(0.6), 0.01);
    std::printf("two lobes: %zu balls, selected %.4f of %.4f inside (%.2f%%), outside %.4f, worst outside %.4f, "
                "mesh volume %.4f\n",
                balls.size(), c.selectedInside, c.inside, 100.0 * c.selectedInside / c.inside,
                c.selected - c.selectedInside, c.worstOutside, meshVolume(model.mesh()));
    EXPECT_LE(balls.size(), 256u);
    EXPECT_GT(c.selectedInside, 0.95 * c.inside);
    EXPECT_LE(c.worstOutside, 2.0 * voxel);
}

TEST(Selection, FieldIsTheMaxOverBallsInOrder) {
    const std::vector<SelectionBall> balls = {{glm::dvec3(0.0), 1.0}, {glm::dvec3(3.0, 0.0, 0.0), 0.5}};
    EXPECT_DOUBLE_EQ(selectionField(balls, glm::dvec3(0.0)), 1.0);
    EXPECT_DOUBLE_EQ(selectionField(balls, glm::dvec3(3.0, 0.0, 0.0)), 0.5);
    EXPECT_DOUBLE_EQ(selectionField(balls, glm::dvec3(2.0, 0.0, 0.0)), -0.5);  // both 0.5 away, one wins
    EXPECT_LT(selectionField({}, glm::dvec3(0.0)), -1e20);
}

TEST(Selection, AnOpenMeshSelectsNothing) {
    DeformMesh open = sphereMesh(glm::dvec3(0.0), 0.5, 2);
    open.triangles.pop_back();
    EXPECT_TRUE(selectionBalls(open, 0.02).empty());
}

}  // namespace
}  // namespace hg::garden::deform
