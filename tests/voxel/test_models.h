// Small HyperFun programs and our own content, ready as Models, for the
// voxel tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "frep/model.h"
#include "frep/parser.h"

namespace hg::voxel::test {

inline frep::Model modelFromSource(const std::string& source, std::vector<double> a = {}) {
    frep::ParseResult r = frep::parseProgram(source, "test.hf");
    EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : frep::formatDiagnostic(r.errors[0]));
    auto program = std::make_shared<const frep::Program>(std::move(*r.program));
    return frep::Model(program, program->defaultBody(), std::move(a));
}

inline frep::Model modelFromFile(const std::string& path, std::vector<double> a = {}) {
    frep::ParseResult r = frep::parseFile(path);
    EXPECT_TRUE(r.ok()) << path;
    auto program = std::make_shared<const frep::Program>(std::move(*r.program));
    return frep::Model(program, program->defaultBody(), std::move(a));
}

// A sphere of radius sqrt(a[1]) at the origin; f is not a distance.
constexpr const char* kSphere = "sphere(x[3], a[1]) { sphere = a[1] - (x[1]^2 + x[2]^2 + x[3]^2); }";

// A torus about y with a blended box: curved and flat faces, a hole.
constexpr const char* kTorusBlock =
    "tb(x[3], a[1]) {\n"
    "  array c[3], o[3];\n"
    "  c = [-0.4, -0.9, -0.4];\n"
    "  o = [0, 0, 0];\n"
    "  t = hfTorusY(x, o, 0.6, 0.2);\n"
    "  b = hfBlock(x, c, 0.8, 0.3, 0.8);\n"
    "  tb = hfBlendUni(t, b, 0.05, 0.1, 0.1);\n"
    "}\n";

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
