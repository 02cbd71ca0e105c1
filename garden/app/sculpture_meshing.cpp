#include "garden/app/sculpture_meshing.h"

#include "polygonizer/realtime/chunk_errors.h"
#include "polygonizer/realtime/chunk_layout.h"
#include "polygonizer/realtime/lod_pyramid.h"

namespace hg::garden {

PreparedMeshing::PreparedMeshing() = default;
PreparedMeshing::~PreparedMeshing() = default;
PreparedMeshing::PreparedMeshing(PreparedMeshing&&) noexcept = default;
PreparedMeshing& PreparedMeshing::operator=(PreparedMeshing&&) noexcept = default;

PreparedMeshing prepareMeshing(const voxel::Volume& volume, const MeshingShape& shape) {
    PreparedMeshing p;
    p.pyramid = std::make_unique<poly::LodPyramid>(volume, shape.levels);
    p.layout = std::make_unique<poly::ChunkLayout>(volume.frame, shape.chunkSize);
    if (shape.measureErrors) p.errors = std::make_unique<poly::ChunkErrors>(*p.pyramid, *p.layout);
    return p;
}

PreparedMeshing copyMeshing(const PreparedMeshing& source, const voxel::Volume& volume) {
    PreparedMeshing p;
    if (!source.pyramid) return p;
    p.pyramid = std::make_unique<poly::LodPyramid>(*source.pyramid, volume);
    p.layout = std::make_unique<poly::ChunkLayout>(*source.layout);
    if (source.errors) p.errors = std::make_unique<poly::ChunkErrors>(*source.errors, *p.pyramid, *p.layout);
    return p;
}

}  // namespace hg::garden
