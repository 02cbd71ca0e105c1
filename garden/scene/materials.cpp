#include "garden/scene/materials.h"

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"

namespace hg::garden {

const std::vector<std::string>& materialKindNames() {
    static const std::vector<std::string> names = {"plain", "stone", "marble", "bronze", "clay", "plaster", "wood"};
    return names;
}

const std::string& materialKindName(MaterialKind kind) { return materialKindNames()[static_cast<std::size_t>(kind)]; }

std::optional<MaterialKind> materialKindNamed(const std::string& name) {
    const auto& names = materialKindNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<MaterialKind>(i);
    return std::nullopt;
}

const std::vector<Material>& builtinMaterials() {
    // Colours as a picker shows them; roughness and metalness as measured
    // materials go: polished marble and patinated bronze fairly smooth,
    // sawn stone, fired clay and plaster rough, oiled wood between.
    static const std::vector<Material> materials = [] {
        auto m = [](MaterialKind kind, std::array<float, 3> color, float roughness, float metallic) {
            return Material{materialKindName(kind), kind, color, roughness, metallic};
        };
        return std::vector<Material>{
            m(MaterialKind::Plain, {0.7f, 0.7f, 0.7f}, 0.5f, 0.0f),
            m(MaterialKind::Stone, {0.63f, 0.6f, 0.55f}, 0.85f, 0.0f),
            m(MaterialKind::Marble, {0.93f, 0.92f, 0.89f}, 0.2f, 0.0f),
            m(MaterialKind::Bronze, {0.62f, 0.42f, 0.22f}, 0.35f, 1.0f),
            m(MaterialKind::Clay, {0.72f, 0.46f, 0.34f}, 0.9f, 0.0f),
            m(MaterialKind::Plaster, {0.94f, 0.93f, 0.9f}, 0.95f, 0.0f),
            m(MaterialKind::Wood, {0.62f, 0.43f, 0.26f}, 0.6f, 0.0f),
        };
    }();
    return materials;
}

std::optional<Material> builtinMaterial(const std::string& name) {
    if (const auto kind = materialKindNamed(name)) return builtinMaterials()[static_cast<std::size_t>(*kind)];
    return std::nullopt;
}

Material readMaterialObject(const nlohmann::json& v, const std::string& path, const std::string& name) {
    ObjectReader o(v, path, {"kind", "color", "roughness", "metallic"});
    o.finish();
    Material m = builtinMaterials().front();
    if (auto* k = o.optional("kind")) {
        const std::string kind = readString(*k, o.pathOf("kind"));
        const auto found = builtinMaterial(kind);
        if (!found) {
            const std::string hint = nearMiss(kind, materialKindNames());
            std::string all;
            for (const std::string& n : materialKindNames()) all += " " + n;
            throw JsonError(o.pathOf("kind"), "unknown material kind '" + kind + "'" +
                                                  (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)") +
                                                  "; expected one of:" + all);
        }
        m = *found;
    }
    m.name = name;
    if (auto* c = o.optional("color")) m.color = readColor(*c, o.pathOf("color"));
    if (auto* r = o.optional("roughness")) m.roughness = static_cast<float>(readNumber(*r, o.pathOf("roughness"), 0, 1));
    if (auto* r = o.optional("metallic")) m.metallic = static_cast<float>(readNumber(*r, o.pathOf("metallic"), 0, 1));
    return m;
}

nlohmann::json materialObjectJson(const Material& m) {
    return {{"kind", materialKindName(m.kind)},
            {"color", {m.color[0], m.color[1], m.color[2]}},
            {"roughness", m.roughness},
            {"metallic", m.metallic}};
}

}  // namespace hg::garden
