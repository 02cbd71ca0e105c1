// The tools' first sizes fitted to what the user sees (issue 23): a fixed
// 5 cm radius is a barely visible ring on a sculpture 3 m away and a huge
// one on a small sculpture close by. A few percent of the sculpture in view
// is what sculpting programs start with.
#pragma once

namespace hg::garden {

class GardenSession;

// The share of the sculpture's size (the diagonal of its box in the world)
// each tool starts with.
constexpr double kStartRadiusShare = 0.03;       // carve, add, melt: the radius
constexpr double kStartPerturbShare = 0.05;      // perturb: its largest radius
constexpr double kStartImpactShare = 0.01;       // impacts: the impact size

// The sculpture in view: of the sculptures in front of the eye, the one
// nearest the view's centre line (by angle); -1 when none is in front.
int sculptureInView(const GardenSession& session);

// Sets the session's tool sizes (every stroke tool's radius, the
// perturbation's scale, the impact size) to those shares of the sculpture
// in view, within the tools' bounds; nothing when none is in view. For a
// session that starts without saved tool settings.
void sizeToolsToView(GardenSession& session);

}  // namespace hg::garden
