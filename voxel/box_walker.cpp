#include "voxel/box_walker.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace hg::voxel {

namespace {

IndexBox boxAt(const int origin[3], int size) {
    return IndexBox::fromCorners(origin[0], origin[1], origin[2], origin[0] + size - 1, origin[1] + size - 1,
                                 origin[2] + size - 1);
}

}  // namespace

BoxWalker::BoxWalker(const frep::Model& model, const VolumeFrame& frame, double scale)
    : frame_(frame), scale_(scale), scalef_(static_cast<float>(scale)), x_(512), y_(512), z_(512), f_(512) {
    const frep::Tape* tape = model.tape();
    if (!tape) {
        sampler_ = std::make_unique<frep::PointSampler<float>>(model);
        return;
    }
    Level& root = levels_[0];
    root.interval = std::make_unique<frep::IntervalEvaluator>(*tape);
    modelTape_ = tape;
    modelAffine_ = root.interval->affine();
    root.tape = tape;
    root.affine = &modelAffine_;
    root.generation = root.bound = 1;
    batch_ = std::make_unique<frep::BatchEvaluator<float>>(*tape);
    batchTape_ = tape;
    batchGeneration_ = 1;
    // Only min and max are pruned: a tape without them is never shortened.
    specialize_ = frep::specializationEnabled() &&
                  std::any_of(tape->code.begin(), tape->code.end(),
                              [](const frep::Instr& in) { return in.op == frep::Op::Min || in.op == frep::Op::Max; });
    const char* probe = std::getenv("HG_PROBE_POINT_TAPES");
    probe_ = specialize_ && probe && std::strcmp(probe, "1") == 0;
}

void BoxWalker::probePointTapes(const Level& leaf, std::size_t n, WalkCounters& counters) {
    frep::IntervalEvaluator interval(*leaf.tape, *leaf.affine);
    for (std::size_t s : {std::size_t{0}, n / 3, 2 * n / 3, n - 1}) {
        const frep::Interval px(x_[s], x_[s]), py(y_[s], y_[s]), pz(z_[s], z_[s]);
        interval.evaluate(px, py, pz, &probeTrace_);
        const bool shorter =
            specializer_.specialize(*leaf.tape, *leaf.affine, probeTrace_, frep::Precision::Float, probeOwn_);
        counters.pointTapeSum += shorter ? probeOwn_.tape.size() : leaf.tape->size();
        ++counters.pointTapes;
    }
}

BoxWalker::Verdict BoxWalker::classify(const IndexBox& domain, WalkCounters& counters, int depth) {
    Level& level = levels_[static_cast<std::size_t>(depth)];
    if (!level.tape) return Verdict::Unknown;
    if (!level.interval) level.interval = std::make_unique<frep::IntervalEvaluator>(*level.tape, *level.affine);
    else if (level.bound != level.generation) level.interval->rebind(*level.tape, *level.affine);
    level.bound = level.generation;
    // The batch evaluator sees float coordinates; rounding is monotone, so
    // the rounded corners bound every rounded point of the box.
    frep::Interval axis[3];
    for (int a = 0; a < 3; ++a)
        axis[a] = frep::Interval(static_cast<double>(static_cast<float>(frame_.coordinate(a, domain.lo[a]))),
                                 static_cast<double>(static_cast<float>(frame_.coordinate(a, domain.hi[a]))));
    ++counters.boxesTested;
    frep::Interval v = level.interval->evaluate(axis[0], axis[1], axis[2], specialize_ ? &trace_ : nullptr);
    if (v.maybeNaN) return Verdict::Unknown;
    const double band = static_cast<double>(frame_.band);
    if (v.lo * scale_ >= band) {
        ++counters.boxesInside;
        return Verdict::Inside;
    }
    if (v.hi * scale_ <= -band) {
        ++counters.boxesOutside;
        return Verdict::Outside;
    }
    return Verdict::Unknown;
}

void BoxWalker::descend(int depth) {
    const Level& parent = levels_[static_cast<std::size_t>(depth)];
    Level& child = levels_[static_cast<std::size_t>(depth + 1)];
    if (!parent.tape) return;
    static std::atomic<std::uint64_t> generations{1};
    if (specialize_ && specializer_.specialize(*parent.tape, *parent.affine, trace_, frep::Precision::Float, child.own)) {
        child.tape = &child.own.tape;
        child.affine = &child.own.affine;
        child.generation = ++generations;
        return;
    }
    child.tape = parent.tape;
    child.affine = parent.affine;
    child.generation = parent.generation;
}

void BoxWalker::walk(const int origin[3], int size, const IndexBox& clip, WalkOutput& out, int deferSize,
                     std::vector<DeferredBox>* deferred, std::shared_ptr<const frep::SpecializedTape> tape) {
    Level& root = levels_[0];
    if (modelTape_) {
        static std::atomic<std::uint64_t> starts{1ull << 62};
        start_ = std::move(tape);
        root.tape = start_ ? &start_->tape : modelTape_;
        root.affine = start_ ? &start_->affine : &modelAffine_;
        root.generation = start_ ? ++starts : 1;
    }
    walkAt(origin, size, clip, out, deferSize, deferred, 0);
}

void BoxWalker::walkAt(const int origin[3], int size, const IndexBox& clip, WalkOutput& out, int deferSize,
                       std::vector<DeferredBox>* deferred, int depth) {
    IndexBox domain = intersect(boxAt(origin, size), frame_.indexBox);
    IndexBox target = intersect(domain, clip);
    if (target.empty()) return;
    if (deferred && size == deferSize) {
        // With the tape in force here: the parent's specialization (shared
        // by its deferred children), else the one this walk started with.
        std::shared_ptr<const frep::SpecializedTape> tape = start_;
        const Level& level = levels_[static_cast<std::size_t>(depth)];
        for (int k = depth; k >= 1; --k) {
            const Level& owner = levels_[static_cast<std::size_t>(k)];
            if (level.tape != &owner.own.tape) continue;
            if (!deferredShare_ || deferredGeneration_ != owner.generation) {
                deferredShare_ = std::make_shared<const frep::SpecializedTape>(owner.own);
                deferredGeneration_ = owner.generation;
            }
            tape = deferredShare_;
            break;
        }
        deferred->push_back({{origin[0], origin[1], origin[2]}, std::move(tape)});
        return;
    }
    // The verdict depends on `domain` only, never on `clip`.
    switch (classify(domain, out.counters, depth)) {
        case Verdict::Inside: out.fills.push_back({target, frame_.band}); return;
        case Verdict::Outside: out.fills.push_back({target, -frame_.band}); return;
        case Verdict::Unknown: break;
    }
    descend(depth);
    if (size <= kLeafSize) {
        evaluateLeaf(origin, target, out, depth + 1);
        return;
    }
    const int half = size / 2;
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                int child[3] = {origin[0] + dx * half, origin[1] + dy * half, origin[2] + dz * half};
                walkAt(child, half, clip, out, deferSize, deferred, depth + 1);
            }
}

void BoxWalker::evaluateLeaf(const int origin[3], const IndexBox& target, WalkOutput& out, int depth) {
    // Points in OpenVDB's leaf order (z fastest) so results drop straight in.
    // (Interval-testing the leaf's 4^3 octants as well was measured: it cut
    // samples by a third but cost more than it saved on every program in
    // bench_voxel; an interval evaluation costs 30-60 points.)
    const float band = frame_.band;
    std::size_t n = 0;
    int offsets[512];
    for (int x = target.lo[0]; x <= target.hi[0]; ++x)
        for (int y = target.lo[1]; y <= target.hi[1]; ++y)
            for (int z = target.lo[2]; z <= target.hi[2]; ++z) {
                x_[n] = static_cast<float>(frame_.coordinate(0, x));
                y_[n] = static_cast<float>(frame_.coordinate(1, y));
                z_[n] = static_cast<float>(frame_.coordinate(2, z));
                offsets[n] = ((x - origin[0]) * kLeafSize + (y - origin[1])) * kLeafSize + (z - origin[2]);
                ++n;
            }
    const Level& level = levels_[static_cast<std::size_t>(depth)];
    if (batch_) {
        if (batchTape_ != level.tape || batchGeneration_ != level.generation) {
            batch_->rebind(*level.tape);
            batchTape_ = level.tape;
            batchGeneration_ = level.generation;
        }
        batch_->evaluate(x_.data(), y_.data(), z_.data(), f_.data(), n, out.errors);
        out.counters.leafTapeSum += level.tape->size();
        out.counters.leafTapeMax = std::max<std::uint64_t>(out.counters.leafTapeMax, level.tape->size());
        ++out.counters.leafTapes;
        if (probe_ && n > 0) probePointTapes(level, n, out.counters);
    } else {
        sampler_->evaluate(x_.data(), y_.data(), z_.data(), f_.data(), n, out.errors);
    }
    out.counters.samples += n;
    bool uniform = true;
    for (std::size_t i = 0; i < n; ++i) {
        f_[i] = std::clamp(f_[i] * scalef_, -band, band);
        uniform = uniform && f_[i] == f_[0] && std::fabs(f_[0]) == band;
    }
    if (uniform) {  // every voxel clamped alike: a fill holds the same values
        out.fills.push_back({target, f_[0]});
        return;
    }
    ++out.counters.leaves;
    LeafSamples leaf;
    std::copy(origin, origin + 3, leaf.origin);
    leaf.values.fill(-band);
    for (std::size_t i = 0; i < n; ++i) {
        leaf.values[static_cast<std::size_t>(offsets[i])] = f_[i];
        leaf.evaluated.set(static_cast<std::size_t>(offsets[i]));
    }
    out.leaves.push_back(leaf);
}

}  // namespace hg::voxel
