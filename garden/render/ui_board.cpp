#include "garden/render/ui_board.h"

#include <cfloat>
#include <cstdint>

#include "garden/render/gl_context.h"
#include "garden/render/gl_objects.h"
#include "garden/render/shader_program.h"

#include <epoxy/gl.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <glm/gtc/type_ptr.hpp>

namespace hg::garden {

namespace {

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
uniform mat4 viewProjection;
out vec2 vUv;
void main() { vUv = uv; gl_Position = viewProjection * vec4(position, 1.0); }
)";
const char* kFragment = R"(#version 330 core
in vec2 vUv;
uniform sampler2D board;
out vec4 color;
void main() { color = texture(board, vUv); }
)";

// FNV-1a over what ImGui would draw (vertices, indices, clip rectangles,
// textures): equal hashes draw the same pixels.
std::uint64_t drawDataHash(const ImDrawData& d) {
    std::uint64_t h = 1469598103934665603ull;
    const auto mix = [&h](const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    };
    for (int l = 0; l < d.CmdListsCount; ++l) {
        const ImDrawList& list = *d.CmdLists[l];
        mix(list.VtxBuffer.Data, static_cast<std::size_t>(list.VtxBuffer.Size) * sizeof(ImDrawVert));
        mix(list.IdxBuffer.Data, static_cast<std::size_t>(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
        for (const ImDrawCmd& c : list.CmdBuffer) {
            mix(&c.ClipRect, sizeof c.ClipRect);
            mix(&c.TextureId, sizeof c.TextureId);
            mix(&c.ElemCount, sizeof c.ElemCount);
            mix(&c.IdxOffset, sizeof c.IdxOffset);
            mix(&c.VtxOffset, sizeof c.VtxOffset);
        }
    }
    return h;
}

}  // namespace

struct UiBoard::Gl {
    gl::Texture texture = gl::Texture::create();
    gl::Framebuffer fbo = gl::Framebuffer::create();
    ShaderProgram program{"ui board", kVertex, kFragment};
    gl::VertexArray vao = gl::VertexArray::create();
    gl::Buffer vertices = gl::Buffer::create();
    std::optional<std::uint64_t> drawn;  // drawDataHash of what the texture shows
};

UiBoard::UiBoard(int widthPixels, int heightPixels)
    : gl_(std::make_unique<Gl>()), width_(widthPixels), height_(heightPixels) {
    glBindTexture(GL_TEXTURE_2D, gl_->texture.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, gl_->fbo.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, gl_->texture.get(), 0);
    const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!complete) throw GlError("a board's texture cannot be drawn into");

    glBindVertexArray(gl_->vao.get());
    glBindBuffer(GL_ARRAY_BUFFER, gl_->vertices.get());
    glBufferData(GL_ARRAY_BUFFER, 4 * 5 * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glBindVertexArray(0);

    // A context of its own: the window's overlay keeps its windows, fonts
    // and mouse; this one has no platform backend, the board is its screen.
    ImGuiContext* before = ImGui::GetCurrentContext();
    ImGuiContext* ours = ImGui::CreateContext();
    context_ = ours;
    ImGui::SetCurrentContext(ours);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(static_cast<float>(width_), static_cast<float>(height_));
    ImGui::StyleColorsDark();
    const bool ok = ImGui_ImplOpenGL3_Init("#version 330 core");
    ImGui::SetCurrentContext(before);
    if (!ok) {
        ImGui::DestroyContext(ours);
        throw GlError("ImGui's OpenGL 3 backend failed to initialise for a board");
    }
}

UiBoard::~UiBoard() {
    ImGuiContext* before = ImGui::GetCurrentContext();
    ImGui::SetCurrentContext(static_cast<ImGuiContext*>(context_));
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(static_cast<ImGuiContext*>(context_));
    ImGui::SetCurrentContext(before == context_ ? nullptr : before);
}

UiBoard::Current::Current(const UiBoard& board) : before_(ImGui::GetCurrentContext()) {
    ImGui::SetCurrentContext(static_cast<ImGuiContext*>(board.context_));
}

UiBoard::Current::~Current() { ImGui::SetCurrentContext(static_cast<ImGuiContext*>(before_)); }

void UiBoard::newFrame(const std::optional<glm::vec2>& mousePixels, bool mouseDown, float dt) {
    ImGuiIO& io = ImGui::GetIO();
    io.DeltaTime = dt > 0.0f ? dt : 1.0f / 90.0f;
    io.MousePos = mousePixels ? ImVec2(mousePixels->x, mousePixels->y) : ImVec2(-FLT_MAX, -FLT_MAX);
    io.MouseDown[0] = mouseDown;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
}

bool UiBoard::render() {
    ImGui::Render();
    const std::uint64_t hash = drawDataHash(*ImGui::GetDrawData());
    if (gl_->drawn == hash) return false;
    gl_->drawn = hash;
    {
        const gl::TargetKept kept;
        glBindFramebuffer(GL_FRAMEBUFFER, gl_->fbo.get());
        glViewport(0, 0, width_, height_);
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    glBindTexture(GL_TEXTURE_2D, gl_->texture.get());
    glGenerateMipmap(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    return true;
}

void UiBoard::draw(const std::array<glm::vec3, 4>& corners, const glm::mat4& viewProjection) const {
    // The texture's first row is the board's top (ImGui's y grows down, GL
    // stores what it drew bottom row first): v = 1 at the top.
    const float uvs[4][2] = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
    float data[4][5];
    for (std::size_t i = 0; i < 4; ++i) {
        data[i][0] = corners[i].x;
        data[i][1] = corners[i].y;
        data[i][2] = corners[i].z;
        data[i][3] = uvs[i][0];
        data[i][4] = uvs[i][1];
    }
    glBindBuffer(GL_ARRAY_BUFFER, gl_->vertices.get());
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(data), data);
    gl_->program.use();
    glUniformMatrix4fv(gl_->program.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    glUniform1i(gl_->program.uniform("board"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, gl_->texture.get());
    const GLboolean depth = glIsEnabled(GL_DEPTH_TEST), cull = glIsEnabled(GL_CULL_FACE), blend = glIsEnabled(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBindVertexArray(gl_->vao.get());
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (depth) glEnable(GL_DEPTH_TEST);
    if (cull) glEnable(GL_CULL_FACE);
    if (!blend) glDisable(GL_BLEND);
}

}  // namespace hg::garden
