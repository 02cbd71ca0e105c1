// What every benchmark in bench/ shares: its command line (--json FILE,
// --filter NAME, --repeat N) and best-of-N timing.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <string>
#include <vector>

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

// The value at fraction p of v's sorted values (nearest rank).
inline double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const double n = static_cast<double>(v.size());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(std::max(1.0, std::ceil(p * n))) - 1)];
}

// Per-frame times as the frame-budget tables give them.
struct Spread {
    double mean = 0.0, p95 = 0.0, p99 = 0.0, max = 0.0;
};
inline Spread spread(const std::vector<double>& v) {
    Spread s;
    if (v.empty()) return s;
    for (double x : v) {
        s.mean += x;
        s.max = std::max(s.max, x);
    }
    s.mean /= static_cast<double>(v.size());
    s.p95 = percentile(v, 0.95);
    s.p99 = percentile(v, 0.99);
    return s;
}
// "mean / p95 / p99 / max".
inline std::string spreadCell(const Spread& s) {
    char b[80];
    std::snprintf(b, sizeof b, "%.2f / %.2f / %.2f / %.1f", s.mean, s.p95, s.p99, s.max);
    return b;
}

}  // namespace hg::bench
