// Dear ImGui on the garden's window: the context and the GLFW and OpenGL 3
// backends (built into Debian's libimgui.a). One Overlay at a time (ImGui's
// context is global). A frame: newFrame, panels (panels.h), render after
// the scene, into whatever framebuffer is bound.
#pragma once

#include "garden/render/panels.h"

namespace hg::garden {

class GlWindow;

class Overlay {
public:
    // installCallbacks: ImGui installs GLFW input callbacks that chain to
    // those already set, so install the garden's own callbacks first.
    // Layout is not saved to an imgui.ini. Throws GlError when a backend
    // fails or another Overlay exists.
    explicit Overlay(GlWindow& window, bool installCallbacks = true);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    void newFrame();
    // Draws the frame's panels over the bound framebuffer; restores the GL
    // state it changes.
    void render();

    // True when ImGui uses the mouse or keyboard this frame, so the garden
    // should not also act on them.
    bool wantsMouse() const;
    bool wantsKeyboard() const;
};

}  // namespace hg::garden
