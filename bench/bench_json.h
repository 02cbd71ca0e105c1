// bench_common.h's figures as the benches' JSON writes them (benches that
// link nlohmann_json).
#pragma once

#include <nlohmann/json.hpp>

#include "bench_common.h"

namespace hg::bench {

// {"mean", "p95", "p99", "max"}.
inline nlohmann::json spreadJson(const Spread& s) {
    return {{"mean", s.mean}, {"p95", s.p95}, {"p99", s.p99}, {"max", s.max}};
}

}  // namespace hg::bench
