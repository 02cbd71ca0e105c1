// A small random generator whose numbers are the same on every platform
// and standard library: std::mt19937 is portable but its distributions are
// not, and the committed weights must be rebuilt bit for bit from a seed.
#pragma once

#include <cmath>
#include <cstdint>

namespace hg::garden {

class GestureRandom {
public:
    explicit GestureRandom(std::uint64_t seed) : state_(seed) {}

    // SplitMix64: full period, good enough for shuffling and noise.
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1), 53 bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform in [0, n).
    std::uint64_t below(std::uint64_t n) { return n == 0 ? 0 : next() % n; }
    bool chance(double p) { return uniform() < p; }
    // Standard normal by Box-Muller (one value per call, for simplicity).
    double normal() {
        const double u1 = 1.0 - uniform();  // (0, 1]
        const double u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
    }
    double normal(double mean, double sigma) { return mean + sigma * normal(); }

private:
    std::uint64_t state_;
};

}  // namespace hg::garden
