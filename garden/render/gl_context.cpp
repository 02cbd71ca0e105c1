#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "garden/render/gl_context.h"

#include <chrono>
#include <cstdlib>
#include <thread>

namespace hg::garden {
namespace {

// GLFW reports errors through a callback; keep the last message so the
// exception can carry it. GLFW is used from the main thread only.
std::string& lastGlfwError() {
    static std::string message;
    return message;
}

void onGlfwError(int code, const char* description) {
    lastGlfwError() = std::string(description ? description : "unknown") + " (GLFW error " + std::to_string(code) + ")";
}

// GLFW, and with it the X connection, stays up from the first window to the
// end of the process. Closing the last connection makes an X server without
// -noreset (Xvfb under xvfb-run) reset itself, and a client connecting
// during the reset is refused: tests that open window after window would
// fail at random.
void initGlfwOnce() {
    static bool initialised = false;
    if (initialised) return;
    glfwSetErrorCallback(onGlfwError);
    // The server may still be resetting after another process, its last
    // client, left; it answers again within a few milliseconds.
    for (int attempt = 0;; ++attempt) {
        lastGlfwError().clear();
        if (glfwInit() == GLFW_TRUE) break;
        const bool refused = lastGlfwError().find("Failed to open display") != std::string::npos;
        if (!refused) throw GlError("cannot initialise GLFW: " + lastGlfwError());
        if (attempt == 40)
            throw GlError("cannot initialise GLFW: " + lastGlfwError() + "; is an X server running there? (xvfb-run -a)");
        std::this_thread::sleep_for(std::chrono::milliseconds(25));
    }
    initialised = true;
    std::atexit(glfwTerminate);
}

// Debian's GLFW 3.3 is built for X11 only.
bool hasDisplay() {
    const char* display = std::getenv("DISPLAY");
    return display && *display;
}

}  // namespace

GlWindow::GlWindow(const WindowOptions& options) {
    if (!hasDisplay()) throw GlError("no X display: run under xvfb-run -a");
    if (options.width <= 0 || options.height <= 0) throw GlError("window size must be positive");
    initGlfwOnce();

    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_RESIZABLE, options.resizable ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    lastGlfwError().clear();
    window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (!window_) {
        std::string why = lastGlfwError();
        throw GlError("cannot create an OpenGL 3.3 core window: " + (why.empty() ? std::string("unknown reason") : why));
    }
    glfwMakeContextCurrent(window_);
    // Mesa may hand out a newer core version; older than 3.3 is refused.
    if (epoxy_gl_version() < 33 || epoxy_is_desktop_gl() == 0) {
        std::string got = glVersionString();
        glfwDestroyWindow(window_);
        window_ = nullptr;
        throw GlError("OpenGL 3.3 core is required, got " + got);
    }
    glfwSwapInterval(options.vsync ? 1 : 0);
}

GlWindow::~GlWindow() {
    if (window_) {
        if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
        glfwDestroyWindow(window_);
    }
}

void GlWindow::makeCurrent() { glfwMakeContextCurrent(window_); }

void GlWindow::swapBuffers() { glfwSwapBuffers(window_); }

void GlWindow::setVsync(bool on) {
    makeCurrent();
    glfwSwapInterval(on ? 1 : 0);
}

void GlWindow::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void GlWindow::setSize(glm::ivec2 size) { glfwSetWindowSize(window_, size.x, size.y); }

bool GlWindow::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

void GlWindow::setShouldClose(bool close) { glfwSetWindowShouldClose(window_, close ? GLFW_TRUE : GLFW_FALSE); }

glm::ivec2 GlWindow::size() const {
    glm::ivec2 s(0);
    glfwGetWindowSize(window_, &s.x, &s.y);
    return s;
}

glm::ivec2 GlWindow::framebufferSize() const {
    glm::ivec2 s(0);
    glfwGetFramebufferSize(window_, &s.x, &s.y);
    return s;
}

std::string GlWindow::glVersionString() {
    auto str = [](GLenum name) {
        const GLubyte* s = glGetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return str(GL_VERSION) + ", " + str(GL_RENDERER);
}

void pollEvents() { glfwPollEvents(); }

}  // namespace hg::garden
