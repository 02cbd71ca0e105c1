// What one frame cost and did, collected every frame (docs/design.md §6: stats are
// always on) and shown by the overlay, written by `replay --stats`.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hg::garden {

// The stages a frame's budget is split between, in the order they run.
enum class Stage : int { Input = 0, Lod, Morph, Remesh, Upload, Render, Count };
constexpr int kStageCount = static_cast<int>(Stage::Count);
const char* stageName(Stage s);

// The GPU's milliseconds for each render pass of a frame (docs/rendering.md,
// "GPU time"); -1 where a pass did not run or is not measured yet.
struct GpuPassMs {
    double shadow = -1.0;
    double scene = -1.0;
    double occlusion = -1.0;  // ambient occlusion
    double post = -1.0;       // the composite, lines and panels
};

struct FrameStats {
    std::uint64_t frame = 0;
    double budgetMs = 11.1;
    double totalMs = 0.0;                       // CPU time of the whole frame
    std::array<double, kStageCount> stageMs{};  // CPU time per stage
    std::size_t morphSamples = 0;               // samples blended this frame
    std::size_t morphPending = 0;               // samples left in the morph update
    std::size_t chunksMeshed = 0;
    std::size_t chunksShown = 0;
    std::size_t remeshPending = 0;              // dirty chunks left, all sculptures
    std::size_t lodChunksVisited = 0;           // chunks whose level the LOD stage tested
    std::size_t sculpturesLoading = 0;          // still being sampled (progressive loading)
    std::size_t meshBytesShown = 0;             // new meshes shown this frame (poly::meshBytes)
    std::size_t groupsShown = 0;                // groups of touching chunks they came in
    std::size_t uploadBytes = 0;
    std::size_t uploadsPending = 0;
    std::size_t trianglesShown = 0;             // in the meshes on show (drawn or not)
    std::size_t trianglesDrawn = 0;             // after view culling (0 headless)
    std::size_t chunksDrawn = 0;                // chunk draws after view culling
    std::size_t drawCalls = 0;                  // GL draw calls (chunks go out batched)
    std::size_t impostorsDrawn = 0;             // far sculptures drawn as impostor cards
    std::size_t sculpturesHidden = 0;           // left out as hidden behind nearer ones
    std::size_t shadowMapsDrawn = 0;            // views whose shadow map was drawn (0 headless)
    std::size_t shadowMapsKept = 0;             // views that kept the one drawn before (Renderer::setShadowReuse)
    std::size_t picturesKept = 0;               // views that showed the picture held (Renderer::setPictureReuse)
    std::size_t picturesSharpened = 0;          // still views drawn again at a still quality
    // GPU milliseconds of the latest frame the GPU finished (timer queries,
    // read without waiting: a frame or a few behind); -1 where unknown.
    double gpuMs = -1.0;
    GpuPassMs gpuPassMs;  // gpuMs pass by pass
};

// The last N frames, for the frame-time graph.
class FrameHistory {
public:
    explicit FrameHistory(std::size_t capacity = 240) : capacity_(capacity) {}
    void push(const FrameStats& s);
    const std::vector<FrameStats>& frames() const { return frames_; }  // oldest first
    const FrameStats* last() const { return frames_.empty() ? nullptr : &frames_.back(); }

private:
    std::size_t capacity_;
    std::vector<FrameStats> frames_;
};

}  // namespace hg::garden
