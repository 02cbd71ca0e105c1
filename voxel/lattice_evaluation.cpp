#include "voxel/lattice_evaluation.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>

#include "frep/eval/eval_batch.h"
#include "frep/eval/eval_interval.h"
#include "frep/eval/tape_specializer.h"

namespace hg::voxel {

namespace {

// Lattice points per block: a batch of 8 x 8 x 4 runs one tape specialized
// to its box; a task of 4 x 4 x 4 blocks specializes the model's tape first,
// and its blocks specialize that one further (docs/hyperfun.md, "Evaluation
// specialized to a region").
constexpr std::size_t kBlock[3] = {8, 8, 4};
constexpr std::size_t kBlocksPerTask = 4;

struct Range {
    std::size_t lo[3], hi[3];  // lattice indices, hi exclusive
    std::size_t count() const { return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]); }
};

// One per thread: the evaluators and the tapes of the task and the block.
struct Worker {
    explicit Worker(const frep::Tape& tape) : task(tape), block(tape), batch(tape) {}
    frep::IntervalEvaluator task, block;
    frep::BatchEvaluator<float> batch;
    frep::TapeSpecializer specializer;
    frep::IntervalTrace trace;
    frep::SpecializedTape taskTape, blockTape;
    std::vector<float> x, y, z, f;
    std::vector<std::uint8_t> failed;
};

// The box the batch evaluator sees: the lattice's float coordinates, which
// are exact in double.
void boxOf(const std::array<std::vector<float>, 3>& axes, const Range& r, frep::Interval box[3]) {
    for (std::size_t a = 0; a < 3; ++a) {
        const auto first = axes[a].begin() + static_cast<std::ptrdiff_t>(r.lo[a]);
        const auto last = axes[a].begin() + static_cast<std::ptrdiff_t>(r.hi[a]);
        const auto [lo, hi] = std::minmax_element(first, last);
        box[a] = frep::Interval(static_cast<double>(*lo), static_cast<double>(*hi));
    }
}

// The lattice evaluated block by block with tapes specialized to each: the
// same values, bit for bit, as the full tape at every point.
frep::ErrorReport evaluateTapeLattice(const frep::Model& model, const std::array<std::vector<float>, 3>& axes,
                                      float* out, std::uint8_t* failed, float scale) {
    const frep::Tape& tape = *model.tape();
    const bool specialize = frep::specializationEnabled() &&
                            std::any_of(tape.code.begin(), tape.code.end(), [](const frep::Instr& in) {
                                return in.op == frep::Op::Min || in.op == frep::Op::Max;
                            });
    const std::size_t n[3] = {axes[0].size(), axes[1].size(), axes[2].size()};
    std::size_t tasks[3];
    for (std::size_t a = 0; a < 3; ++a) tasks[a] = (n[a] + kBlock[a] * kBlocksPerTask - 1) / (kBlock[a] * kBlocksPerTask);
    const std::size_t taskCount = tasks[0] * tasks[1] * tasks[2];
    std::vector<frep::ErrorReport> taskErrors(taskCount);
    tbb::enumerable_thread_specific<std::unique_ptr<Worker>> workers;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, taskCount, 1), [&](const tbb::blocked_range<std::size_t>& tr) {
        auto& w = workers.local();
        if (!w) w = std::make_unique<Worker>(tape);
        for (std::size_t t = tr.begin(); t != tr.end(); ++t) {
            const std::size_t ti[3] = {t % tasks[0], (t / tasks[0]) % tasks[1], t / (tasks[0] * tasks[1])};
            Range task;
            for (std::size_t a = 0; a < 3; ++a) {
                task.lo[a] = ti[a] * kBlock[a] * kBlocksPerTask;
                task.hi[a] = std::min(n[a], task.lo[a] + kBlock[a] * kBlocksPerTask);
            }
            const frep::Tape* taskTape = &tape;
            if (specialize) {
                frep::Interval box[3];
                boxOf(axes, task, box);
                w->task.evaluate(box[0], box[1], box[2], &w->trace);
                if (w->specializer.specialize(tape, w->task.affine(), w->trace, frep::Precision::Float, w->taskTape)) {
                    taskTape = &w->taskTape.tape;
                    w->block.rebind(w->taskTape.tape, w->taskTape.affine);
                } else {
                    w->block.rebind(tape, w->task.affine());
                }
            }
            for (std::size_t bz = task.lo[2]; bz < task.hi[2]; bz += kBlock[2])
                for (std::size_t by = task.lo[1]; by < task.hi[1]; by += kBlock[1])
                    for (std::size_t bx = task.lo[0]; bx < task.hi[0]; bx += kBlock[0]) {
                        const Range block{{bx, by, bz},
                                          {std::min(task.hi[0], bx + kBlock[0]), std::min(task.hi[1], by + kBlock[1]),
                                           std::min(task.hi[2], bz + kBlock[2])}};
                        const frep::Tape* blockTape = taskTape;
                        if (specialize) {
                            frep::Interval box[3];
                            boxOf(axes, block, box);
                            w->block.evaluate(box[0], box[1], box[2], &w->trace);
                            if (w->specializer.specialize(*taskTape, w->block.affine(), w->trace, frep::Precision::Float,
                                                          w->blockTape))
                                blockTape = &w->blockTape.tape;
                        }
                        // A specialized tape is new content at a reused address.
                        if (blockTape != &tape || &w->batch.tape() != &tape) w->batch.rebind(*blockTape);
                        const std::size_t count = block.count();
                        w->x.resize(count); w->y.resize(count); w->z.resize(count); w->f.resize(count);
                        w->failed.resize(count);
                        std::size_t p = 0;
                        for (std::size_t k = block.lo[2]; k < block.hi[2]; ++k)
                            for (std::size_t j = block.lo[1]; j < block.hi[1]; ++j)
                                for (std::size_t i = block.lo[0]; i < block.hi[0]; ++i, ++p) {
                                    w->x[p] = axes[0][i];
                                    w->y[p] = axes[1][j];
                                    w->z[p] = axes[2][k];
                                }
                        w->batch.evaluate(w->x.data(), w->y.data(), w->z.data(), w->f.data(), count, taskErrors[t],
                                          w->failed.data());
                        p = 0;
                        for (std::size_t k = block.lo[2]; k < block.hi[2]; ++k)
                            for (std::size_t j = block.lo[1]; j < block.hi[1]; ++j)
                                for (std::size_t i = block.lo[0]; i < block.hi[0]; ++i, ++p) {
                                    const std::size_t o = (k * n[1] + j) * n[0] + i;
                                    out[o] = scale != 1.0f ? w->f[p] * scale : w->f[p];
                                    if (failed) failed[o] = w->failed[p];
                                }
                    }
        }
    });
    frep::ErrorReport errors;
    for (const auto& e : taskErrors) errors.merge(e);
    return errors;
}

}  // namespace

frep::ErrorReport evaluateLattice(const frep::Model& model, const std::array<std::vector<float>, 3>& axes, float* out,
                                  std::uint8_t* failed, float scale) {
    if (model.tape()) return evaluateTapeLattice(model, axes, out, failed, scale);
    // The interpreter's path, one z slice per task.
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
