// What the tool hand works with (docs/design.md §6): the tool and its live sizes.
#pragma once

#include <array>
#include <cstdint>

#include "garden/sculpt/edit.h"
#include "garden/sculpt/impacts.h"

namespace hg::garden {

// The tool the tool hand works (docs/design.md §6); sizes in metres of the world.
struct ToolSettings {
    enum class Kind { None, Carve, Add, Melt, Perturb, Impacts, Move, Sketch, Smooth, Inflate };
    // None: the trigger picks the morph on the ground; Move: it selects,
    // moves and turns a sculpture (garden/app/session_moving.cpp); Sketch:
    // held, it draws an outline from a point on a sculpture, inflated and
    // joined (reverse: cut) on release (garden/app/session_sketching.cpp).
    Kind kind = Kind::None;
    double radius = 0.05;        // carve, add, melt (soft carve), smooth, inflate: the tool radius
    double softness = 2.0;       // melt: voxels
    // Smooth: the blend's weight in (0, 1]; inflate: voxels (reverse
    // deflates). Each stroke's is this times the pen's pressure.
    double smoothStrength = 0.5;
    double inflateStrength = 1.0;
    Falloff falloff = Falloff::Smooth;  // smooth and inflate
    QuadricShape shape = QuadricShape::Ellipsoid;
    std::array<double, 3> radii{0.08, 0.08, 0.08};  // perturb: ellipsoid radii, or torus R, r
    double strength = 2.0;       // perturb: voxels, > 0 pulls, < 0 pushes
    double perturbScale = 1.0;   // perturb: multiplies the radii (the live size of the quadric)
    bool reverse = false;        // the action reversed: carve <-> add, pull <-> push
    // What the sketch tool's next outline makes; the gestures choose it
    // (garden/app/session_gestures.cpp). Auto: joined to the sculpture it
    // starts on (reverse: cut), a new sculpture when begun in the air. New:
    // a new sculpture wherever it starts. Join, Cut: joined to or cut from
    // the sculpture it starts on (reverse swaps them). Model: a deformable
    // model around the sculpture it starts on, or the selected one, that
    // circling gestures shrink onto it or grow, making a selection.
    enum class SketchUse { Auto, New, Join, Cut, Model };
    SketchUse sketchUse = SketchUse::Auto;
    // Impacts: sizes in metres, the volume in cubic centimetres.
    ImpactShape impactShape = ImpactShape::Sphere;
    double impactSize = 0.02;
    double compactionCm3 = 0.5;
    ImpactSpread spread = ImpactSpread::Uniform;
    double spreadSize = 0.05;    // metres across the aim, or the cone's half-angle in degrees
    int impactCount = 20;
    std::uint64_t seed = 1;      // grows by one with every pull

    // What each tool keeps while another is in hand (by Kind): its reverse
    // and, for carve, add and melt, its radius (a radius of 0: never held
    // yet, it takes the radius in hand). selectTool swaps them in and out,
    // so R on perturb does not turn carve into add.
    struct Kept {
        bool reverse = false;
        double radius = 0.0;
    };
    std::array<Kept, 10> kept{};

    // What a perturbation placed now would have: radii times the scale,
    // strength with the reverse applied.
    std::array<double, 3> perturbRadii() const {
        return {radii[0] * perturbScale, radii[1] * perturbScale, radii[2] * perturbScale};
    }
    double perturbStrength() const { return reverse ? -strength : strength; }
};

// The one set of bounds every device and panel keeps the tool in (the
// desktop's keys and wheel, the headset's stick, both panels' sliders,
// replay intents): sizes in metres, strengths in their units.
//  * every size: the stroke radius, each of the perturbation's live radii
//    (radii times the scale), the impact size (at most kMaxImpactSize);
constexpr double kMinToolSize = 1e-3, kMaxToolSize = 5.0;
constexpr double kMinImpactSize = kMinToolSize, kMaxImpactSize = 1.0;
//  * the perturbation's scale, which multiplies its radii;
constexpr double kMinPerturbScale = 0.05, kMaxPerturbScale = 20.0;
//  * the perturbation's strength, voxels, either sign (the sign pulls or pushes);
constexpr double kMinPerturbStrength = 0.1, kMaxPerturbStrength = 50.0;
//  * the impacts' compaction volume, cubic centimetres;
constexpr double kMinCompactionCm3 = 0.01, kMaxCompactionCm3 = 100.0;
//  * smooth's blend weight, and inflate's strength in voxels (a stroke
//    also keeps it under its grid's band: stroke_segments.h, checkStroke).
constexpr double kMinSmoothStrength = 0.05, kMaxSmoothStrength = 1.0;
constexpr double kMinInflateStrength = 0.05, kMaxInflateStrength = 2.5;

// The tool's size times `factor` (a size step: the desktop's [ and ], the
// headset's stick up and down): the stroke radius, the perturbation's
// scale (its radii together, their ratio kept) or the impact size, as the
// tool in hand uses. A step stops exactly at a bound and never moves a
// size away from its bounds (one set by a script outside them stays until
// a step takes it in); a NaN factor does nothing. None and move have no
// size (the move tool's size step scales the selection instead,
// GardenSession::applyToolIntents).
void scaleToolSize(ToolSettings& tool, double factor);

// The tool's strength times `factor` (the headset's stick right and left):
// the perturbation's strength (its sign kept), the impacts' compaction
// volume, or smooth's or inflate's strength, bounded as sizes are. Other
// tools have no strength.
void scaleToolStrength(ToolSettings& tool, double factor);

// Every bounded setting brought into the bounds above: what the panels'
// sliders call after the user sets absolute values. Raw perturbation radii
// are kept so that times the scale they lie in the size bounds.
void clampToolSettings(ToolSettings& tool);

// Takes `kind` in hand: the tool put down keeps its reverse and radius,
// the tool taken up gets back its own (ToolSettings::kept). Every tool
// change of a device or panel goes through here.
void selectTool(ToolSettings& tool, ToolSettings::Kind kind);

// Whether the tool's size is ToolSettings::radius (carve, add, melt,
// smooth, inflate).
bool strokeTool(ToolSettings::Kind kind);

// "none", "carve", "add", "melt", "perturb", "impacts", "move", "sketch",
// "smooth", "inflate": the files' words (melt is shown as "soft carve":
// toolLabel).
const char* toolKindName(ToolSettings::Kind kind);
// What panels, help and the key table call the tool.
const char* toolLabel(ToolSettings::Kind kind);
// The stroke tool a stroke kind makes, reverse applied (carve <-> add;
// inflate <-> deflate is the strength's sign: strokeStrength).
StrokeTool strokeToolOf(const ToolSettings& tool);
// A smooth or inflate stroke's strength with the reverse and the pen's
// pressure in [0, 1] applied, and inflate's kept under `band`.
double strokeStrength(const ToolSettings& tool, double pressure, double band);

}  // namespace hg::garden
