#include "garden/window/garden_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace hg::garden {

namespace {

WindowEvents* eventsOf(GLFWwindow* w) { return static_cast<WindowEvents*>(glfwGetWindowUserPointer(w)); }

void onScroll(GLFWwindow* w, double, double dy) { eventsOf(w)->wheel += static_cast<float>(dy); }

void onKey(GLFWwindow* w, int key, int, int action, int mods) {
    if (action == GLFW_PRESS) addKeyPress(eventsOf(w)->keys, key, mods);
}

glm::vec2 cursorOf(GLFWwindow* w) {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(w, &x, &y);
    return {static_cast<float>(x), static_cast<float>(y)};
}

void onCursor(GLFWwindow* w, double x, double y) {
    eventsOf(w)->pointer.push_back({PointerEvent::Kind::Move, PointerButton::Tool,
                                    {static_cast<float>(x), static_cast<float>(y)}});
}

void onMouseButton(GLFWwindow* w, int button, int action, int) {
    PointerButton b = PointerButton::Tool;
    switch (button) {
        case GLFW_MOUSE_BUTTON_LEFT: b = PointerButton::Tool; break;
        case GLFW_MOUSE_BUTTON_RIGHT: b = PointerButton::Look; break;
        case GLFW_MOUSE_BUTTON_MIDDLE: b = PointerButton::Gesture; break;
        default: return;
    }
    const auto kind = action == GLFW_PRESS ? PointerEvent::Kind::Press : PointerEvent::Kind::Release;
    eventsOf(w)->pointer.push_back({kind, b, cursorOf(w)});
}

}  // namespace

GardenWindow::GardenWindow(const WindowOptions& options, bool overlay) : window_(options) {
    glfwSetWindowUserPointer(window_.handle(), &events_);
    glfwSetScrollCallback(window_.handle(), onScroll);
    glfwSetKeyCallback(window_.handle(), onKey);
    glfwSetCursorPosCallback(window_.handle(), onCursor);
    glfwSetMouseButtonCallback(window_.handle(), onMouseButton);
    if (overlay) overlay_ = std::make_unique<Overlay>(window_);  // after our callbacks: ImGui chains to them
    renderer_ = std::make_unique<Renderer>();
    view_ = std::make_unique<GardenView>(*renderer_);
}

// The GL objects go while the window's context is current; the window last.
GardenWindow::~GardenWindow() {
    window_.makeCurrent();
    view_.reset();
    renderer_.reset();
    overlay_.reset();
    glfwSetWindowUserPointer(window_.handle(), nullptr);
}

}  // namespace hg::garden
