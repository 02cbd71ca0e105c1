#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "garden/render/gl_context.h"
#include "garden/render/overlay.h"

namespace hg::garden {
namespace {
bool overlayLive = false;
}

Overlay::Overlay(GlWindow& window, bool installCallbacks) {
    if (overlayLive) throw GlError("only one ImGui overlay at a time");
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    ImGui::StyleColorsDark();
    window.makeCurrent();
    if (!ImGui_ImplGlfw_InitForOpenGL(window.handle(), installCallbacks)) {
        ImGui::DestroyContext();
        throw GlError("ImGui GLFW backend failed to initialise");
    }
    // The backend's own GL loader reads the current context's version;
    // 330 core shaders match the context the window asks for.
    if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        throw GlError("ImGui OpenGL 3 backend failed to initialise");
    }
    overlayLive = true;
}

Overlay::~Overlay() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    overlayLive = false;
}

void Overlay::newFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void Overlay::render() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool Overlay::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }

bool Overlay::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace hg::garden
