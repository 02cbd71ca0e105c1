#include "voxel/lattice_evaluation.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <memory>

namespace hg::voxel {

frep::ErrorReport evaluateLattice(const frep::Model& model, const std::array<std::vector<float>, 3>& axes, float* out,
                                  std::uint8_t* failed, float scale) {
    struct Worker {
        explicit Worker(const frep::Model& m) : sampler(m) {}
        frep::PointSampler<float> sampler;
        std::vector<float> x, y, z;
    };
    tbb::enumerable_thread_specific<std::unique_ptr<Worker>> workers;
    const std::size_t nx = axes[0].size(), ny = axes[1].size(), nz = axes[2].size();
    const std::size_t slice = nx * ny;
    std::vector<frep::ErrorReport> sliceErrors(nz);
    tbb::parallel_for(std::size_t{0}, nz, [&](std::size_t k) {
        auto& w = workers.local();
        if (!w) w = std::make_unique<Worker>(model);
        w->x.resize(slice); w->y.resize(slice); w->z.resize(slice);
        for (std::size_t j = 0; j < ny; ++j)
            for (std::size_t i = 0; i < nx; ++i) {
                const std::size_t o = j * nx + i;
                w->x[o] = axes[0][i];
                w->y[o] = axes[1][j];
                w->z[o] = axes[2][k];
            }
        float* values = out + k * slice;
        w->sampler.evaluate(w->x.data(), w->y.data(), w->z.data(), values, slice, sliceErrors[k],
                            failed ? failed + k * slice : nullptr);
        if (scale != 1.0f)
            for (std::size_t o = 0; o < slice; ++o) values[o] *= scale;
    });
    frep::ErrorReport errors;
    for (const auto& e : sliceErrors) errors.merge(e);
    return errors;
}

}  // namespace hg::voxel
