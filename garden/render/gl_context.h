// A GLFW window with an OpenGL 3.3 core context: the desktop garden's
// window, and (hidden) the context that replay and the tests render into.
// GL entry points come from libepoxy, which resolves them per context, so
// nothing needs loading after the context is made current.
#pragma once

#include <glm/vec2.hpp>

#include <stdexcept>
#include <string>

struct GLFWwindow;

namespace hg::garden {

// No display, no GLFW, or no GL 3.3 core context: the message says which.
class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct WindowOptions {
    int width = 1280;
    int height = 720;
    std::string title = "Hypergarden";
    bool visible = true;   // false: offscreen work (replay, tests) in a hidden window
    bool vsync = true;     // swap interval 1; off for benchmarks
    bool resizable = true;
};

class GlWindow {
public:
    // Creates the window and makes its context current on this thread.
    // Throws GlError with "no X display: run under xvfb-run -a" when DISPLAY
    // is unset, and with GLFW's own message when window or context fail.
    explicit GlWindow(const WindowOptions& options = {});
    ~GlWindow();
    GlWindow(const GlWindow&) = delete;
    GlWindow& operator=(const GlWindow&) = delete;

    void makeCurrent();
    void swapBuffers();
    void setVsync(bool on);
    void setTitle(const std::string& title);
    void setSize(glm::ivec2 size);  // screen coordinates
    bool shouldClose() const;
    void setShouldClose(bool close);

    glm::ivec2 size() const;             // screen coordinates (input, ImGui)
    glm::ivec2 framebufferSize() const;  // pixels (viewport, screenshots)

    // For input callbacks and the ImGui backend. Owned by this object.
    GLFWwindow* handle() const { return window_; }

    // "4.5 (Core Profile) Mesa ..." and the renderer string, for logs.
    static std::string glVersionString();

private:
    GLFWwindow* window_ = nullptr;
};

// Polls window-system events for every window (input callbacks run here).
void pollEvents();

}  // namespace hg::garden
