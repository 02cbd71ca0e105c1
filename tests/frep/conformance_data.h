// Reads the HyperFun conformance tables (tests/data/hyperfun/conformance/README.md).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hg::test {

struct ConformanceRow {
    double x = 0, y = 0, z = 0, a1 = 0;
    bool error = false;
    double expected = 0;
    int line = 0;
};

// The suite the repository carries (tests/data/hyperfun).
inline std::filesystem::path hyperfunDir() { return std::filesystem::path(HG_TEST_DATA_DIR) / "hyperfun"; }

inline std::vector<ConformanceRow> readTable(const std::filesystem::path& tsv) {
    std::vector<ConformanceRow> rows;
    std::ifstream in(tsv);
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
        ++n;
        if (n == 1 || line.empty()) continue;  // header
        std::istringstream s(line);
        std::string f[5];
        for (auto& v : f) std::getline(s, v, '\t');
        ConformanceRow r;
        r.x = std::strtod(f[0].c_str(), nullptr);
        r.y = std::strtod(f[1].c_str(), nullptr);
        r.z = std::strtod(f[2].c_str(), nullptr);
        r.a1 = std::strtod(f[3].c_str(), nullptr);
        r.error = f[4] == "error";
        r.expected = r.error ? 0.0 : std::strtod(f[4].c_str(), nullptr);
        r.line = n;
        rows.push_back(r);
    }
    return rows;
}

// Tables: every NAME.tsv with its NAME.hf, in conformance/ and corpus/.
inline std::vector<std::filesystem::path> tables() {
    std::vector<std::filesystem::path> out;
    for (const char* sub : {"conformance", "corpus"}) {
        auto dir = hyperfunDir() / sub;
        if (!std::filesystem::is_directory(dir)) continue;
        for (const auto& e : std::filesystem::directory_iterator(dir))
            if (e.path().extension() == ".tsv") out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Rows the README lists as hand-picked on a branch boundary at the start of
// their table (`tapers` 3, `powers` 33, ...): exact in double by
// construction, beyond float precision by construction.
inline int handPickedRows(const std::string& table) {
    static const std::pair<const char*, int> rows[] = {
        {"tapers", 3}, {"powers", 33}, {"builtins", 32}, {"control_flow", 11},
        {"arrays", 7}, {"lexical", 2}, {"runtime_errors", 21}};
    for (const auto& [name, n] : rows)
        if (table == name) return n;
    return 0;
}

inline bool matches(double v, double e) { return std::fabs(v - e) <= std::max(1e-9 * std::fabs(e), 1e-9); }
inline bool matchesFloat(double v, double e) { return std::fabs(v - e) <= std::max(1e-4 * std::fabs(e), 1e-4); }

}  // namespace hg::test
