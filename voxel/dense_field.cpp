#include "voxel/dense_field.h"

#include <openvdb/tools/Dense.h>

#include <array>
#include <chrono>

#include "voxel/lattice_evaluation.h"
#include "voxel/memory_guard.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {

DenseResult sampleDense(const frep::Model& model, const VolumeFrame& frame, double scale, const IndexBox& box,
                        std::uint64_t limit) {
    auto start = std::chrono::steady_clock::now();
    DenseResult r;
    r.bytes = box.volume() * sizeof(float);
    int longest = std::max({box.extent(0), box.extent(1), box.extent(2)});
    r.error = refuseIfTooBig("a dense cache of " + std::to_string(box.extent(0)) + "x" + std::to_string(box.extent(1)) +
                                 "x" + std::to_string(box.extent(2)) + " voxels",
                             longest, r.bytes, memoryLimit(limit), 3.0);
    if (!r.error.empty() || box.empty()) return r;
    r.field.box = box;
    r.field.values.resize(box.volume());

    std::array<std::vector<float>, 3> axes;
    for (int a = 0; a < 3; ++a)
        for (int i = 0; i < box.extent(a); ++i)
            axes[static_cast<std::size_t>(a)].push_back(static_cast<float>(frame.coordinate(a, box.lo[a] + i)));
    r.errors = evaluateLattice(model, axes, r.field.values.data(), nullptr, static_cast<float>(scale));
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

Volume volumeFromDense(DenseField&& field, const VolumeFrame& frame, double scale, const VolumeSource& source) {
    Volume v;
    v.frame = frame;
    v.normalization = scale;
    v.kind = VolumeKind::DenseSource;
    v.source = source;
    // Unclamped: the background only matters outside the box, where the
    // field was not sampled; the clamped outside value is the honest guess.
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(-frame.band);
    grid->setTransform(frameTransform(frame));
    grid->setName(source.body);
    if (!field.box.empty()) {
        openvdb::tools::Dense<float, openvdb::tools::LayoutXYZ> dense(toCoordBBox(field.box), field.values.data());
        openvdb::tools::copyFromDense(dense, *grid, 0.0f);
    }
    field.values.clear();
    field.values.shrink_to_fit();
    v.grid().grid = grid;
    return v;
}

}  // namespace hg::voxel
