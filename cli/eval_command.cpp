// `hypergarden eval FILE.hf [--body NAME] [--a V,...] [x y z]`: the body's
// value at one point, or at each "x y z" line of standard input. A point
// where the program fails prints "error: <reason> at line L, column C".
//
// Lines from standard input are evaluated in batches on the compiled tape
// (the double path, bit for bit the interpreter's) and the answers written
// in blocks: one process answers 100,000 points about as fast as it starts.
// Before waiting for more input it answers every line it has read, so a
// terminal, or a program writing a line and waiting for its answer, gets
// each answer as soon as its line is complete.
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frep/eval/eval_batch.h"
#include "frep/eval/eval_interval.h"
#include "frep/language/interpreter.h"
#include "frep/eval/tape_specializer.h"
#include "cli/commands.h"
#include "cli/load_model.h"
#include "cli/point_lines.h"

namespace hg::garden::cli {
namespace {

// Answers in order, written to stdout in large blocks.
class Answers {
public:
    ~Answers() { flush(); }

    void value(double v) {
        // "%.17g" (std::to_chars is specified as printf's output), without
        // printf's per-call cost.
        char buf[32];
        auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
        text_.append(buf, r.ptr);
        text_ += '\n';
        if (text_.size() >= kBlock) flush();
    }
    void error(frep::DomainError e, frep::SourceLoc loc) {
        text_ += "error: ";
        text_ += frep::describe(e);
        text_ += " at line " + std::to_string(loc.line) + ", column " + std::to_string(loc.column) + "\n";
        if (text_.size() >= kBlock) flush();
    }
    void flush() {
        if (!text_.empty()) std::fwrite(text_.data(), 1, text_.size(), stdout);
        text_.clear();
        std::fflush(stdout);
    }

private:
    static constexpr size_t kBlock = 1 << 16;
    std::string text_;
};

// Points waiting for their values, evaluated together.
class PointBatch {
public:
    static constexpr size_t kMax = 4096;

    PointBatch(const frep::Model& model, bool forceInterpreter)
        : model_(model), interp_(model.program(), model.bodyIndex(), model.parameters()) {
        if (model.tape() && !forceInterpreter) {
            tape_.emplace(*model.tape());
            // eval prints what the program computes, as the interpreter does.
            tape_->setClamped(false);
        }
    }

    bool full() const { return x_.size() == kMax; }
    void add(double x, double y, double z) {
        x_.push_back(x);
        y_.push_back(y);
        z_.push_back(z);
    }

    void answer(Answers& out) {
        const size_t n = x_.size();
        if (n == 0) return;
        if (tape_) {
            values_.resize(n);
            failed_.resize(n);
            evaluateByRegion(n);
            for (size_t i = 0; i < n; ++i) {
                if (!failed_[i]) {
                    out.value(values_[i]);
                    continue;
                }
                // The batch reports its first error only: this point's own
                // comes from evaluating it alone (rare, so cheap enough).
                frep::ErrorReport one;
                double v;
                tape_->evaluate(&x_[i], &y_[i], &z_[i], &v, 1, one);
                out.error(one.first, one.firstLoc);
            }
        } else {
            for (size_t i = 0; i < n; ++i) {
                frep::PointResult r = interp_.evaluate(x_[i], y_[i], z_[i]);
                if (r.ok()) out.value(r.value);
                else out.error(r.error, r.loc);
            }
        }
        x_.clear();
        y_.clear();
        z_.clear();
    }

private:
    // Points that lie close together are evaluated together with the tape
    // specialized to their box (frep/eval/tape_specializer.h; the same values
    // bit for bit): the batch is split at the median of its longest side
    // until a group holds at most kGroup points.
    static constexpr size_t kGroup = 256;
    void evaluateByRegion(size_t n) {
        const frep::Tape& full = *model_.tape();
        if (!frep::specializationEnabled() || full.size() < 96 || n < 2 * kGroup) {
            frep::ErrorReport errors;
            tape_->evaluate(x_.data(), y_.data(), z_.data(), values_.data(), n, errors, failed_.data());
            return;
        }
        if (!interval_) interval_.emplace(full);
        order_.resize(n);
        for (size_t i = 0; i < n; ++i) order_[i] = i;
        split(0, n, full);
        bindFull(full);  // a failed point is evaluated alone on it, for its own message
    }
    // Rebinding fills every constant's registers: the full tape only when
    // another is bound.
    void bindFull(const frep::Tape& full) {
        if (!boundFull_) tape_->rebind(full);
        boundFull_ = true;
    }
    void split(size_t begin, size_t end, const frep::Tape& full) {
        const double* axes[3] = {x_.data(), y_.data(), z_.data()};
        double lo[3], hi[3];
        for (int a = 0; a < 3; ++a) lo[a] = hi[a] = axes[a][order_[begin]];
        for (size_t k = begin; k < end; ++k)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], axes[a][order_[k]]);
                hi[a] = std::max(hi[a], axes[a][order_[k]]);
            }
        if (end - begin > kGroup) {
            int longest = 0;
            for (int a = 1; a < 3; ++a)
                if (hi[a] - lo[a] > hi[longest] - lo[longest]) longest = a;
            const size_t mid = begin + (end - begin) / 2;
            const double* v = axes[longest];
            std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(begin), order_.begin() + static_cast<std::ptrdiff_t>(mid),
                             order_.begin() + static_cast<std::ptrdiff_t>(end),
                             [v](size_t a, size_t b) { return v[a] < v[b] || (v[a] == v[b] && a < b); });
            split(begin, mid, full);
            split(mid, end, full);
            return;
        }
        interval_->evaluate(frep::Interval(lo[0], hi[0]), frep::Interval(lo[1], hi[1]), frep::Interval(lo[2], hi[2]), &trace_);
        if (specializer_.specialize(full, interval_->affine(), trace_, frep::Precision::Double, shorter_)) {
            tape_->rebind(shorter_.tape);
            boundFull_ = false;
        } else {
            bindFull(full);
        }
        const size_t m = end - begin;
        gx_.resize(m); gy_.resize(m); gz_.resize(m); gv_.resize(m); gf_.resize(m);
        for (size_t k = 0; k < m; ++k) {
            gx_[k] = x_[order_[begin + k]];
            gy_[k] = y_[order_[begin + k]];
            gz_[k] = z_[order_[begin + k]];
        }
        frep::ErrorReport errors;
        tape_->evaluate(gx_.data(), gy_.data(), gz_.data(), gv_.data(), m, errors, gf_.data());
        for (size_t k = 0; k < m; ++k) {
            values_[order_[begin + k]] = gv_[k];
            failed_[order_[begin + k]] = gf_[k];
        }
    }

    const frep::Model& model_;
    std::optional<frep::IntervalEvaluator> interval_;
    frep::IntervalTrace trace_;
    frep::TapeSpecializer specializer_;
    frep::SpecializedTape shorter_;
    bool boundFull_ = true;  // tape_ runs the model's whole tape
    std::vector<size_t> order_;
    std::vector<double> gx_, gy_, gz_, gv_;
    std::vector<std::uint8_t> gf_;
    frep::Interpreter interp_;
    std::optional<frep::BatchEvaluator<double>> tape_;
    std::vector<double> x_, y_, z_, values_;
    std::vector<std::uint8_t> failed_;
};

}  // namespace

int runEval(const EvalOptions& options) {
    auto lm = loadModel(options.model);
    if (!lm) return 1;
    PointBatch batch(*lm->model, options.interpreter);
    Answers out;
    if (!options.point.empty()) {
        if (options.point.size() != 3) {
            std::fprintf(stderr, "eval: give a point as three numbers: x y z\n");
            return 2;
        }
        batch.add(options.point[0], options.point[1], options.point[2]);
        batch.answer(out);
        return 0;
    }
    LineReader input(0);
    std::string_view line;
    int lineNo = 0, bad = 0;
    do {
        while (input.next(line)) {
            ++lineNo;
            if (blankLine(line)) continue;
            double x, y, z;
            if (!parsePointLine(line, x, y, z)) {
                // Answers to the lines before this one come first.
                batch.answer(out);
                out.flush();
                std::string msg = "<stdin>:" + std::to_string(lineNo) +
                                  ": error: expected three numbers \"x y z\", got \"";
                msg.append(line);
                msg += "\"\n";
                std::fwrite(msg.data(), 1, msg.size(), stderr);
                ++bad;
                continue;
            }
            batch.add(x, y, z);
            if (batch.full()) batch.answer(out);
        }
        // Everything read so far is answered before waiting for more.
        batch.answer(out);
        out.flush();
    } while (input.fill());
    if (input.error()) {
        std::fprintf(stderr, "eval: error reading standard input: %s\n", std::strerror(input.error()));
        return 1;
    }
    return bad ? 1 : 0;
}

}  // namespace hg::garden::cli
