#include "io/progress.h"

#include <algorithm>

namespace hg::io {

Progress::~Progress() = default;

Progress::Progress(Progress* parent) : flag_(parent ? parent->flag_ : &own_) {}

void Progress::start(const char*) {}

void Progress::end() {}

bool Progress::report(double) { return false; }

bool Progress::interrupted(double fraction) {
    // Reports from several threads arrive out of order: only a larger
    // fraction is passed on, and under the lock, so report() sees them
    // one at a time and rising. NaN and negatives only ask.
    if (fraction >= 0.0 && !cancelled()) {
        fraction = std::min(fraction, 1.0);
        std::lock_guard<std::mutex> lock(mutex_);
        if (fraction > last_.load(std::memory_order_relaxed)) {
            last_.store(fraction, std::memory_order_relaxed);
            if (report(fraction)) cancel();
        }
    }
    return cancelled();
}

double Progress::fraction() const noexcept { return std::max(0.0, last_.load(std::memory_order_relaxed)); }

ProgressRange::ProgressRange(Progress* parent, double lo, double hi) : Progress(parent), parent_(parent), lo_(lo), hi_(hi) {}

bool ProgressRange::report(double fraction) {
    // The end is the parent's hi exactly, so work that ends at 1 shows 1.
    return parent_ && parent_->interrupted(fraction >= 1.0 ? hi_ : lo_ + fraction * (hi_ - lo_));
}

}  // namespace hg::io
