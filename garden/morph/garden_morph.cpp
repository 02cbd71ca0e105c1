#include "garden/morph/garden_morph.h"

#include "voxel/sampler.h"

namespace hg::garden {

MorphTriangle morphTriangle(const Garden& garden) {
    MorphTriangle t;
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec3& p = garden.sculptures[garden.morph->sourceIndex[i]].placement.position;
        t.corners[i] = {p[0], p[2]};
    }
    return t;
}

std::string morphModelBox(const GardenLoad& load, frep::Box3& box, const ResolvedBoxes& resolved) {
    if (!load.garden || !load.garden->morph) return "the garden has no morph";
    const MorphSpec& m = *load.garden->morph;
    if (m.box) {
        box = *m.box;
        return "";
    }
    if (!load.morphError.empty()) return load.morphError;
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

MorphSourcesResult buildGardenMorphSources(const GardenLoad& load, std::uint64_t memoryLimit,
                                           const ResolvedBoxes& resolved) {
    MorphSourcesResult r;
    frep::Box3 box;
    r.error = morphModelBox(load, box, resolved);
    if (!r.error.empty()) return r;
    if (!load.morphError.empty()) {
        r.error = load.morphError;
        return r;
    }
    const MorphSpec& m = *load.garden->morph;
    std::array<const frep::Model*, 3> models{};
    for (std::size_t i = 0; i < 3; ++i) models[i] = &*load.sculptures[m.sourceIndex[i]].model;
    return buildMorphSources(models, box, m.resolution, m.band, memoryLimit);
}

std::array<double, 3> morphBalance(const MorphSpec& spec, const MorphSources& sources) {
    if (spec.balance) return *spec.balance;
    return balancingFactors(sources.surfaceGradient);
}

}  // namespace hg::garden
