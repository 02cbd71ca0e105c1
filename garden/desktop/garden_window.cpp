#include "garden/desktop/garden_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace hg::garden {

namespace {

WindowEvents* eventsOf(GLFWwindow* w) { return static_cast<WindowEvents*>(glfwGetWindowUserPointer(w)); }

void onScroll(GLFWwindow* w, double, double dy) { eventsOf(w)->wheel += static_cast<float>(dy); }

void onKey(GLFWwindow* w, int key, int, int action, int mods) {
    if (action == GLFW_PRESS) addKeyPress(eventsOf(w)->keys, key, mods);
}

}  // namespace

GardenWindow::GardenWindow(const WindowOptions& options, bool overlay) : window_(options) {
    glfwSetWindowUserPointer(window_.handle(), &events_);
    glfwSetScrollCallback(window_.handle(), onScroll);
    glfwSetKeyCallback(window_.handle(), onKey);
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
