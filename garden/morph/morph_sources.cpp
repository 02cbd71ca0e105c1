#include "garden/morph/morph_sources.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "voxel/normalization.h"

namespace hg::garden {

frep::Box3 unionBox(const std::array<frep::Box3, 3>& boxes) {
    frep::Box3 u = boxes[0];
    for (const auto& b : boxes)
        for (int a = 0; a < 3; ++a) {
            u.lo[a] = std::min(u.lo[a], b.lo[a]);
            u.hi[a] = std::max(u.hi[a], b.hi[a]);
        }
    return u;
}

std::string checkSources(const MorphSources& s) {
    for (std::size_t i = 0; i < 3; ++i)
        if (s.fields[i].size() == 0 || !(s.fields[i].box() == s.frame.indexBox))
            return "morph source " + std::to_string(i) + " does not cover the shared frame";
    return "";
}

double surfaceGradient(const voxel::DenseField& field) {
    const voxel::IndexBox& b = field.box;
    if (b.extent(0) < 3 || b.extent(1) < 3 || b.extent(2) < 3) return 0.0;
    const std::size_t sx = 1, sy = static_cast<std::size_t>(b.extent(0)),
                      sz = sy * static_cast<std::size_t>(b.extent(1));
    const float* v = field.values.data();
    // One list per z-slice, joined in order: the result does not depend on
    // the number of threads.
    std::vector<std::vector<double>> slices(static_cast<std::size_t>(b.extent(2)));
    tbb::parallel_for(b.lo[2] + 1, b.hi[2], [&](int k) {
        std::vector<double>& out = slices[static_cast<std::size_t>(k - b.lo[2])];
        for (int j = b.lo[1] + 1; j < b.hi[1]; ++j)
            for (int i = b.lo[0] + 1; i < b.hi[0]; ++i) {
                std::size_t o = field.at(i, j, k);
                bool inside = v[o] >= 0.0f;
                if ((v[o + sx] >= 0.0f) == inside && (v[o + sy] >= 0.0f) == inside && (v[o + sz] >= 0.0f) == inside)
                    continue;
                double gx = 0.5 * (static_cast<double>(v[o + sx]) - static_cast<double>(v[o - sx]));
                double gy = 0.5 * (static_cast<double>(v[o + sy]) - static_cast<double>(v[o - sy]));
                double gz = 0.5 * (static_cast<double>(v[o + sz]) - static_cast<double>(v[o - sz]));
                out.push_back(std::sqrt(gx * gx + gy * gy + gz * gz));
            }
    });
    std::vector<double> all;
    for (const auto& s : slices) all.insert(all.end(), s.begin(), s.end());
    if (all.empty()) return 0.0;
    double median = 0.0, p90 = 0.0;
    voxel::medianAndP90(all.data(), all.size(), median, p90);
    return median;
}

MorphSources morphSourcesFromDense(const voxel::VolumeFrame& frame, const std::array<voxel::DenseField, 3>& dense,
                                   const std::array<double, 3>& normalization) {
    MorphSources s;
    s.frame = frame;
    s.normalization = normalization;
    for (std::size_t i = 0; i < 3; ++i) {
        s.surfaceGradient[i] = surfaceGradient(dense[i]);
        s.fields[i] = BlockedField(dense[i]);
    }
    return s;
}

MorphSourcesResult buildMorphSources(const std::array<const frep::Model*, 3>& models, const frep::Box3& box,
                                     int resolution, float band, std::uint64_t memoryLimit) {
    auto start = std::chrono::steady_clock::now();
    MorphSourcesResult r;
    MorphSources s;
    r.error = voxel::makeFrame(box, resolution, band, s.frame);
    if (!r.error.empty()) return r;
    for (std::size_t i = 0; i < 3; ++i) {
        s.normalization[i] = voxel::estimateNormalization(*models[i], s.frame).scale;
        voxel::DenseResult d = voxel::sampleDense(*models[i], s.frame, s.normalization[i], s.frame.indexBox, memoryLimit);
        if (!d.error.empty()) {
            r.error = "morph source " + std::to_string(i) + ": " + d.error;
            return r;
        }
        s.surfaceGradient[i] = surfaceGradient(d.field);
        s.fields[i] = BlockedField(d.field);  // the dense copy goes at the end of this iteration
    }
    r.sources = std::move(s);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace hg::garden
