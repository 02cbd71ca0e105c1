// What the tool hand works with (docs/design.md §6): the tool and its live sizes.
#pragma once

#include <array>
#include <cstdint>

#include "garden/sculpt/edit.h"
#include "garden/sculpt/impacts.h"

namespace hg::garden {

// The tool the tool hand works (docs/design.md §6); sizes in metres of the world.
struct ToolSettings {
    enum class Kind { None, Carve, Add, Melt, Perturb, Impacts, Move };
    // None: the trigger picks the morph on the ground; Move: it selects,
    // moves and turns a sculpture (garden/app/session_moving.cpp).
    Kind kind = Kind::None;
    double radius = 0.05;        // carve, add, melt: the tool radius
    double softness = 2.0;       // melt: voxels
    QuadricShape shape = QuadricShape::Ellipsoid;
    std::array<double, 3> radii{0.08, 0.08, 0.08};  // perturb: ellipsoid radii, or torus R, r
    double strength = 2.0;       // perturb: voxels, > 0 pulls, < 0 pushes
    double perturbScale = 1.0;   // perturb: multiplies the radii (the live size of the quadric)
    bool reverse = false;        // the action reversed: carve <-> add, pull <-> push
    // Impacts: sizes in metres, the volume in cubic centimetres.
    ImpactShape impactShape = ImpactShape::Sphere;
    double impactSize = 0.02;
    double compactionCm3 = 0.5;
    ImpactSpread spread = ImpactSpread::Uniform;
    double spreadSize = 0.05;    // metres across the aim, or the cone's half-angle in degrees
    int impactCount = 20;
    std::uint64_t seed = 1;      // grows by one with every pull

    // What a perturbation placed now would have: radii times the scale,
    // strength with the reverse applied.
    std::array<double, 3> perturbRadii() const {
        return {radii[0] * perturbScale, radii[1] * perturbScale, radii[2] * perturbScale};
    }
    double perturbStrength() const { return reverse ? -strength : strength; }
};

// The bounds scaleToolSize keeps sizes in.
constexpr double kMinToolRadius = 1e-3, kMaxToolRadius = 5.0;          // metres
constexpr double kMinPerturbScale = 0.05, kMaxPerturbScale = 20.0;
constexpr double kMinImpactSize = 1e-3, kMaxImpactSize = 1.0;          // metres

// The tool's size times `factor` (the desktop's [ and ] keys, x1.25 a
// press): the stroke radius, the perturbation's scale or the impact size,
// as the tool in hand uses; clamped to the bounds above. None and Move
// have no size.
void scaleToolSize(ToolSettings& tool, double factor);

// "none", "carve", "add", "melt", "perturb", "impacts", "move".
const char* toolKindName(ToolSettings::Kind kind);

}  // namespace hg::garden
