// The inflated solid as HyperFun text and as a Model of our kernel parsed
// from that text, so that what the garden evaluates and the tests check is
// what the export writes and the reference interpreter reads.
//
// The body uses only arithmetic, sqrt, min and max: the plane coordinates
// of x once, then per piece five statements (inflation_field.h's steps in
// the same order), each piece max-ed into the result. Numbers are plain
// decimals with 12 places (inflation_field.h's hfDecimal; the language's
// exponent spellings are not exact), and the C++ field uses the values the
// lexer reads from them, so both agree bit for bit.
#pragma once

#include <optional>
#include <string>

#include "frep/eval/model.h"
#include "garden/sketch/inflation.h"

namespace hg::garden::sketch {

// A whole program with one body `name(x[3], a[1])`; a[1] is not used.
std::string inflatedHyperFun(const InflatedSolid& solid, const std::string& name = "my_model");

// The text parsed and compiled; nullopt with `error` set when it does not
// parse (which would be a bug here).
std::optional<frep::Model> compileHyperFun(const std::string& text, std::string& error);

}  // namespace hg::garden::sketch
