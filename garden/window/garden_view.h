// Draws a running garden (GardenSession) with the Renderer: the upload
// stage (new chunk meshes to GPU buffers) and the render stage (ground,
// paths, sculptures, the morph triangle on the ground, the detail sphere,
// markers for missing sculptures). Shared by the desktop window and `replay
// --offscreen`, so screenshots show what the window shows.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "garden/app/garden_session.h"
#include "garden/render/material_look.h"
#include "garden/render/renderer.h"

namespace hg::garden {

// What a frame's views drew, for the frame's stats (garden/app/view_sink.h),
// from the renderer's endFrame: the desktop, the headset and offscreen alike.
ViewDraw viewDrawOf(const RenderStats& r);

class GardenView {
public:
    explicit GardenView(Renderer& renderer) : renderer_(renderer) {}

    // Uploads the chunks whose shown mesh changed. A sculpture's chunks go
    // up together (its remesh queue shows groups at once, and so must the
    // GPU); once `allowanceMs` is spent the next sculptures wait for the
    // next frame. The bytes uploaded, and the sculptures that wait. Then
    // bakes the impostors the last render wanted (nearest first, at most
    // kBakesPerFrame, within the allowance), from sculptures whose meshes
    // are all meshed and uploaded. With time still left, moves up to
    // arenaCompactBytes() of chunk meshes out of a sparse page of the
    // renderer's arena (Renderer::compactArena: defragmented in the background).
    ViewUpload upload(const GardenSession& session, double allowanceMs);

    // Draws into the bound framebuffer of `viewport` pixels; chunks outside
    // the view frustum are not drawn. A sculpture whose bounding sphere is
    // beyond impostorDistance() from the eye is
    // drawn as its impostor card once one is baked (and back as chunks
    // within 0.9 times that distance); not with the wireframe overlay.
    void render(const GardenSession& session, glm::ivec2 viewport, float fovY);
    // The same through a given camera (an XR eye: its own view and
    // off-centre projection, `eye` its world position).
    void render(const GardenSession& session, glm::ivec2 viewport, const glm::mat4& view, const glm::mat4& projection,
                const glm::vec3& eye);

    static ChunkId chunkId(std::size_t sculpture, std::size_t chunk) {
        return (static_cast<ChunkId>(sculpture) << 32) | static_cast<ChunkId>(chunk);
    }
    // Paths are drawn as meshes too, under ids no sculpture reaches.
    static ChunkId pathId(std::size_t path) { return (ChunkId{0xFFFFFFFFu} << 32) | static_cast<ChunkId>(path); }

    // The clay view and the wireframe overlay (sculptures only; the paths
    // keep their materials).
    ViewLook& look() { return look_; }
    const ViewLook& look() const { return look_; }

    // Only sculpture `index` drawn (-1: every one), with the ground and the
    // paths: a turntable shows one sculpture, with nothing passing in front.
    void showOnly(int index) { only_ = index; }

    // A path's material detail is sized in metres of the path (its mesh is
    // in world units): a tenth puts stone's grains at about a centimetre,
    // gravel underfoot, where a sculpture's detail is sized to its model.
    static constexpr float kPathDetailScale = 0.1f;

    // Metres from the eye to a sculpture's bounding sphere beyond which it
    // is drawn as its impostor card (0: never; --impostor-distance).
    static constexpr float kDefaultImpostorDistance = 30.0f;
    void setImpostorDistance(float metres) { impostorDistance_ = metres; }
    float impostorDistance() const { return impostorDistance_; }
    // Sculptures the last render drew as chunks for want of a current impostor.
    std::size_t impostorsWanted() const;
    // Impostors baked per upload at most (each renders views^2 frames of
    // one sculpture's coarse meshes).
    static constexpr int kBakesPerFrame = 2;
    // Bytes of chunk meshes the arena may move a frame (0: never compacted).
    // 2 MiB: a tenth of a millisecond's copy on a GPU, about a millisecond on
    // the software renderer; a 48 MiB page left a tenth full empties in a
    // few frames.
    static constexpr std::size_t kDefaultArenaCompactBytes = std::size_t{2} << 20;
    void setArenaCompactBytes(std::size_t bytes) { arenaCompactBytes_ = bytes; }
    std::size_t arenaCompactBytes() const { return arenaCompactBytes_; }

private:
    // What a sculpture's chunks are drawn with: its material, sized for its
    // detail, as the clay view or wireframe may change it.
    RenderMaterial materialOf(const Sculpture& st) const;
    // Draws sculpture `s` (model box lo..hi, in view) as its impostor card
    // when it is far enough and one is current; else notes that it wants one.
    bool drawnAsCard(const GardenSession& session, std::size_t s, const RenderMaterial& m, const double lo[3],
                     const double hi[3], const glm::vec3& eye);
    void bakeImpostors(const GardenSession& session, const std::chrono::steady_clock::time_point& start,
                       double allowanceMs);
    // Each sculpture whose cover changed since the last view (see Cover)
    // makes the renderer forget the hidden results behind it, old place and new.
    void forgetHiddenBehindChanges(const GardenSession& session);

    Renderer& renderer_;
    ViewLook look_;
    float impostorDistance_ = kDefaultImpostorDistance;
    std::size_t arenaCompactBytes_ = kDefaultArenaCompactBytes;
    int only_ = -1;
    // Per sculpture, the queue's shownGeneration() + 1 last uploaded (0:
    // never): a sculpture whose queue showed nothing new is not looked at.
    std::vector<std::uint64_t> uploaded_;
    // Per sculpture, the frameGeneration and chunk count of what was
    // uploaded: a grid rebuilt in a new frame (its source read again) has
    // other chunks, whose versions start again, so the old ones are dropped.
    struct Uploaded {
        std::uint64_t frameGeneration = 0;
        std::size_t chunks = 0;
        // Model-space box of the meshes uploaded (lo > hi: none), which the
        // visibility test draws (docs/rendering.md, "Hidden sculptures").
        glm::vec3 meshLo{1e30f}, meshHi{-1e30f};
        // What the sculpture covers on screen, as of the last view: drawn
        // or not, as a card or its chunks, where, and which meshes; with its
        // world box then (lo > hi: none).
        struct Cover {
            bool shown = false, card = false;
            glm::mat4 model{1.0f};
            std::uint64_t meshes = 0;
            glm::vec3 lo{1e30f}, hi{-1e30f};
            bool sameAs(const Cover& o) const {
                return shown == o.shown && (!shown || (card == o.card && model == o.model && meshes == o.meshes));
            }
        } cover;
    };
    std::vector<Uploaded> frames_;
    // Per sculpture: drawn as a card in the last view, and whether (and how
    // far beyond the distance) it wanted an impostor none was baked for.
    struct Far {
        bool card = false;
        bool wanted = false;
        float away = 0.0f;
    };
    std::vector<Far> far_;
};

}  // namespace hg::garden
