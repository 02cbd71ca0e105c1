#include "garden/desktop/offscreen_garden.h"

#include <cstdio>

#include "garden/window/garden_view.h"
#include "garden/render/gl_context.h"
#include "garden/render/quality_governor.h"
#include "garden/render/offscreen_target.h"
#include "garden/render/screenshot.h"

namespace hg::garden {

struct OffscreenGarden::Impl {
    GlWindow window;
    OffscreenTarget target;
    Renderer renderer;
    GardenView view{renderer};
    std::optional<Camera> camera;
    std::optional<QualityGovernor> governor;  // replay --quality auto

    Impl(int width, int height)
        : window([] {
              WindowOptions o;
              o.width = 64;
              o.height = 64;
              o.visible = false;
              o.vsync = false;
              return o;
          }()),
          target(width, height) {}
};

std::unique_ptr<OffscreenGarden> OffscreenGarden::create(int width, int height, std::string& error) {
    try {
        return std::unique_ptr<OffscreenGarden>(new OffscreenGarden(std::make_unique<Impl>(width, height)));
    } catch (const std::exception& e) {
        error = std::string("cannot render offscreen: ") + e.what();
        return nullptr;
    }
}

OffscreenGarden::OffscreenGarden(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
OffscreenGarden::~OffscreenGarden() = default;

ViewUpload OffscreenGarden::upload(GardenSession& session, double allowanceMs) {
    return impl_->view.upload(session, allowanceMs);
}

ViewDraw OffscreenGarden::render(GardenSession& session) {
    impl_->target.bind();
    const glm::ivec2 viewport(impl_->target.width(), impl_->target.height());
    if (const auto& c = impl_->camera)
        impl_->view.render(session, viewport, c->view, c->projection, c->eye);
    else
        impl_->view.render(session, viewport, static_cast<float>(session.settings().fovY));
    const RenderStats r = impl_->renderer.endFrame();
    // The CPU cost of drawing includes waiting for llvmpipe here: a software
    // GPU; on hardware this is where the driver would queue the frame.
    OffscreenTarget::finish();
    if (auto& g = impl_->governor) {
        if (const auto q = g->observe(r.gpuMs())) impl_->renderer.setQuality(*q);
        // From the next frame on, as the desktop does each frame.
        session.settings().viewportHeight = detailPixels(impl_->target.height(), impl_->renderer.quality());
    }
    return viewDrawOf(r);
}

void OffscreenGarden::setQuality(const RenderQuality& quality) { impl_->renderer.setQuality(quality); }

void OffscreenGarden::setAutoQuality(double budgetMs) {
    impl_->governor.emplace(rendererPreset(GlWindow::glVersionString()), budgetMs);
    impl_->renderer.setQuality(impl_->governor->quality());
}

std::string OffscreenGarden::autoQualitySummary() const {
    const auto& g = impl_->governor;
    if (!g) return "off";
    const RenderQuality& q = g->quality();
    char text[240];
    std::snprintf(text, sizeof text,
                  "%zu change%s against %.1f ms; ended on rung %zu of %zu (MSAA %dx, shadows %s, occlusion %s, render "
                  "scale %.2f, detail scale %.2f)",
                  g->changes(), g->changes() == 1 ? "" : "s", g->budgetMs(), g->step() + 1,
                  g->steps(), q.msaaSamples, q.shadows ? "on" : "off", q.ambientOcclusion ? "on" : "off",
                  static_cast<double>(q.renderScale), static_cast<double>(q.detailScale));
    return text;
}

void OffscreenGarden::setCamera(const std::optional<Camera>& camera) { impl_->camera = camera; }

void OffscreenGarden::showOnly(int index) { impl_->view.showOnly(index); }

void OffscreenGarden::setImpostorDistance(float metres) { impl_->view.setImpostorDistance(metres); }

std::size_t OffscreenGarden::impostorsWanted() const { return impl_->view.impostorsWanted(); }

std::size_t OffscreenGarden::impostorsBaked() const {
    const ImpostorAtlas* atlas = impl_->renderer.impostorAtlas();
    return atlas ? atlas->bakes() : 0;
}

void OffscreenGarden::setArenaCompactBytes(std::size_t bytes) { impl_->view.setArenaCompactBytes(bytes); }

OffscreenGarden::ArenaUse OffscreenGarden::arenaUse() const {
    const ChunkArena& a = impl_->renderer.arena();
    return {a.capacityBytes(), a.usedBytes(), a.livePages(), a.pagesMade(), a.bytesMoved(),
            impl_->view.arenaCompactBytes()};
}

bool OffscreenGarden::setMultiDraw(bool on) { return impl_->renderer.setMultiDraw(on) == on; }
void OffscreenGarden::setOcclusionCulling(bool on) { impl_->renderer.setOcclusionCulling(on); }

std::string OffscreenGarden::screenshot(const std::string& path) {
    impl_->target.bind();
    return writePng(path, impl_->target.width(), impl_->target.height(), impl_->target.readColor());
}

}  // namespace hg::garden
