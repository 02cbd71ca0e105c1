// A still view is not drawn again (docs/rendering.md, "A still view"): when
// a view's inputs (the camera, lights, sky, every draw recorded and the
// meshes they name) equal those of the picture the scene targets hold, the
// renderer skips the shadow, scene and occlusion passes and composites the
// held picture again; lines, gizmos and panels are drawn over it as ever.
// And a still view sharpens: after a few views held, it is drawn once more
// at each of the caller's still qualities in turn (the automatic mode's
// ceiling at the window's full size, then the high preset), then held.
// This file is the policy; the renderer compares the inputs.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "garden/render/occlusion_pass.h"
#include "garden/render/render_quality.h"

namespace hg::garden {

struct PictureStep {
    enum Kind {
        Draw,     // a new picture, at the renderer's quality
        Keep,     // the held picture again: composite only
        Sharpen,  // the held view again, drawn at still quality `still`
    };
    Kind kind = Draw;
    std::size_t still = 0;
};

class StillPicture {
public:
    // Views held before the first sharpening, and between one and the next.
    static constexpr int kViewsBeforeSharpening = 3;
    static constexpr int kViewsBetweenSharpenings = 12;

    // What to do with a view whose inputs equal the held picture's or not
    // (`same`), the renderer's quality being `quality` and the caller's
    // still qualities `stills` (in the order to sharpen through; none:
    // never sharpen).
    PictureStep step(bool same, const RenderQuality& quality, const std::vector<RenderQuality>& stills);
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
        int views = 0;  // views in a row that kept it
    };
    std::optional<Held> held_;
};

}  // namespace hg::garden
