#include "garden/render/still_picture.h"

namespace hg::garden {

PictureStep StillPicture::step(bool same, const RenderQuality& quality, const std::vector<RenderQuality>& stills) {
    if (!same || !held_) return {PictureStep::Draw};
    held_->views += 1;
    // Where the held picture stands: at the quality asked for (-1), at a
    // still quality (its index, the last that matches), or at neither.
    int level = sameQuality(held_->quality, quality) ? -1 : -2;
    for (std::size_t i = 0; i < stills.size(); ++i)
        if (sameQuality(held_->quality, stills[i])) level = static_cast<int>(i);
    if (level == -2) return {PictureStep::Draw};  // the quality asked for changed: drawn at it
    const auto next = static_cast<std::size_t>(level + 1);
    const int wait = level < 0 ? kViewsBeforeSharpening : kViewsBetweenSharpenings;
    if (next < stills.size() && held_->views >= wait) return {PictureStep::Sharpen, next};
    return {PictureStep::Keep};
}

void StillPicture::drawn(const RenderQuality& quality, const OcclusionImage& occlusion) {
    held_ = Held{quality, occlusion, 0};
}

}  // namespace hg::garden
