// What the tool hand works with (DESIGN §6): the tool and its live sizes.
#pragma once

#include <array>
#include <cstdint>

#include "garden/sculpt/edit.h"
#include "garden/sculpt/impacts.h"

namespace hg::garden {

// The tool the tool hand works (DESIGN §6); sizes in metres of the world.
struct ToolSettings {
    enum class Kind { None, Carve, Add, Melt, Perturb, Impacts };
    Kind kind = Kind::None;      // None: the trigger picks the morph on the ground
    double radius = 0.05;        // carve, add, melt: the tool radius
    double softness = 2.0;       // melt: voxels
    QuadricShape shape = QuadricShape::Ellipsoid;
    std::array<double, 3> radii{0.08, 0.08, 0.08};  // perturb: ellipsoid radii, or torus R, r
    double strength = 2.0;       // perturb: voxels, > 0 pulls, < 0 pushes
    bool reverse = false;        // the action reversed: carve <-> add, pull <-> push
    // Impacts: sizes in metres, the volume in cubic centimetres.
    ImpactShape impactShape = ImpactShape::Sphere;
    double impactSize = 0.02;
    double compactionCm3 = 0.5;
    ImpactSpread spread = ImpactSpread::Uniform;
    double spreadSize = 0.05;    // metres across the aim, or the cone's half-angle in degrees
    int impactCount = 20;
    std::uint64_t seed = 1;      // grows by one with every pull
};

}  // namespace hg::garden
