// A still view is not drawn again (docs/rendering.md, "A still view"): when
// a view's inputs (the camera, lights, sky, every draw recorded and the
// meshes they name) equal those of the picture the scene targets hold, the
// renderer skips the shadow, scene and occlusion passes and composites the
// held picture again; lines, gizmos and panels are drawn over it as ever.
// And a still view sharpens: after a few views held, a picture drawn at a
// lower quality than the caller's still quality (the automatic mode's
// render scale while moving) is drawn once more at that quality, then held.
// This file is the policy; the renderer compares the inputs.
#pragma once

#include <optional>

#include "garden/render/occlusion_pass.h"
#include "garden/render/render_quality.h"

namespace hg::garden {

struct View;

// The view's lights, camera, viewport and sky, compared exactly.
bool sameView(const View& a, const View& b);
// Every setting, compared exactly.
bool sameQuality(const RenderQuality& a, const RenderQuality& b);

enum class PictureStep {
    Draw,     // a new picture, at the renderer's quality
    Keep,     // the held picture again: composite only
    Sharpen,  // the held view again, drawn at the still quality
};

class StillPicture {
public:
    // What to do with a view whose inputs equal the held picture's or not
    // (`same`), the renderer's quality being `quality` and the caller's
    // still quality `still` (none: never sharpen). Sharpens once the view
    // has been held `viewsBeforeSharpening` views in a row.
    PictureStep step(bool same, const RenderQuality& quality, const std::optional<RenderQuality>& still,
                     int viewsBeforeSharpening);
    // The scene targets now hold a picture drawn at `quality`, with this
    // occlusion (its textures stay the occlusion pass's until it runs again).
    void drawn(const RenderQuality& quality, const OcclusionImage& occlusion);
    // Nothing held (the targets were drawn into for something else).
    void forget() { held_.reset(); }

    bool holds() const { return held_.has_value(); }
    // The held picture's quality and occlusion; holds() must be true.
    const RenderQuality& quality() const { return held_->quality; }
    const OcclusionImage& occlusion() const { return held_->occlusion; }

private:
    struct Held {
        RenderQuality quality;
        OcclusionImage occlusion;
        int views = 0;  // views in a row that kept it (or sharpened it)
    };
    std::optional<Held> held_;
};

}  // namespace hg::garden
