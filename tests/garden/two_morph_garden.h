// The small garden (session_garden.h) with a second metamorphosis beside the
// first: what the tests of several morphs in one garden open.
#pragma once

#include <array>
#include <fstream>

#include "session_garden.h"

namespace hg::garden::test {

// The small garden with a second morph 10 m along x: balls d, e and f (the
// sizes of a, b and c, turned round) at its corners and its result "second"
// at their centroid (10, 0, 0). The garden file writes both as $.morphs.
inline std::string writeTwoMorphGarden(const std::filesystem::path& dir) {
    const std::string path = writeSmallGarden(dir);
    nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
    const std::array<const char*, 3> names{"d", "e", "f"};
    const std::array<double, 3> radii{0.36, 0.25, 0.16};
    const std::array<std::array<double, 3>, 3> at{{{10, 0, -2.3094}, {8, 0, 1.1547}, {12, 0, 1.1547}}};
    for (std::size_t i = 0; i < 3; ++i)
        j["sculptures"].push_back({{"name", names[i]}, {"file", "ball.hf"}, {"a", {radii[i]}}, {"resolution", 32},
                                   {"box", {{"min", {-0.6, -0.1, -0.6}}, {"max", {0.6, 1.1, 0.6}}}},
                                   {"placement", {{"position", at[i]}}}});
    j["morphs"] = nlohmann::json::array(
        {j["morph"], {{"sources", {"d", "e", "f"}}, {"selector", {10.5, 0.2}}, {"result", {{"name", "second"}, {"resolution", 32}}}}});
    j.erase("morph");
    std::ofstream(dir / "garden.json") << j.dump(2);
    return path;
}

}  // namespace hg::garden::test
