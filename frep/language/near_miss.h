// Suggestions for a mistyped word ("did you mean ...?"): for unknown keys of
// garden files and replay scripts, unknown commands and options of the
// command line. Here, in the kernel, because the small `hypergarden`
// executable (the kernel only) parses the command line too.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace hg::frep {

// Levenshtein distance: insertions, deletions and substitutions.
std::size_t editDistance(const std::string& a, const std::string& b);

// The candidate nearest to `word` by edit distance when it is a near miss
// (at most 2 edits), else "".
std::string nearMiss(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace hg::frep
