#include "garden/morph/garden_morph.h"

#include <algorithm>

#include "voxel/sampler.h"

namespace hg::garden {

bool feedsMorph(const MorphSpec& morph, std::size_t sculpture) {
    return std::find(morph.sourceIndex.begin(), morph.sourceIndex.end(), sculpture) != morph.sourceIndex.end();
}

bool isMorphSource(const Garden& garden, std::size_t sculpture) {
    return std::any_of(garden.morphs.begin(), garden.morphs.end(),
                       [sculpture](const MorphSpec& m) { return feedsMorph(m, sculpture); });
}

MorphTriangle morphTriangle(const Garden& garden, std::size_t morph) {
    MorphTriangle t;
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec3& p = garden.sculptures[garden.morphs[morph].sourceIndex[i]].placement.position;
        t.corners[i] = {p[0], p[2]};
    }
    return t;
}

std::string morphModelBox(const GardenLoad& load, std::size_t morph, frep::Box3& box, const ResolvedBoxes& resolved) {
    if (!load.garden || morph >= load.garden->morphs.size()) return "the garden has no such morph";
    const MorphSpec& m = load.garden->morphs[morph];
    if (m.box) {
        box = *m.box;
        return "";
    }
    if (morph < load.morphErrors.size() && !load.morphErrors[morph].empty()) return load.morphErrors[morph];
    std::array<frep::Box3, 3> boxes;
    for (std::size_t i = 0; i < 3; ++i) {
        const SculptureSpec& spec = load.garden->sculptures[m.sourceIndex[i]];
        if (m.sourceIndex[i] < resolved.size() && resolved[m.sourceIndex[i]]) {
            boxes[i] = *resolved[m.sourceIndex[i]];
            continue;
        }
        voxel::ModelBox found;
        std::string why = voxel::resolveModelBox(*load.sculptures[m.sourceIndex[i]].model, spec.box, found);
        if (!why.empty()) return "morph source '" + spec.name + "': " + why;
        boxes[i] = found.box;
    }
    box = unionBox(boxes);
    return "";
}

MorphSourcesResult buildGardenMorphSources(const GardenLoad& load, std::size_t morph, std::uint64_t memoryLimit,
                                           const ResolvedBoxes& resolved) {
    MorphSourcesResult r;
    frep::Box3 box;
    r.error = morphModelBox(load, morph, box, resolved);
    if (!r.error.empty()) return r;
    if (morph < load.morphErrors.size() && !load.morphErrors[morph].empty()) {
        r.error = load.morphErrors[morph];
        return r;
    }
    const MorphSpec& m = load.garden->morphs[morph];
    std::array<const frep::Model*, 3> models{};
    for (std::size_t i = 0; i < 3; ++i) models[i] = &*load.sculptures[m.sourceIndex[i]].model;
    return buildMorphSources(models, box, m.resolution, m.band, memoryLimit);
}

std::array<double, 3> morphBalance(const MorphSpec& spec, const MorphSources& sources) {
    if (spec.balance) return *spec.balance;
    return balancingFactors(sources.surfaceGradient);
}

}  // namespace hg::garden
