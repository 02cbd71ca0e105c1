// Materials by name and as JSON (docs/garden-format.md "Materials"): the
// built-in ones a garden file may name without defining them (stone,
// marble, bronze, clay, plaster, wood, plain), the kinds' names, and the
// one reader and writer of a material object, shared by the garden file
// and the journal's `material` action.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "garden/scene/garden.h"

namespace hg::garden {

// "plain", "stone", ... in MaterialKind's order.
const std::vector<std::string>& materialKindNames();
const std::string& materialKindName(MaterialKind kind);
std::optional<MaterialKind> materialKindNamed(const std::string& name);

// The built-in materials, one per kind, each named after its kind: a
// physically plausible colour, roughness and metalness for it.
const std::vector<Material>& builtinMaterials();
std::optional<Material> builtinMaterial(const std::string& name);

// A material object {"kind", "color", "roughness", "metallic"}, all
// optional: the kind's built-in values, then the keys given over them.
// Throws JsonError at the offending key; an unknown kind gets the nearest
// name as a suggestion. The result is named `name`.
Material readMaterialObject(const nlohmann::json& v, const std::string& path, const std::string& name);
// The same object with every field (the kind by name; not the name).
nlohmann::json materialObjectJson(const Material& m);

}  // namespace hg::garden
