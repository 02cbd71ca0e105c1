// An io::Progress for tests: it keeps every fraction report() was shown,
// notices two report() calls at once (the interface promises one at a
// time), and cancels the work once a fraction reaches `cancelAt`.
#pragma once

#include <atomic>
#include <thread>
#include <vector>

#include "io/progress.h"

namespace hg::test {

class RecordingProgress final : public io::Progress {
public:
    explicit RecordingProgress(double cancelAt = 2.0) : cancelAt_(cancelAt) {}

    // Read once the work is over.
    const std::vector<double>& fractions() const { return fractions_; }
    bool overlapped() const { return overlapped_; }
    // The fractions are shown rising, and the last is `last`.
    bool risesTo(double last) const {
        for (std::size_t i = 1; i < fractions_.size(); ++i)
            if (!(fractions_[i] > fractions_[i - 1])) return false;
        return !fractions_.empty() && fractions_.back() == last;
    }

protected:
    bool report(double fraction) override {
        if (inside_.fetch_add(1) != 0) overlapped_ = true;
        fractions_.push_back(fraction);
        std::this_thread::yield();  // widen the window another report could enter by
        inside_.fetch_sub(1);
        return fraction >= cancelAt_;
    }

private:
    double cancelAt_;
    std::vector<double> fractions_;
    std::atomic<int> inside_{0};
    std::atomic<bool> overlapped_{false};
};

}  // namespace hg::test
