// Where a frame's views go (docs/design.md §6): GardenSession::frame runs the
// upload stage and then the render stage through a ViewSink, and keeps the
// stage accounting (times, bytes, draw calls) itself. The desktop window,
// each headset frame (both eyes), `replay --offscreen` and the benches'
// recorders implement it; headless replays, tests and benches use the null
// sink, which uploads and draws nothing.
#pragma once

#include <cstddef>

#include "garden/app/frame_stats.h"

namespace hg::garden {

class GardenSession;

// What the upload stage moved to the GPU, and what it left for later frames.
struct ViewUpload {
    std::size_t bytes = 0;
    std::size_t pending = 0;  // sculptures whose new meshes wait for a later frame
};

// What the render stage drew, over every view of the frame.
struct ViewDraw {
    std::size_t trianglesDrawn = 0;
    std::size_t chunksDrawn = 0;
    std::size_t drawCalls = 0;  // GL calls: one per batch of chunks where multi-draw is on
    double gpuMs = -1.0;        // the GPU's time for the latest frame it finished; -1 unknown
    GpuPassMs gpuPassMs;        // the same, pass by pass
    std::size_t impostorsDrawn = 0;  // far sculptures drawn as cards (impostors) instead of chunks
    std::size_t sculpturesHidden = 0;  // left out as hidden behind nearer ones (occlusion queries)
    std::size_t shadowMapsDrawn = 0;   // views whose shadow map was drawn
    std::size_t shadowMapsKept = 0;    // views that kept the map drawn before (nothing it shows changed)
    std::size_t picturesKept = 0;      // views that showed the picture held (a still view)
    std::size_t picturesSharpened = 0;  // still views drawn again at a still quality
};

class ViewSink {
public:
    virtual ~ViewSink() = default;
    // New meshes to the GPU within `allowanceMs` (the scheduler's share of
    // what is left of the frame).
    virtual ViewUpload upload(GardenSession& session, double allowanceMs) = 0;
    // Draws the frame's views (and the panels that go with them: a panel
    // may change the session, as a command would).
    virtual ViewDraw render(GardenSession& session) = 0;
};

// Uploads and draws nothing: the garden without a window.
class NullViewSink final : public ViewSink {
public:
    ViewUpload upload(GardenSession&, double) override { return {}; }
    ViewDraw render(GardenSession&) override { return {}; }
};

}  // namespace hg::garden
