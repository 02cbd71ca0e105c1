#include "garden/morph/morph_blend.h"

#include <tbb/parallel_for.h>

#include <memory>
#include <stdexcept>

#include "garden/morph/blend_block_vdb.h"

namespace hg::garden {

using namespace blend;

voxel::Volume makeMorphVolume(const MorphSources& sources) {
    voxel::Volume v;
    v.frame = sources.frame;
    v.normalization = 1.0;  // the blend is already in voxels
    v.kind = voxel::VolumeKind::NarrowBand;
    v.source.body = "morph";
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(-sources.frame.band);
    grid->setTransform(voxel::frameTransform(sources.frame));
    grid->setName("morph");
    v.grid().grid = grid;
    return v;
}

voxel::Volume blendMorph(const MorphSources& sources, const MorphWeights& weights) {
    std::string why = checkSources(sources);
    if (!why.empty()) throw std::invalid_argument(why);
    voxel::Volume result = makeMorphVolume(sources);
    const BlendInputs in = inputs(sources, weights);
    const std::vector<std::array<int, 3>> origins = voxel::alignedBoxes(in.box, kBlendBlock);
    std::vector<std::unique_ptr<FloatLeaf>> leaves(origins.size());
    std::vector<char> insideTile(origins.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, origins.size()), [&](const tbb::blocked_range<std::size_t>& r) {
        BlockValues values;
        for (std::size_t b = r.begin(); b != r.end(); ++b) {
            const auto& o = origins[b];
            blendBlock(o, in, values);
            float uniform = 0.0f;
            if (uniformClamped(values.v, values.mask, in.band, uniform)) {
                insideTile[b] = uniform > 0.0f;  // outside: the background already
                continue;
            }
            leaves[b] = std::make_unique<FloatLeaf>(openvdb::Coord(o[0], o[1], o[2]), -in.band, false);
            storeBlock(*leaves[b], values);
        }
    });
    openvdb::FloatTree& tree = voxel::vdb(result).tree();
    for (std::size_t b = 0; b < origins.size(); ++b) {
        const openvdb::Coord c(origins[b][0], origins[b][1], origins[b][2]);
        if (leaves[b]) tree.addLeaf(leaves[b].release());
        else if (insideTile[b]) tree.addTile(1, c, in.band, false);
    }
    return result;
}

}  // namespace hg::garden
