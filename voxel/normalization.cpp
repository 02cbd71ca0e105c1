#include "voxel/normalization.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "frep/eval_gradient.h"
#include "frep/eval_interval.h"
#include "frep/tape_specializer.h"
#include "voxel/lattice_evaluation.h"

namespace hg::voxel {

namespace {

constexpr int kProbeCells = 48;            // lattice cells along the longest side
constexpr std::size_t kMaxSurfaceSamples = 4096;

struct Probe {
    int n[3];
    double lo[3];
    double step;
    std::vector<double> f;
    std::vector<std::uint8_t> failed;
    std::size_t at(int i, int j, int k) const {
        return (static_cast<std::size_t>(k) * static_cast<std::size_t>(n[1]) + static_cast<std::size_t>(j)) *
                   static_cast<std::size_t>(n[0]) + static_cast<std::size_t>(i);
    }
};

Probe sampleLattice(const frep::Model& model, const VolumeFrame& frame) {
    Probe p;
    double extent[3];
    double longest = 0.0;
    for (int a = 0; a < 3; ++a) {
        p.lo[a] = frame.coordinate(a, frame.indexBox.lo[a]);
        extent[a] = frame.coordinate(a, frame.indexBox.hi[a]) - p.lo[a];
        longest = std::max(longest, extent[a]);
    }
    int cells = std::min(kProbeCells, frame.resolution);
    p.step = longest / cells;
    for (int a = 0; a < 3; ++a) p.n[a] = static_cast<int>(std::ceil(extent[a] / p.step)) + 1;
    p.f.resize(static_cast<std::size_t>(p.n[0]) * static_cast<std::size_t>(p.n[1]) * static_cast<std::size_t>(p.n[2]));
    p.failed.resize(p.f.size());

    // Float is plenty to find sign changes, and several times faster than
    // the exact double path on convolution-heavy programs.
    std::array<std::vector<float>, 3> axes;
    for (int a = 0; a < 3; ++a)
        for (int i = 0; i < p.n[a]; ++i)
            axes[static_cast<std::size_t>(a)].push_back(static_cast<float>(p.lo[a] + i * p.step));
    std::vector<float> values(p.f.size());
    evaluateLattice(model, axes, values.data(), p.failed.data());
    std::copy(values.begin(), values.end(), p.f.begin());
    return p;
}

// Surface crossings along the lattice's edges, in a fixed order.
std::vector<double> surfacePoints(const Probe& p) {
    std::vector<double> pts;  // x, y, z triples
    const int d[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 0; k < p.n[2]; ++k)
        for (int j = 0; j < p.n[1]; ++j)
            for (int i = 0; i < p.n[0]; ++i) {
                std::size_t a = p.at(i, j, k);
                if (p.failed[a]) continue;
                for (const auto& e : d) {
                    int i1 = i + e[0], j1 = j + e[1], k1 = k + e[2];
                    if (i1 >= p.n[0] || j1 >= p.n[1] || k1 >= p.n[2]) continue;
                    std::size_t b = p.at(i1, j1, k1);
                    if (p.failed[b] || (p.f[a] >= 0.0) == (p.f[b] >= 0.0)) continue;
                    double t = p.f[a] / (p.f[a] - p.f[b]);
                    pts.push_back(p.lo[0] + (i + t * e[0]) * p.step);
                    pts.push_back(p.lo[1] + (j + t * e[1]) * p.step);
                    pts.push_back(p.lo[2] + (k + t * e[2]) * p.step);
                }
            }
    std::size_t count = pts.size() / 3;
    if (count <= kMaxSurfaceSamples) return pts;
    std::vector<double> kept;
    kept.reserve(kMaxSurfaceSamples * 3);
    for (std::size_t s = 0; s < kMaxSurfaceSamples; ++s) {
        std::size_t i = s * count / kMaxSurfaceSamples;
        kept.insert(kept.end(), pts.begin() + static_cast<std::ptrdiff_t>(3 * i),
                    pts.begin() + static_cast<std::ptrdiff_t>(3 * i + 3));
    }
    return kept;
}

// Surface samples grouped by the block of probe cells they fall in, and
// within it by a smaller block, so that each group's gradients run a tape
// specialized to its box (the outer block's tape specialized further).
constexpr int kOuterBlockCells = 8, kInnerBlockCells = 2;

struct GradientWorker {
    explicit GradientWorker(const frep::Tape& t) : outer(t), inner(t), grad(t) {}
    frep::IntervalEvaluator outer, inner;
    frep::GradientEvaluator grad;
    frep::TapeSpecializer specializer;
    frep::IntervalTrace trace;
    frep::SpecializedTape outerTape, innerTape;
};

// The box of the samples `group` (indices into `pts`, xyz triples).
std::array<frep::Interval, 3> boxOf(const std::vector<double>& pts, const std::vector<std::size_t>& group) {
    std::array<frep::Interval, 3> box;
    for (std::size_t a = 0; a < 3; ++a) box[a] = frep::Interval(pts[3 * group[0] + a]);
    for (std::size_t i : group)
        for (std::size_t a = 0; a < 3; ++a) {
            box[a].lo = std::min(box[a].lo, pts[3 * i + a]);
            box[a].hi = std::max(box[a].hi, pts[3 * i + a]);
        }
    return box;
}

std::vector<double> gradientMagnitudes(const frep::Model& model, const std::vector<double>& pts, double h,
                                       const Probe& probe) {
    std::size_t n = pts.size() / 3;
    std::vector<double> mags;
    mags.reserve(n);
    frep::ErrorReport errors;
    if (const frep::Tape* tape = model.tape()) {
        // groups[outer][inner] = sample indices, in a fixed order.
        std::vector<std::vector<std::vector<std::size_t>>> groups;
        {
            std::map<std::array<int, 3>, std::size_t> outerIndex;
            std::vector<std::map<std::array<int, 3>, std::size_t>> innerIndex;
            for (std::size_t i = 0; i < n; ++i) {
                std::array<int, 3> cell;
                for (std::size_t a = 0; a < 3; ++a)
                    cell[a] = static_cast<int>(std::floor((pts[3 * i + a] - probe.lo[a]) / probe.step));
                std::array<int, 3> outerKey, innerKey;
                for (std::size_t a = 0; a < 3; ++a) {
                    outerKey[a] = cell[a] >= 0 ? cell[a] / kOuterBlockCells : -1;
                    innerKey[a] = cell[a] >= 0 ? cell[a] / kInnerBlockCells : -1;
                }
                auto [o, freshOuter] = outerIndex.emplace(outerKey, groups.size());
                if (freshOuter) {
                    groups.emplace_back();
                    innerIndex.emplace_back();
                }
                auto [in, freshInner] = innerIndex[o->second].emplace(innerKey, groups[o->second].size());
                if (freshInner) groups[o->second].emplace_back();
                groups[o->second][in->second].push_back(i);
            }
        }
        // In parallel, each magnitude written at its sample's index so the
        // result does not depend on the number of threads. The specialized
        // tapes give the same values, bit for bit (frep/tape_specializer.h).
        std::vector<double> all(n, 0.0);
        const bool specialize = frep::specializationEnabled();
        tbb::enumerable_thread_specific<std::unique_ptr<GradientWorker>> workers;
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
            auto& w = workers.local();
            if (!w) w = std::make_unique<GradientWorker>(*tape);
            frep::ErrorReport pointErrors;
            for (std::size_t g = r.begin(); g != r.end(); ++g) {
                const frep::Tape* outerTape = tape;
                if (specialize) {
                    std::vector<std::size_t> every;
                    for (const auto& inner : groups[g]) every.insert(every.end(), inner.begin(), inner.end());
                    const auto box = boxOf(pts, every);
                    w->outer.evaluate(box[0], box[1], box[2], &w->trace);
                    if (w->specializer.specialize(*tape, w->outer.affine(), w->trace, frep::Precision::Gradient, w->outerTape)) {
                        outerTape = &w->outerTape.tape;
                        w->inner.rebind(w->outerTape.tape, w->outerTape.affine);
                    } else {
                        w->inner.rebind(*tape, w->outer.affine());
                    }
                }
                for (const auto& group : groups[g]) {
                    w->grad.rebind(*outerTape);
                    if (specialize) {
                        const auto box = boxOf(pts, group);
                        w->inner.evaluate(box[0], box[1], box[2], &w->trace);
                        if (w->specializer.specialize(*outerTape, w->inner.affine(), w->trace, frep::Precision::Gradient,
                                                      w->innerTape))
                            w->grad.rebind(w->innerTape.tape);
                    }
                    for (std::size_t i : group) {
                        std::uint64_t before = pointErrors.count;
                        frep::Gradient gr = w->grad.evaluate(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2], pointErrors);
                        double m = std::sqrt(gr.dx * gr.dx + gr.dy * gr.dy + gr.dz * gr.dz);
                        if (pointErrors.count == before && std::isfinite(m) && m > 0.0) all[i] = m;
                    }
                }
            }
        });
        for (double m : all)
            if (m > 0.0) mags.push_back(m);
        return mags;
    }
    // Interpreter path: central differences, six points per sample.
    frep::PointSampler<double> sampler(model);
    for (std::size_t i = 0; i < n; ++i) {
        double x[6], y[6], z[6], f[6];
        std::uint8_t failed[6];
        for (int s = 0; s < 6; ++s) {
            x[s] = pts[3 * i]; y[s] = pts[3 * i + 1]; z[s] = pts[3 * i + 2];
        }
        x[0] += h; x[1] -= h; y[2] += h; y[3] -= h; z[4] += h; z[5] -= h;
        sampler.evaluate(x, y, z, f, 6, errors, failed);
        if (std::any_of(failed, failed + 6, [](std::uint8_t b) { return b != 0; })) continue;
        double gx = (f[0] - f[1]) / (2 * h), gy = (f[2] - f[3]) / (2 * h), gz = (f[4] - f[5]) / (2 * h);
        double m = std::sqrt(gx * gx + gy * gy + gz * gz);
        if (std::isfinite(m) && m > 0.0) mags.push_back(m);
    }
    return mags;
}

}  // namespace

void medianAndP90(double* values, std::size_t n, double& median, double& p90) {
    median = p90 = 0.0;
    if (n == 0) return;
    std::size_t m = n / 2, q = std::min(n - 1, (n * 9) / 10);
    std::nth_element(values, values + m, values + n);
    median = values[m];
    std::nth_element(values, values + q, values + n);
    p90 = values[q];
}

Normalization estimateNormalization(const frep::Model& model, const VolumeFrame& frame) {
    Normalization result;
    result.scale = 1.0 / frame.voxelSize;
    Probe probe = sampleLattice(model, frame);
    std::vector<double> pts = surfacePoints(probe);
    std::vector<double> mags = gradientMagnitudes(model, pts, frame.voxelSize * 0.25, probe);
    result.surfaceSamples = mags.size();
    if (mags.empty()) return result;
    medianAndP90(mags.data(), mags.size(), result.medianGradient, result.p90Gradient);
    if (result.medianGradient > 0.0 && std::isfinite(result.medianGradient))
        result.scale = 1.0 / (frame.voxelSize * result.medianGradient);
    return result;
}

}  // namespace hg::voxel
