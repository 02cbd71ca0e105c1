#include "garden/sculpt/tool_settings.h"

#include <algorithm>
#include <cmath>

namespace hg::garden {

void scaleToolSize(ToolSettings& tool, double factor) {
    using K = ToolSettings::Kind;
    if (std::isnan(factor)) return;  // clamping would keep the NaN
    switch (tool.kind) {
        case K::Carve:
        case K::Add:
        case K::Melt:
            tool.radius = std::clamp(tool.radius * factor, kMinToolRadius, kMaxToolRadius);
            break;
        case K::Perturb:
            tool.perturbScale = std::clamp(tool.perturbScale * factor, kMinPerturbScale, kMaxPerturbScale);
            break;
        case K::Impacts:
            tool.impactSize = std::clamp(tool.impactSize * factor, kMinImpactSize, kMaxImpactSize);
            break;
        case K::None:
        case K::Move:
            break;
    }
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
    }
    return "none";
}

}  // namespace hg::garden
