#include "garden/app/sculpture_sampling.h"

#include <sstream>

#include "polygonizer/mesh.h"
#include "voxel/mesh_volume.h"
#include "voxel/scalar_volume.h"

namespace hg::garden {

std::string sampledSourceKey(const SculptureSpec& spec) {
    if (spec.scan || spec.mesh) return "";
    std::ostringstream key;
    key.precision(17);
    key << spec.file << '\n' << spec.body << '\n' << spec.resolution << ' ' << spec.band;
    for (double a : spec.a) key << ' ' << a;
    if (spec.box)
        for (int i = 0; i < 3; ++i) key << ' ' << spec.box->lo[i] << ' ' << spec.box->hi[i];
    return key.str();
}

voxel::VoxelizeResult sampleSculptureSource(const SculptureSpec& spec, const SculptureLoad& load,
                                            const voxel::VolumeRequest& request, io::Progress* progress) {
    if (load.model) {
        voxel::SampleOptions options;
        options.progress = progress;
        return voxel::voxelize(*load.model, request, options);
    }
    voxel::VoxelizeResult r;
    if (load.mesh && spec.mesh) {
        voxel::MeshLevelSetRequest m;
        m.box = request.box;
        m.resolution = request.resolution;
        m.band = request.band;
        m.source = request.source;
        if (m.source.file.empty()) m.source.file = spec.fileAsWritten;
        r = voxel::levelSetFromMesh(load.mesh->positions, load.mesh->indices, m);
        if (!r.volume) r.error = spec.mesh->at + ": " + r.error;
        return r;
    }
    if (!load.scan || !spec.scan) {
        r.error = load.error.empty() ? "the sculpture has no source to sample" : load.error;
        return r;
    }
    voxel::IsoSurfaceRequest iso;
    iso.iso = spec.scan->iso;
    iso.insideAbove = spec.scan->insideAbove;
    iso.box = request.box;
    iso.resolution = request.resolution;
    iso.band = request.band;
    iso.source = request.source;
    if (iso.source.file.empty()) iso.source.file = spec.fileAsWritten;
    r = voxel::levelSetFromScalar(*load.scan, iso);
    if (!r.volume) r.error = spec.scan->at + ": " + r.error;
    return r;
}

ResolvedBoxes sampledModelBoxes(const std::vector<Sculpture>& sculptures) {
    ResolvedBoxes boxes(sculptures.size());
    for (std::size_t i = 0; i < sculptures.size(); ++i)
        if (sculptures[i].volume && !sculptures[i].morphResult()) boxes[i] = sculptures[i].volume->frame.modelBox;
    return boxes;
}

}  // namespace hg::garden
