// Small HyperFun programs and our own content, ready as Models, for the
// voxel tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "frep/eval/model.h"
#include "frep/language/parser.h"
#include "tests/test_models.h"

namespace hg::voxel::test {

using ::hg::test::modelFromFile;
using ::hg::test::modelFromSource;



// A sphere of radius sqrt(a[1]) at the origin; f is not a distance.
constexpr const char* kSphere = "sphere(x[3], a[1]) { sphere = a[1] - (x[1]^2 + x[2]^2 + x[3]^2); }";

using ::hg::test::kTorusBlock;

// Runs on the scalar interpreter: its loop's trip count depends on x.
constexpr const char* kInterpreterOnly =
    "wavy(x[3], a[1]) {\n"
    "  q = 0; n = 0;\n"
    "  while (n < 3) loop\n"
    "    q = q + x[1] * x[1] / 3;\n"
    "    n = n + 1 + 0 * x[2];\n"
    "  endloop;\n"
    "  wavy = 0.8 - q - x[2] * x[2] - x[3] * x[3];\n"
    "}\n";

inline std::string contentFile(const std::string& name) {
    return (std::filesystem::path(HG_SOURCE_DIR) / "content" / "hyperfun" / name).string();
}

}  // namespace hg::voxel::test
