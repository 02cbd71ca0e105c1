// A one-line progress bar on standard error, drawn only when it is a
// terminal: the command line's io::Progress (export, turntable, voxelize).
// Thread-safe as every io::Progress is: samplers report from their
// workers, and report() draws one call at a time.
#pragma once

#include <string>

#include "io/progress.h"

namespace hg::garden::cli {

class ProgressBar final : public io::Progress {
public:
    explicit ProgressBar(std::string label);
    ~ProgressBar() override;  // finishes the line if anything was drawn
    bool enabled() const { return enabled_; }

protected:
    bool report(double fraction) override;

private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    int lastPercent_ = -1;
};

}  // namespace hg::garden::cli
