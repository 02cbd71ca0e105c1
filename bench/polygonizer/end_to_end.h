// bench_poly's second table: `hypergarden mesh` end to end (issue 14).
#pragma once

#include <nlohmann/json.hpp>

#include "../bench_common.h"

namespace hg::bench {

// Prints the table and returns its rows.
nlohmann::json benchMeshEndToEnd(const BenchArgs& args);

}  // namespace hg::bench
