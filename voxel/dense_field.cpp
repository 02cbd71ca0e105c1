#include "voxel/dense_field.h"

#include <openvdb/tools/Dense.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <memory>

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

    struct Worker {
        explicit Worker(const frep::Model& m) : sampler(m) {}
        frep::PointSampler<float> sampler;
        std::vector<float> x, y, z;
        frep::ErrorReport errors;
    };
    tbb::enumerable_thread_specific<std::unique_ptr<Worker>> workers;
    const int nx = box.extent(0), ny = box.extent(1), nz = box.extent(2);
    std::vector<frep::ErrorReport> sliceErrors(static_cast<std::size_t>(nz));
    const float scalef = static_cast<float>(scale);
    tbb::parallel_for(0, nz, [&](int kk) {
        auto& w = workers.local();
        if (!w) w = std::make_unique<Worker>(model);
        std::size_t n = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
        w->x.resize(n); w->y.resize(n); w->z.resize(n);
        const int k = box.lo[2] + kk;
        const float zf = static_cast<float>(frame.coordinate(2, k));
        for (int j = 0; j < ny; ++j) {
            const float yf = static_cast<float>(frame.coordinate(1, box.lo[1] + j));
            for (int i = 0; i < nx; ++i) {
                std::size_t o = static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i);
                w->x[o] = static_cast<float>(frame.coordinate(0, box.lo[0] + i));
                w->y[o] = yf;
                w->z[o] = zf;
            }
        }
        float* out = r.field.values.data() + r.field.at(box.lo[0], box.lo[1], k);
        w->sampler.evaluate(w->x.data(), w->y.data(), w->z.data(), out, n, sliceErrors[static_cast<std::size_t>(kk)]);
        for (std::size_t o = 0; o < n; ++o) out[o] *= scalef;
    });
    for (const auto& e : sliceErrors) r.errors.merge(e);
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
