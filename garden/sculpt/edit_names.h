// The edit enums as the JSON files spell them (replay scripts, journals):
// readers that refuse any other word with its JSON path.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "garden/sculpt/edit.h"
#include "garden/sculpt/impacts.h"

namespace hg::garden {

StrokeTool readStrokeTool(const nlohmann::json& v, const std::string& path);          // carve, add, melt, smooth, inflate
Falloff readFalloff(const nlohmann::json& v, const std::string& path);                // smooth, linear, sharp, constant
QuadricShape readQuadricShape(const nlohmann::json& v, const std::string& path);      // ellipsoid, torus
SketchMode readSketchMode(const nlohmann::json& v, const std::string& path);          // add, cut
ImpactShape readImpactShape(const nlohmann::json& v, const std::string& path);        // sphere, chisel, square
ImpactSpread readImpactSpread(const nlohmann::json& v, const std::string& path);      // uniform, gaussian, cone
const char* quadricShapeName(QuadricShape s);

}  // namespace hg::garden
