// What every benchmark in bench/ shares: its command line (--json FILE,
// --filter NAME, --repeat N) and best-of-N timing.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace hg::bench {

struct BenchArgs {
    std::string jsonPath;
    std::string filter;
    int repeat = 3;
    bool matches(const std::string& name) const { return filter.empty() || name.find(filter) != std::string::npos; }
};

// False (after printing the usage) on an unknown argument.
inline bool parseBenchArgs(int argc, char** argv, BenchArgs& args) {
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--json" && i + 1 < argc) args.jsonPath = argv[++i];
        else if (arg == "--filter" && i + 1 < argc) args.filter = argv[++i];
        else if (arg == "--repeat" && i + 1 < argc) args.repeat = std::max(1, std::atoi(argv[++i]));
        else {
            std::fprintf(stderr, "usage: %s [--json FILE] [--filter NAME] [--repeat N]\n", argv[0]);
            return false;
        }
    }
    return true;
}

// Seconds of the fastest of `repeat` runs of f.
template <class F>
double bestOf(int repeat, F f) {
    double best = 1e30;
    for (int i = 0; i < repeat; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

}  // namespace hg::bench
