#include "voxel/normalization.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <tuple>
#include <memory>
#include <vector>

#include "frep/eval/eval_gradient.h"
#include "frep/eval/eval_interval.h"
#include "frep/eval/tape_specializer.h"
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

// Surface samples grouped by the block of probe cells they fall in, then by
// smaller and smaller blocks within it, so that each group's gradients run
// a tape specialized to its box, the enclosing block's tape specialized
// further (docs/hyperfun.md, "Evaluation specialized to a region").
constexpr int kBlockCells[] = {8, 4, 2};
constexpr std::size_t kLevels = std::size(kBlockCells);

struct GradientWorker {
    explicit GradientWorker(const frep::Tape& t) : grad(t) {
        for (std::size_t l = 0; l < kLevels; ++l) interval.emplace_back(t);
    }
    std::vector<frep::IntervalEvaluator> interval;  // per level, bound to the tape it specializes
    frep::GradientEvaluator grad;
    frep::TapeSpecializer specializer;
    frep::IntervalTrace trace;
    frep::SpecializedTape tapes[kLevels];
    std::vector<double> x, y, z;
    std::vector<frep::Gradient> g;
};

// The box of the samples `group` (indices into `pts`, xyz triples).
std::array<frep::Interval, 3> boxOf(const std::vector<double>& pts, const std::size_t* group, std::size_t n) {
    std::array<frep::Interval, 3> box;
    for (std::size_t a = 0; a < 3; ++a) box[a] = frep::Interval(pts[3 * group[0] + a]);
    for (std::size_t s = 0; s < n; ++s)
        for (std::size_t a = 0; a < 3; ++a) {
            box[a].lo = std::min(box[a].lo, pts[3 * group[s] + a]);
            box[a].hi = std::max(box[a].hi, pts[3 * group[s] + a]);
        }
    return box;
}

// |grad f| at the samples order[begin, end) (all in one block of level
// `level`, evaluated with `tape`) into `all`, splitting into the next
// level's blocks (keys[level + 1]) where specialization is on.
void gradientsOf(GradientWorker& w, const frep::Tape& tape, const std::vector<double>& pts,
                 const std::vector<std::array<std::array<int, 3>, kLevels>>& keys, const std::vector<std::size_t>& order,
                 std::size_t begin, std::size_t end, std::size_t level, bool specialize, std::vector<double>& all) {
    const frep::Tape* own = &tape;
    if (specialize) {
        const auto box = boxOf(pts, order.data() + begin, end - begin);
        frep::IntervalEvaluator& interval = w.interval[level];
        interval.evaluate(box[0], box[1], box[2], &w.trace);
        if (w.specializer.specialize(tape, interval.affine(), w.trace, frep::Precision::Gradient, w.tapes[level]))
            own = &w.tapes[level].tape;
        if (level + 1 < kLevels) {
            if (own == &tape) w.interval[level + 1].rebind(tape, interval.affine());
            else w.interval[level + 1].rebind(*own, w.tapes[level].affine);
            for (std::size_t i = begin; i < end;) {
                std::size_t j = i + 1;
                while (j < end && keys[order[j]][level + 1] == keys[order[i]][level + 1]) ++j;
                gradientsOf(w, *own, pts, keys, order, i, j, level + 1, specialize, all);
                i = j;
            }
            return;
        }
    }
    // A failing point has a zero gradient, as has one whose derivative is
    // undefined: neither counts.
    const std::size_t n = end - begin;
    w.x.resize(n); w.y.resize(n); w.z.resize(n); w.g.resize(n);
    for (std::size_t s = 0; s < n; ++s) {
        const std::size_t i = order[begin + s];
        w.x[s] = pts[3 * i]; w.y[s] = pts[3 * i + 1]; w.z[s] = pts[3 * i + 2];
    }
    w.grad.rebind(*own);
    frep::ErrorReport errors;
    w.grad.evaluate(w.x.data(), w.y.data(), w.z.data(), w.g.data(), n, errors);
    for (std::size_t s = 0; s < n; ++s) {
        const frep::Gradient& gr = w.g[s];
        const double m = std::sqrt(gr.dx * gr.dx + gr.dy * gr.dy + gr.dz * gr.dz);
        if (std::isfinite(m) && m > 0.0) all[order[begin + s]] = m;
    }
}

std::vector<double> gradientMagnitudes(const frep::Model& model, const std::vector<double>& pts, double h,
                                       const Probe& probe) {
    std::size_t n = pts.size() / 3;
    std::vector<double> mags;
    mags.reserve(n);
    frep::ErrorReport errors;
    if (const frep::Tape* tape = model.tape()) {
        // Each sample's block at every level, and the samples in the order
        // of their blocks (a fixed order); the outermost blocks are tasks.
        std::vector<std::array<std::array<int, 3>, kLevels>> keys(n);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t a = 0; a < 3; ++a) {
                const int cell = static_cast<int>(std::floor((pts[3 * i + a] - probe.lo[a]) / probe.step));
                for (std::size_t l = 0; l < kLevels; ++l) keys[i][l][a] = cell >= 0 ? cell / kBlockCells[l] : -1;
            }
        std::vector<std::size_t> order(n);
        for (std::size_t i = 0; i < n; ++i) order[i] = i;
        std::sort(order.begin(), order.end(),
                  [&](std::size_t p, std::size_t q) { return std::tie(keys[p], p) < std::tie(keys[q], q); });
        std::vector<std::size_t> starts;
        for (std::size_t i = 0; i < n; ++i)
            if (i == 0 || keys[order[i]][0] != keys[order[i - 1]][0]) starts.push_back(i);
        starts.push_back(n);
        // In parallel, each magnitude written at its sample's index so the
        // result does not depend on the number of threads. The specialized
        // tapes give the same values, bit for bit (frep/eval/tape_specializer.h).
        std::vector<double> all(n, 0.0);
        const bool specialize = frep::specializationEnabled();
        tbb::enumerable_thread_specific<std::unique_ptr<GradientWorker>> workers;
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, starts.size() - 1, 1), [&](const tbb::blocked_range<std::size_t>& r) {
            auto& w = workers.local();
            if (!w) w = std::make_unique<GradientWorker>(*tape);
            for (std::size_t g = r.begin(); g != r.end(); ++g)
                gradientsOf(*w, *tape, pts, keys, order, starts[g], starts[g + 1], 0, specialize, all);
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
