// What the renderer spends on the picture: anti-aliasing, shadows, ambient
// occlusion, render scale and exposure, each switchable (docs/rendering.md).
#pragma once

#include <optional>
#include <string>

namespace hg::garden {

struct RenderQuality {
    int msaaSamples = 4;             // 1: no multisampling; clamped to what the driver offers
    bool shadows = true;             // the sun's (the first directional light's) shadow map
    int shadowMapSize = 2048;        // texels on a side
    float shadowDistance = 40.0f;    // metres from the eye within which chunks cast (0: all in view)
    bool ambientOcclusion = true;    // screen-space, from the depth buffer
    int aoSamples = 12;              // hemisphere samples per pixel (4..32)
    bool aoHalfResolution = false;   // AO computed at half width and height, then upsampled
    float aoRadius = 0.25f;          // metres: the largest hollow that darkens
    float exposure = 1.0f;           // linear scale before tone mapping
    float renderScale = 1.0f;        // the scene drawn at this share of the window's width and height (0.25..1)
    bool smoothUpscale = true;       // below scale 1, stretched bilinearly (false: nearest scene pixel)
    bool materialBump = true;        // the materials' detail as relief too (the shading normal perturbed)
    int skyMapSize = 1024;           // texels on a side of each face of the sky's cube map (sky_pass.h)
    // The level of detail chooses meshes for this share of the scene's
    // pixels (0.25..1; below 1: coarser meshes, fewer and larger
    // triangles). Only the automatic mode's last rung lowers it: a software
    // renderer pays for each triangle and for the partly covered pixel
    // blocks around it, whatever their size (docs/rendering.md, "Quality").
    float detailScale = 1.0f;
};

}  // namespace hg::garden

namespace hg::garden {

// low: no multisampling, shadows, occlusion or material relief (the old
// look, for software rendering); medium: 2x MSAA, a 1024 shadow map, 8 occlusion samples at
// half resolution; high: the defaults above with 16 samples, also at half
// resolution (brought up by depth: on the H100 full resolution cost 5 times
// as much, 2.3 ms at 1280 x 720, the dearest pass, for a picture that
// differs by under one level a pixel on average; docs/rendering.md).
enum class QualityPreset { Low, Medium, High };

RenderQuality qualityOf(QualityPreset preset);
// "low", "medium" or "high"; nothing for another word.
std::optional<QualityPreset> parseQualityPreset(const std::string& name);
// The preset `--quality auto` takes for a GL renderer (GL_RENDERER's text):
// low on Mesa's software rasterizers (llvmpipe, softpipe, swrast), where
// the high preset costs about 2.5 times the frame (docs/benchmarks.md,
// bench_look), else high.
QualityPreset rendererPreset(const std::string& glRenderer);

// The scene's pixels along a side of `outputPixels` at q's render scale
// (clamped to 0.25..1, as the renderer draws it): what the level of detail
// should resolve, since finer geometry would only be averaged away.
int scenePixels(int outputPixels, const RenderQuality& q);
// The pixels along that side the level of detail chooses meshes for: the
// scene's at q's detail scale (clamped to 0.25..1). What the desktop, the
// headset and the offscreen replay give the session as its viewport.
int detailPixels(int outputPixels, const RenderQuality& q);
// Every setting, compared exactly.
bool sameQuality(const RenderQuality& a, const RenderQuality& b);

}  // namespace hg::garden
