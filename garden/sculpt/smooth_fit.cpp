#include "garden/sculpt/smooth_fit.h"

#include <algorithm>
#include <cmath>

namespace hg::garden {

namespace {

constexpr int kTerms = 10;
// Samples along the capsule's radius at most: larger tools take every n-th
// voxel, so a fit costs about the same at any radius.
constexpr double kSamplesPerRadius = 12.0;
constexpr std::size_t kMinSamples = 30;

void terms(double u, double v, double w, double out[kTerms]) {
    out[0] = 1.0;
    out[1] = u;
    out[2] = v;
    out[3] = w;
    out[4] = u * u;
    out[5] = v * v;
    out[6] = w * w;
    out[7] = u * v;
    out[8] = v * w;
    out[9] = u * w;
}

// Solves the symmetric positive definite system a x = b in place
// (Cholesky); false when a pivot is not clearly positive.
bool solve(double a[kTerms][kTerms], double b[kTerms]) {
    double scaleMax = 0.0;
    for (int i = 0; i < kTerms; ++i) scaleMax = std::max(scaleMax, a[i][i]);
    for (int j = 0; j < kTerms; ++j) {
        double d = a[j][j];
        for (int k = 0; k < j; ++k) d -= a[j][k] * a[j][k];
        if (!(d > 1e-12 * scaleMax)) return false;
        a[j][j] = std::sqrt(d);
        for (int i = j + 1; i < kTerms; ++i) {
            double s = a[i][j];
            for (int k = 0; k < j; ++k) s -= a[i][k] * a[j][k];
            a[i][j] = s / a[j][j];
        }
    }
    for (int i = 0; i < kTerms; ++i) {
        double s = b[i];
        for (int k = 0; k < i; ++k) s -= a[i][k] * b[k];
        b[i] = s / a[i][i];
    }
    for (int i = kTerms - 1; i >= 0; --i) {
        double s = b[i];
        for (int k = i + 1; k < kTerms; ++k) s -= a[k][i] * b[k];
        b[i] = s / a[i][i];
    }
    return true;
}

}  // namespace

std::optional<SegmentFit> fitSegment(const voxel::Volume& grid, const StrokeSegment& segment, double radius) {
    const voxel::VolumeFrame& f = grid.frame;
    const double v = f.voxelSize, band = static_cast<double>(f.band);
    SegmentFit fit;
    for (int a = 0; a < 3; ++a) fit.centre[a] = 0.5 * (segment.begin[a] + segment.end[a]);
    fit.scale = radius;
    const int stride = std::max(1, static_cast<int>(std::ceil(radius / v / kSamplesPerRadius)));
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        const double from = std::min(segment.begin[a], segment.end[a]) - radius;
        const double to = std::max(segment.begin[a], segment.end[a]) + radius;
        lo[a] = std::max(f.indexBox.lo[a], static_cast<int>(std::floor((from - f.modelBox.lo[a]) / v)));
        hi[a] = std::min(f.indexBox.hi[a], static_cast<int>(std::ceil((to - f.modelBox.lo[a]) / v)));
    }
    const double ax = segment.end[0] - segment.begin[0], ay = segment.end[1] - segment.begin[1],
                 az = segment.end[2] - segment.begin[2];
    const double l2 = ax * ax + ay * ay + az * az;
    double m[kTerms][kTerms] = {}, rhs[kTerms] = {};
    double total = 0.0;
    std::size_t samples = 0;
    for (int i = lo[0]; i <= hi[0]; i += stride)
        for (int j = lo[1]; j <= hi[1]; j += stride)
            for (int k = lo[2]; k <= hi[2]; k += stride) {
                const double value = grid.value(i, j, k);
                if (!(std::fabs(value) < band - 0.5)) continue;
                const auto p = f.position(i, j, k);
                const double px = p[0] - segment.begin[0], py = p[1] - segment.begin[1], pz = p[2] - segment.begin[2];
                const double t = l2 > 0.0 ? std::clamp((px * ax + py * ay + pz * az) / l2, 0.0, 1.0) : 0.0;
                const double ex = px - t * ax, ey = py - t * ay, ez = pz - t * az;
                const double d2 = (ex * ex + ey * ey + ez * ez) / (radius * radius);
                if (d2 >= 1.0) continue;
                const double weight = (1.0 - d2) * (1.0 - d2);
                double x[kTerms];
                terms((p[0] - fit.centre[0]) / radius, (p[1] - fit.centre[1]) / radius, (p[2] - fit.centre[2]) / radius, x);
                for (int r = 0; r < kTerms; ++r) {
                    rhs[r] += weight * x[r] * value;
                    for (int c = 0; c <= r; ++c) m[r][c] += weight * x[r] * x[c];
                }
                total += weight;
                ++samples;
            }
    if (samples < kMinSamples) return std::nullopt;
    for (int r = 0; r < kTerms; ++r)
        for (int c = r + 1; c < kTerms; ++c) m[r][c] = m[c][r];
    for (int r = 1; r < kTerms; ++r) m[r][r] += 1e-5 * total;
    if (!solve(m, rhs)) return std::nullopt;
    for (int r = 0; r < kTerms; ++r) {
        if (!std::isfinite(rhs[r])) return std::nullopt;
        fit.c[static_cast<std::size_t>(r)] = rhs[r];
    }
    return fit;
}

}  // namespace hg::garden
