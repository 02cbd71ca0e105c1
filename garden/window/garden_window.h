// What the garden is drawn with, made once per run: the window (the
// desktop's view, or the headset's mirror), its key and wheel events, the
// ImGui overlay, the renderer and the session's meshes on the GPU. The
// desktop and the headset modes share one, so switching between them keeps
// the uploaded meshes and ImGui's single context, and the garden's own input
// callbacks stay installed before ImGui's (which chain to them).
#pragma once

#include <memory>
#include <vector>

#include "garden/window/desktop_keys.h"
#include "garden/window/garden_view.h"
#include "garden/hands/pointer_events.h"
#include "garden/render/gl_context.h"
#include "garden/render/overlay.h"
#include "garden/render/renderer.h"

namespace hg::garden {

// Key presses, the wheel and the mouse's buttons and moves arrive as
// events between frames (garden/hands/pointer_events.h); the frame that
// reads them clears them.
struct WindowEvents {
    float wheel = 0.0f;
    DesktopKeys keys;
    std::vector<PointerEvent> pointer;  // in the order they came
};

class GardenWindow {
public:
    // `overlay` false: no ImGui (a hidden headset mirror, benchmarks).
    // Throws GlError when the window or GL cannot be had.
    explicit GardenWindow(const WindowOptions& options, bool overlay = true);
    ~GardenWindow();
    GardenWindow(const GardenWindow&) = delete;
    GardenWindow& operator=(const GardenWindow&) = delete;

    GlWindow& window() { return window_; }
    WindowEvents& events() { return events_; }
    Overlay* overlay() { return overlay_.get(); }  // null without one
    Renderer& renderer() { return *renderer_; }
    GardenView& view() { return *view_; }

private:
    GlWindow window_;
    WindowEvents events_;
    std::unique_ptr<Overlay> overlay_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<GardenView> view_;
};

}  // namespace hg::garden
