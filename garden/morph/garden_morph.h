// From a loaded garden to a morph's inputs (each of Garden::morphs by its index): the triangle (the sources'
// positions on the ground), the shared model frame (the union of the
// sources' model boxes unless the file gives one), the source caches and
// the balancing factors (given in the file, or computed from the caches).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "garden/morph/morph_sources.h"
#include "garden/morph/morph_weights.h"
#include "garden/scene/garden_file.h"

namespace hg::garden {

// Sculpture `sculpture` (its index in Garden::sculptures) is one of the
// morph's three sources; ... of any of the garden's morphs.
bool feedsMorph(const MorphSpec& morph, std::size_t sculpture);
bool isMorphSource(const Garden& garden, std::size_t sculpture);

// Corner i is source i's position (x, z). `morph` < garden.morphs.size().
MorphTriangle morphTriangle(const Garden& garden, std::size_t morph);

// Model boxes already resolved for the garden's sculptures, by sculpture
// index (none: not resolved): a session that sampled the sources passes
// theirs, so they are not estimated a second time.
using ResolvedBoxes = std::vector<std::optional<frep::Box3>>;

// The shared model box: the morph's result.box, else the union of the
// sources' boxes (given, resolved, or found by voxel::resolveModelBox). ""
// on success, else why not (no such morph, a source is missing, or its box
// cannot be found).
std::string morphModelBox(const GardenLoad& load, std::size_t morph, frep::Box3& box, const ResolvedBoxes& resolved = {});

// The three caches at the morph's result.resolution and band.
MorphSourcesResult buildGardenMorphSources(const GardenLoad& load, std::size_t morph, std::uint64_t memoryLimit = 0,
                                           const ResolvedBoxes& resolved = {});

// The morph's balance when given, else balancingFactors(sources.surfaceGradient).
std::array<double, 3> morphBalance(const MorphSpec& spec, const MorphSources& sources);

}  // namespace hg::garden
