// The lights a frame draws, from the garden's lights: ambient ones summed,
// the first kMaxLights directional ones, and of the point lights the
// kMaxPointLights whose reach comes nearest the eye (a garden may hold many
// along its paths; those around the visitor are drawn).
#pragma once

#include "garden/render/renderer.h"
#include "garden/scene/garden.h"

namespace hg::garden {

// Fills v.lights, v.pointLights and v.ambient; v.eye must be set. A garden
// without directional or point lights gets a default sun and fill, and one
// without ambient lights a default ambient, so its sculptures still show.
void addGardenLights(const Garden& g, View& v);

}  // namespace hg::garden
