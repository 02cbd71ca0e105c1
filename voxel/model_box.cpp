#include "voxel/model_box.h"

#include <chrono>
#include <cstdio>

#include "voxel/sampler.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {

namespace {

using Clock = std::chrono::steady_clock;

std::string formatBox(const frep::Box3& b) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "[%.4g, %.4g] x [%.4g, %.4g] x [%.4g, %.4g]", b.lo[0], b.hi[0], b.lo[1], b.hi[1],
                  b.lo[2], b.hi[2]);
    return buf;
}

// Where the samples of one coarse pass are inside the solid (f >= 0, as
// HyperFun counts its boundary): their index bounds in the pass's frame.
struct InsideSamples {
    VolumeFrame frame;
    openvdb::CoordBBox inside;  // empty when no sample is inside
    std::uint64_t samples = 0;
    std::string error;
};

// One coarse pass: the ordinary sampler (interval culling on the tape path,
// every point on the interpreter's) over `box` at kSampledBoxResolution, with
// the narrowest band, since only the sign is read. Culled boxes become
// tiles holding the band's sign, so tiles count as well as voxels.
InsideSamples sampleInside(const frep::Model& model, const frep::Box3& box) {
    InsideSamples s;
    VolumeRequest request;
    request.box = box;
    request.resolution = kSampledBoxResolution;
    request.band = kMinBand;
    VoxelizeResult r = voxelize(model, request);
    if (!r.volume) {
        s.error = r.error;
        return s;
    }
    s.frame = r.volume->frame;
    s.samples = r.stats.samples;
    const openvdb::FloatTree& tree = vdb(*r.volume).tree();
    for (auto it = tree.cbeginValueAll(); it; ++it)
        if (*it >= 0.0f) s.inside.expand(it.getBoundingBox());
    return s;
}

// The model box around a pass's inside samples, kSampledBoxMargin cells
// wider on every side.
frep::Box3 aroundInside(const InsideSamples& s) {
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = s.frame.coordinate(a, s.inside.min()[a] - kSampledBoxMargin);
        b.hi[a] = s.frame.coordinate(a, s.inside.max()[a] + kSampledBoxMargin);
    }
    return b;
}

// Why the interval estimate gives no usable box ("" when it does; then
// `empty` says whether it proved the solid empty).
std::string intervalFailure(const frep::Model& model, frep::BoundsEstimate& est) {
    if (!model.tape())
        return "the program runs on the scalar interpreter (" + model.fallbackReason() +
               "), which has no interval bounds";
    est = frep::estimateBounds(*model.tape());
    if (est.empty || !est.unbounded) return "";
    if (est.budgetSpent)
        return "interval bounds did not separate the solid from far space within the interval estimate's budget";
    return "interval bounds did not separate the solid from the search cube's faces (too loose far from a "
           "blend or a twist, or an unbounded solid)";
}

// The default box's faces that the first pass's inside samples reach, as
// "x = -10, z = 10"; "" when none.
std::string facesReached(const InsideSamples& s, const frep::Box3& box) {
    std::string faces;
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
            const bool reached = side == 0 ? s.inside.min()[a] <= s.frame.indexOf(a, box.lo[a])
                                           : s.inside.max()[a] >= s.frame.indexOf(a, box.hi[a]);
            if (!reached) continue;
            char buf[48];
            std::snprintf(buf, sizeof buf, "%s%c = %g", faces.empty() ? "" : ", ", "xyz"[a],
                          side == 0 ? box.lo[a] : box.hi[a]);
            faces += buf;
        }
    return faces;
}

}  // namespace

std::string resolveModelBox(const frep::Model& model, const std::optional<frep::Box3>& given, ModelBox& out) {
    out = ModelBox();
    if (given) {
        out.box = *given;
        return "";
    }
    frep::BoundsEstimate est;
    const std::string failure = intervalFailure(model, est);
    if (failure.empty()) {
        if (est.empty) return "the solid is empty: no point of the search cube is inside it";
        out.box = est.box;
        out.origin = BoxOrigin::IntervalEstimate;
        return "";
    }

    // The default box first, then the region its inside samples show at the
    // same number of samples: its cells are then a 128th of the solid's size
    // instead of the default box's, so a small sculpture does not get a box
    // twice its size.
    const auto start = Clock::now();
    frep::Box3 wide;
    for (int a = 0; a < 3; ++a) {
        wide.lo[a] = -kDefaultBoxHalfSize;
        wide.hi[a] = kDefaultBoxHalfSize;
    }
    char defaultBox[64];
    std::snprintf(defaultBox, sizeof defaultBox, "the default box [%g, %g]^3", -kDefaultBoxHalfSize,
                  kDefaultBoxHalfSize);
    InsideSamples first = sampleInside(model, wide);
    if (!first.error.empty()) return "sampling " + std::string(defaultBox) + ": " + first.error;
    if (first.inside.empty())
        return "the solid is empty as far as sampling shows: " + failure + ", and no sample of " + defaultBox +
               " is inside it; give the model box explicitly";
    if (std::string faces = facesReached(first, wide); !faces.empty())
        return "the solid is unbounded: " + failure + ", and sampling " + defaultBox + " finds it reaching " +
               faces + "; give the model box explicitly";
    out.box = aroundInside(first);
    InsideSamples second = sampleInside(model, out.box);
    if (!second.error.empty()) return "sampling the region found in " + std::string(defaultBox) + ": " + second.error;
    // The second pass's lattice is finer, so it misses nothing the first
    // found; its margin still covers what lies between its samples.
    if (!second.inside.empty()) out.box = aroundInside(second);
    out.origin = BoxOrigin::Sampled;
    out.estimateFailure = failure;
    out.samples = first.samples + second.samples;
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return "";
}

std::string describeModelBox(const ModelBox& b) {
    std::string s = formatBox(b.box) + " (";
    switch (b.origin) {
        case BoxOrigin::Given: return s + "given)";
        case BoxOrigin::IntervalEstimate: return s + "estimated by interval subdivision)";
        case BoxOrigin::Sampled: break;
    }
    char how[256];
    std::snprintf(how, sizeof how,
                  "; so the default box [%g, %g]^3 was sampled at %d a side, then the region found in it at %d, "
                  "plus %d samples on every side: %llu samples, %.3f s)",
                  -kDefaultBoxHalfSize, kDefaultBoxHalfSize, kSampledBoxResolution, kSampledBoxResolution,
                  kSampledBoxMargin, static_cast<unsigned long long>(b.samples), b.seconds);
    return s + "sampled: the interval estimate failed: " + b.estimateFailure + how;
}

}  // namespace hg::voxel
