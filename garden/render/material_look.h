// A garden material (garden/scene/garden.h) as the renderer draws it, and
// the views that replace the materials to judge form: the clay view (one
// neutral matte material on every sculpture) and the wireframe overlay
// (docs/rendering.md "Materials", "Clay view and wireframe").
#pragma once

#include "garden/render/renderer.h"
#include "garden/scene/garden.h"

namespace hg::garden {

// How sculptures are shown; the desktop's C and X keys and its Garden
// panel switch them.
struct ViewLook {
    bool clay = false;       // every sculpture in kClayView's material
    bool wireframe = false;  // the sculptures' triangle edges drawn over them
    bool cavity = true;      // the clay view's cavity shading (grooves darker, ridges lighter)
};

// `m` for the renderer: roughness as the highlight's strength and size,
// the kind as its procedural detail at `detailScale` model units per
// pattern unit (detailScaleFor).
RenderMaterial renderMaterial(const Material& m, float detailScale = 1.0f);

// The pattern unit of a sculpture whose model box's longest side is
// `modelSize` model units: a tenth of it, so a sculpture shows a few marble
// veins, a dozen growth rings, whatever its size; fixed in model units, so
// the pattern moves and scales with it.
float detailScaleFor(double modelSize);

// The clay view's material: a warm mid grey, matte, no detail, with cavity
// shading, the same for every sculpture (form alone reads).
RenderMaterial clayViewMaterial();

// What `look` makes of a sculpture's material.
RenderMaterial lookedAt(const RenderMaterial& material, const ViewLook& look);

}  // namespace hg::garden
