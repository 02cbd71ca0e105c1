// The one way long work says how far it is and is told to stop (issue 21):
// the sampler, the export mesher, mesh export, the export file, the
// turntable, the sculpture loader; shown by the command line's bar, the
// desktop's Export panel, or nobody. In the style of OpenVDB's interrupter
// (openvdb/util/NullInterrupter.h): the work calls interrupted(fraction)
// now and then and stops when it says true. See docs/design.md, "Progress
// and cancel".
//
// Threads. interrupted(), cancelled() and cancel() may be called from any
// thread at once (the sampler reports from its TBB workers); report() is
// called one call at a time, under this object's lock, only with fractions
// larger than any before (so a display never goes backwards) and at most 1.
// start() and end() come from the thread that runs the work.
//
// Cancelled work stops at its next check, writes nothing, and says so as
// an outcome of its own (a `cancelled` flag in its result or report, beside
// the kCancelled message for a person); nothing is thrown.
#pragma once

#include <atomic>
#include <mutex>

namespace hg::io {

// What a person is told when work was cancelled; code tests the outcome's
// flag or Progress::cancelled(), never this text.
constexpr const char* kCancelled = "cancelled; nothing was written";

class Progress {
public:
    Progress() = default;
    virtual ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // A piece of work named `what` begins, and ends; for displays only.
    virtual void start(const char* what);
    virtual void end();

    // `fraction` (0..1) of the work is done; a negative one only asks.
    // True when the work should stop: cancel() was called (on this object
    // or on a parent it reports into), or report() said so. Any thread.
    bool interrupted(double fraction = -1.0);
    // As interrupted() without a report, and as cheap as can be (one relaxed
    // atomic load): for inner loops on any thread.
    bool cancelled() const noexcept { return flag_->load(std::memory_order_relaxed); }
    // Asks the work to stop (a Cancel button, the session closing); sticky,
    // from any thread. A range's cancel stops its parent's work too.
    void cancel() noexcept { flag_->store(true, std::memory_order_relaxed); }
    // The largest fraction reported so far (0 before any).
    double fraction() const noexcept;

protected:
    // Shares `parent`'s cancel flag (its own when `parent` is null).
    explicit Progress(Progress* parent);
    // A fraction larger than any before: draw it. True stops the work (as
    // cancel()). Called under the lock, so one call at a time.
    virtual bool report(double fraction);

private:
    std::atomic<bool> own_{false};
    std::atomic<bool>* flag_ = &own_;
    std::mutex mutex_;
    std::atomic<double> last_{-1.0};
};

// Nobody shows it: a cancel flag and the fraction so far (fraction()).
class NullProgress final : public Progress {};

// A stage of `parent`'s work: its fractions 0..1 are lo..hi of the
// parent's (stage 2 of 3: 1/3..2/3), and it shares the parent's cancel
// flag. `parent` may be null: then it only holds a cancel flag of its own,
// so work can always report into a range, whether or not anyone watches.
class ProgressRange final : public Progress {
public:
    ProgressRange(Progress* parent, double lo, double hi);

protected:
    bool report(double fraction) override;

private:
    Progress* parent_;
    double lo_, hi_;
};

}  // namespace hg::io
