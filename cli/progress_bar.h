// A one-line progress bar on standard error, drawn only when it is a
// terminal. Thread-safe: samplers report from their workers.
#pragma once

#include <mutex>
#include <string>

namespace hg::garden::cli {

class ProgressBar {
public:
    explicit ProgressBar(std::string label);
    ~ProgressBar();  // finishes the line if anything was drawn
    void update(double fraction);
    bool enabled() const { return enabled_; }

private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    int lastPercent_ = -1;
    std::mutex mutex_;
};

}  // namespace hg::garden::cli
