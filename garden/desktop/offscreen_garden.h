// `replay --offscreen WxH`: a hidden window's GL context, an offscreen
// framebuffer and the renderer; each replayed frame is uploaded and drawn,
// and screenshots are PNGs of that framebuffer.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "garden/render/render_quality.h"
#include "garden/replay/replay_runner.h"

namespace hg::garden {

class OffscreenGarden : public FrameRenderer {
public:
    // Null with `error` set when there is no display or no GL 3.3 context.
    static std::unique_ptr<OffscreenGarden> create(int width, int height, std::string& error);
    ~OffscreenGarden() override;

    ViewUpload upload(GardenSession& session, double allowanceMs) override;
    ViewDraw render(GardenSession& session) override;
    std::string screenshot(const std::string& path) override;
    // What the renderer spends on the picture (replay --quality).
    void setQuality(const RenderQuality& quality);
    // `replay --quality auto`: as the desktop, the renderer's preset stepped
    // down and up by the GPU's time against `budgetMs` (QualityGovernor),
    // and the levels of detail chosen for the scene's pixels at its render
    // scale. What it did, in words, for the replay's notes.
    void setAutoQuality(double budgetMs);
    std::string autoQualitySummary() const;
    // Chunks in one multi-draw (the default where GL 4.3 is there) or a call
    // each; false when multi-draw was asked for and is missing.
    bool setMultiDraw(bool on);
    // Sculptures hidden behind nearer ones left out (the default) or drawn
    // (Renderer::setOcclusionCulling).
    void setOcclusionCulling(bool on);

    // A camera of the caller's instead of the session's navigator (none:
    // the navigator's, as the window shows it).
    struct Camera {
        glm::mat4 view{1.0f};
        glm::mat4 projection{1.0f};
        glm::vec3 eye{0.0f};
    };
    void setCamera(const std::optional<Camera>& camera);
    // Only sculpture `index` drawn (-1: every one; GardenView::showOnly).
    void showOnly(int index);
    // Far sculptures as cards beyond `metres` (0: never; GardenView::setImpostorDistance).
    void setImpostorDistance(float metres);
    // Far sculptures the last render drew as chunks for want of a baked
    // impostor, and impostors baked so far (benches).
    std::size_t impostorsWanted() const;
    std::size_t impostorsBaked() const;
    // Bytes of chunk meshes the arena may move a frame (0: never compacted;
    // GardenView::setArenaCompactBytes), and what the arena holds now.
    void setArenaCompactBytes(std::size_t bytes);
    struct ArenaUse {
        std::size_t capacityBytes = 0, usedBytes = 0, pages = 0, pagesMade = 0, bytesMoved = 0;
        std::size_t compactBytesPerFrame = 0;
    };
    ArenaUse arenaUse() const;

private:
    struct Impl;
    explicit OffscreenGarden(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace hg::garden
