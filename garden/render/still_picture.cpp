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

bool sameQuality(const RenderQuality& a, const RenderQuality& b) {
    return a.msaaSamples == b.msaaSamples && a.shadows == b.shadows && a.shadowMapSize == b.shadowMapSize &&
           a.shadowDistance == b.shadowDistance && a.ambientOcclusion == b.ambientOcclusion &&
           a.aoSamples == b.aoSamples && a.aoHalfResolution == b.aoHalfResolution && a.aoRadius == b.aoRadius &&
           a.exposure == b.exposure && a.renderScale == b.renderScale && a.smoothUpscale == b.smoothUpscale &&
           a.materialBump == b.materialBump && a.skyMapSize == b.skyMapSize && a.detailScale == b.detailScale;
}

PictureStep StillPicture::step(bool same, const RenderQuality& quality, const std::optional<RenderQuality>& still,
                               int viewsBeforeSharpening) {
    if (!same || !held_) return PictureStep::Draw;
    held_->views += 1;
    const bool atQuality = sameQuality(held_->quality, quality);
    const bool atStill = still && sameQuality(held_->quality, *still);
    if (atStill) return PictureStep::Keep;
    // Held at the quality asked for: kept while it may yet sharpen.
    if (atQuality) return still && held_->views >= viewsBeforeSharpening ? PictureStep::Sharpen : PictureStep::Keep;
    return PictureStep::Draw;  // the quality asked for changed: drawn at it
}

void StillPicture::drawn(const RenderQuality& quality, const OcclusionImage& occlusion) {
    held_ = Held{quality, occlusion, 0};
}

}  // namespace hg::garden
