#include "garden/render/material_look.h"

#include <algorithm>

namespace hg::garden {

static_assert(static_cast<int>(MaterialKind::Plain) == kSurfacePlain && static_cast<int>(MaterialKind::Stone) == kSurfaceStone &&
                  static_cast<int>(MaterialKind::Marble) == kSurfaceMarble &&
                  static_cast<int>(MaterialKind::Bronze) == kSurfaceBronze &&
                  static_cast<int>(MaterialKind::Clay) == kSurfaceClay &&
                  static_cast<int>(MaterialKind::Plaster) == kSurfacePlaster &&
                  static_cast<int>(MaterialKind::Wood) == kSurfaceWood,
              "MaterialKind and SurfaceKind list the kinds in one order");

RenderMaterial renderMaterial(const Material& m, float detailScale) {
    RenderMaterial r;
    r.baseColor = glm::vec3(m.color[0], m.color[1], m.color[2]);
    // Rough surfaces have a weak, wide highlight; smooth ones a sharp one.
    r.specular = 0.05f + 0.6f * (1.0f - m.roughness) + 0.3f * m.metallic;
    r.shininess = 4.0f + 200.0f * (1.0f - m.roughness) * (1.0f - m.roughness);
    r.kind = static_cast<int>(m.kind);
    r.metallic = m.metallic;
    r.detailScale = detailScale;
    return r;
}

float detailScaleFor(double modelSize) { return static_cast<float>(std::max(modelSize, 1e-6) / 10.0); }

RenderMaterial clayViewMaterial() {
    RenderMaterial r;
    r.baseColor = glm::vec3(0.68f, 0.66f, 0.63f);
    r.specular = 0.06f;
    r.shininess = 10.0f;
    r.cavity = 1.0f;  // grooves darker, ridges lighter: form reads as in sculpting programs
    return r;
}

RenderMaterial lookedAt(const RenderMaterial& material, const ViewLook& look) {
    RenderMaterial r = look.clay ? clayViewMaterial() : material;
    if (look.clay && !look.cavity) r.cavity = 0.0f;
    r.edges = look.wireframe ? 1 : 0;
    return r;
}

}  // namespace hg::garden
