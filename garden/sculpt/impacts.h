// Aging by impacts (seed 002): a trigger pull fires N small tools along rays
// drawn from a seeded distribution about the aim (uniform or gaussian over a
// disc across it, or uniform in a cone of directions); each ray meets the
// surface, and its tool goes in as deep as removes the compaction volume
// from a locally flat surface. The series is one edit. Its rays, relative to
// the sculpture's model box, can be applied again to another sculpture.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "garden/sculpt/edit.h"
#include "voxel/volume.h"

namespace hg::garden {

enum class ImpactSpread { Uniform, Gaussian, Cone };
const char* impactSpreadName(ImpactSpread s);

// Sizes in model units (the session converts from metres).
struct ImpactTool {
    ImpactShape shape = ImpactShape::Sphere;
    double size = 0.02;                 // sphere radius, chisel edge length, square side
    double volume = 2e-6;               // compaction volume per impact, cubic model units
    ImpactSpread spread = ImpactSpread::Uniform;
    double spreadSize = 0.05;           // uniform: disc radius; gaussian: sigma; cone: half-angle, radians
    int count = 10;                     // impacts per trigger pull
    std::uint64_t seed = 1;
};

struct ImpactRay {
    ModelPoint origin{};
    ModelPoint direction{0, 0, -1};  // unit
};

// "" when the tool's values are usable, else why not.
std::string checkImpactTool(const ImpactTool& tool, double voxelSize);

// The tool's rays about `aim`: the same seed gives the same rays.
std::vector<ImpactRay> drawImpactRays(const ImpactRay& aim, const ImpactTool& tool);

// How deep the tool goes to remove `volume` from a flat surface.
double impactDepth(ImpactShape shape, double size, double volume);

// The impact of one ray on the grid (none when it misses), with its reach.
std::optional<Impact> castImpact(const voxel::Volume& grid, const ImpactRay& ray, const ImpactTool& tool,
                                 const FieldUnits& units);
frep::Box3 impactReach(const Impact& m, const FieldUnits& units);

// Rays relative to a model box (origins as fractions of it), so a series
// recorded on one sculpture lands on another; and back.
std::vector<ImpactRay> raysInBox(const std::vector<ImpactRay>& rays, const frep::Box3& box);
std::vector<ImpactRay> raysFromBox(const std::vector<ImpactRay>& relative, const frep::Box3& box);

}  // namespace hg::garden
