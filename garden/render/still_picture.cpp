#include "garden/render/still_picture.h"

#include "garden/render/renderer.h"

namespace hg::garden {

namespace {

bool sameLights(const std::vector<DirectionalLight>& a, const std::vector<DirectionalLight>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].direction != b[i].direction || a[i].color != b[i].color) return false;
    return true;
}

bool samePoints(const std::vector<PointLight>& a, const std::vector<PointLight>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].position != b[i].position || a[i].color != b[i].color || a[i].range != b[i].range) return false;
    return true;
}

}  // namespace

bool sameView(const View& a, const View& b) {
    return a.view == b.view && a.projection == b.projection && a.eye == b.eye && a.viewport == b.viewport &&
           a.clearColor == b.clearColor && a.ambient == b.ambient && a.hazeDistance == b.hazeDistance &&
           a.clouds == b.clouds && sameLights(a.lights, b.lights) && samePoints(a.pointLights, b.pointLights);
}

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
