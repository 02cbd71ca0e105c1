#include "garden/render/render_quality.h"

#include <algorithm>
#include <cmath>

namespace hg::garden {

RenderQuality qualityOf(QualityPreset preset) {
    RenderQuality q;
    switch (preset) {
        case QualityPreset::Low:
            q.msaaSamples = 1;
            q.shadows = false;
            q.ambientOcclusion = false;
            q.materialBump = false;
            q.skyMapSize = 512;
            break;
        case QualityPreset::Medium:
            q.msaaSamples = 2;
            q.shadowMapSize = 1024;
            q.aoSamples = 8;
            q.aoHalfResolution = true;
            break;
        case QualityPreset::High:
            q.aoSamples = 16;
            q.aoHalfResolution = true;
            break;
    }
    return q;
}

int scenePixels(int outputPixels, const RenderQuality& q) {
    const float scale = std::clamp(q.renderScale, 0.25f, 1.0f);
    return std::max(1, static_cast<int>(std::lround(static_cast<float>(outputPixels) * scale)));
}

int detailPixels(int outputPixels, const RenderQuality& q) {
    const float scale = std::clamp(q.detailScale, 0.25f, 1.0f);
    return std::max(1, static_cast<int>(std::lround(static_cast<float>(scenePixels(outputPixels, q)) * scale)));
}

bool sameQuality(const RenderQuality& a, const RenderQuality& b) {
    return a.msaaSamples == b.msaaSamples && a.shadows == b.shadows && a.shadowMapSize == b.shadowMapSize &&
           a.shadowDistance == b.shadowDistance && a.ambientOcclusion == b.ambientOcclusion &&
           a.aoSamples == b.aoSamples && a.aoHalfResolution == b.aoHalfResolution && a.aoRadius == b.aoRadius &&
           a.exposure == b.exposure && a.renderScale == b.renderScale && a.smoothUpscale == b.smoothUpscale &&
           a.materialBump == b.materialBump && a.skyMapSize == b.skyMapSize && a.detailScale == b.detailScale;
}

QualityPreset rendererPreset(const std::string& glRenderer) {
    for (const char* software : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"})
        if (glRenderer.find(software) != std::string::npos) return QualityPreset::Low;
    return QualityPreset::High;
}

std::optional<QualityPreset> parseQualityPreset(const std::string& name) {
    if (name == "low") return QualityPreset::Low;
    if (name == "medium") return QualityPreset::Medium;
    if (name == "high") return QualityPreset::High;
    return std::nullopt;
}

}  // namespace hg::garden
