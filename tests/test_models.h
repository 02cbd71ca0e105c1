// Models from HyperFun text or files for the tests of every module: the
// program's default body with the given a[] values. A parse error fails the
// test with its first diagnostic.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "frep/eval/model.h"
#include "frep/language/parser.h"

namespace hg::test {

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

}  // namespace hg::test
