#include "garden/sculpt/tool_settings.h"

#include <algorithm>
#include <cmath>

namespace hg::garden {

namespace {

// `v` times `factor`, stopping at the bound it moves towards; a value
// already past that bound stays (a step never moves it farther out, nor
// jumps it the other way).
double stepWithin(double v, double factor, double lo, double hi) {
    if (std::isnan(factor) || factor == 1.0) return v;
    if (factor > 1.0) return v >= hi ? v : std::min(v * factor, hi);
    return v <= lo ? v : std::max(v * factor, lo);
}

// The perturbation's radii in use: three for an ellipsoid, R and r for a torus.
std::size_t radiiInUse(const ToolSettings& tool) { return tool.shape == QuadricShape::Torus ? 2 : 3; }

}  // namespace

bool strokeTool(ToolSettings::Kind kind) {
    using K = ToolSettings::Kind;
    return kind == K::Carve || kind == K::Add || kind == K::Melt || kind == K::Smooth || kind == K::Inflate;
}

void selectTool(ToolSettings& tool, ToolSettings::Kind kind) {
    if (kind == tool.kind) return;
    ToolSettings::Kept& down = tool.kept[static_cast<std::size_t>(tool.kind)];
    down.reverse = tool.reverse;
    if (strokeTool(tool.kind)) down.radius = tool.radius;
    tool.kind = kind;
    const ToolSettings::Kept& up = tool.kept[static_cast<std::size_t>(kind)];
    tool.reverse = up.reverse;
    if (strokeTool(kind) && up.radius > 0.0) tool.radius = up.radius;
}

void scaleToolSize(ToolSettings& tool, double factor) {
    using K = ToolSettings::Kind;
    switch (tool.kind) {
        case K::Carve:
        case K::Add:
        case K::Melt:
        case K::Smooth:
        case K::Inflate: tool.radius = stepWithin(tool.radius, factor, kMinToolSize, kMaxToolSize); break;
        case K::Perturb: {
            // The scale within its own bounds and those that keep every live
            // radius a size: the radii grow and shrink together.
            double lo = kMinPerturbScale, hi = kMaxPerturbScale;
            for (std::size_t a = 0; a < radiiInUse(tool); ++a) {
                const double r = tool.radii[a];
                if (!(r > 0.0)) continue;
                lo = std::max(lo, kMinToolSize / r);
                hi = std::min(hi, kMaxToolSize / r);
            }
            tool.perturbScale = stepWithin(tool.perturbScale, factor, lo, hi);
            break;
        }
        case K::Impacts: tool.impactSize = stepWithin(tool.impactSize, factor, kMinImpactSize, kMaxImpactSize); break;
        case K::None:
        case K::Move:
        case K::Sketch: break;
    }
}

void scaleToolStrength(ToolSettings& tool, double factor) {
    using K = ToolSettings::Kind;
    if (tool.kind == K::Perturb) {
        const double k = stepWithin(std::fabs(tool.strength), factor, kMinPerturbStrength, kMaxPerturbStrength);
        tool.strength = std::copysign(k, tool.strength);
    } else if (tool.kind == K::Impacts) {
        tool.compactionCm3 = stepWithin(tool.compactionCm3, factor, kMinCompactionCm3, kMaxCompactionCm3);
    } else if (tool.kind == K::Smooth) {
        tool.smoothStrength = stepWithin(tool.smoothStrength, factor, kMinSmoothStrength, kMaxSmoothStrength);
    } else if (tool.kind == K::Inflate) {
        tool.inflateStrength = stepWithin(tool.inflateStrength, factor, kMinInflateStrength, kMaxInflateStrength);
    }
}

void clampToolSettings(ToolSettings& tool) {
    const auto clampFinite = [](double& v, double lo, double hi) { v = std::isnan(v) ? lo : std::clamp(v, lo, hi); };
    clampFinite(tool.radius, kMinToolSize, kMaxToolSize);
    clampFinite(tool.perturbScale, kMinPerturbScale, kMaxPerturbScale);
    for (std::size_t a = 0; a < radiiInUse(tool); ++a)
        clampFinite(tool.radii[a], kMinToolSize / tool.perturbScale, kMaxToolSize / tool.perturbScale);
    double k = std::fabs(tool.strength);
    clampFinite(k, kMinPerturbStrength, kMaxPerturbStrength);
    tool.strength = std::copysign(k, tool.strength);
    clampFinite(tool.impactSize, kMinImpactSize, kMaxImpactSize);
    clampFinite(tool.compactionCm3, kMinCompactionCm3, kMaxCompactionCm3);
    clampFinite(tool.smoothStrength, kMinSmoothStrength, kMaxSmoothStrength);
    clampFinite(tool.inflateStrength, kMinInflateStrength, kMaxInflateStrength);
}

const char* toolKindName(ToolSettings::Kind kind) {
    using K = ToolSettings::Kind;
    switch (kind) {
        case K::None: return "none";
        case K::Carve: return "carve";
        case K::Add: return "add";
        case K::Melt: return "melt";
        case K::Perturb: return "perturb";
        case K::Impacts: return "impacts";
        case K::Move: return "move";
        case K::Sketch: return "sketch";
        case K::Smooth: return "smooth";
        case K::Inflate: return "inflate";
    }
    return "none";
}

const char* toolLabel(ToolSettings::Kind kind) {
    return kind == ToolSettings::Kind::Melt ? "soft carve" : toolKindName(kind);
}

StrokeTool strokeToolOf(const ToolSettings& tool) {
    using K = ToolSettings::Kind;
    switch (tool.kind) {
        case K::Add: return tool.reverse ? StrokeTool::Carve : StrokeTool::Add;
        case K::Melt: return StrokeTool::Melt;
        case K::Smooth: return StrokeTool::Smooth;
        case K::Inflate: return StrokeTool::Inflate;
        default: return tool.reverse ? StrokeTool::Add : StrokeTool::Carve;
    }
}

double strokeStrength(const ToolSettings& tool, double pressure, double band) {
    const double p = std::isnan(pressure) ? 1.0 : std::clamp(pressure, 0.0, 1.0);
    if (tool.kind == ToolSettings::Kind::Smooth)
        return std::clamp(tool.smoothStrength * p, kMinSmoothStrength * 0.1, kMaxSmoothStrength);
    // Inflate: under the band (checkStroke), a hair inside it.
    const double k = std::min(tool.inflateStrength * p, 0.95 * band);
    return tool.reverse ? -k : k;
}

}  // namespace hg::garden
