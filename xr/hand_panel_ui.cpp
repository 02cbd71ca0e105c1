#include "xr/hand_panel_ui.h"

#include "garden/app/garden_session.h"
#include "garden/render/gl_context.h"
#include "garden/render/gl_objects.h"
#include "garden/render/morph_triangle.h"
#include "garden/render/panels.h"
#include "garden/render/shader_program.h"
#include "xr/hand_panel.h"

#include <epoxy/gl.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cfloat>
#include <iterator>

#include <glm/gtc/type_ptr.hpp>

namespace hg::xr {

namespace {

using Kind = garden::ToolSettings::Kind;

// Two rows of four buttons across the top; the tool's parameters below on
// the left, the morph triangle on the right, the profile along the bottom.
constexpr float kCellX = kPanelPixelsX / 4.0f, kCellY = 40.0f, kButtonInset = 4.0f;
constexpr float kTop = 4.0f;
constexpr float kBodyY = 2.0f * kCellY + 12.0f;
constexpr float kMorphX = 300.0f, kMorphSide = 120.0f;
// ImGui's built-in font (ProggyClean) is 13 pixels high: the morph
// triangle's labels take a line above and below it.
constexpr float kFontLine = 13.0f;
constexpr float kFieldWidth = 150.0f;
constexpr float kTogglesY = kPanelPixelsY - 62.0f, kToggleStep = 130.0f;
constexpr float kCheckBox = kFontLine + 6.0f;  // the font and ImGui's frame padding (3) above and below

constexpr const char* kLabels[] = {"morph", "carve", "add", "melt", "perturb", "impacts", "undo", "redo"};

glm::vec2 buttonTopLeft(PanelButton b) {
    const int i = static_cast<int>(b);
    return glm::vec2(static_cast<float>(i % 4) * kCellX + kButtonInset, kTop + static_cast<float>(i / 4) * kCellY);
}
const glm::vec2 kButtonSize(kCellX - 2.0f * kButtonInset, kCellY - 2.0f * kButtonInset);

Kind toolOf(PanelButton b) {
    switch (b) {
        case PanelButton::Carve: return Kind::Carve;
        case PanelButton::Add: return Kind::Add;
        case PanelButton::Melt: return Kind::Melt;
        case PanelButton::Perturb: return Kind::Perturb;
        case PanelButton::Impacts: return Kind::Impacts;
        default: return Kind::None;
    }
}

bool slider(const char* label, double& value, double lo, double hi, const char* format) {
    ImGui::SetNextItemWidth(kFieldWidth);
    return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format,
                               ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
}

void parameters(garden::ToolSettings& t) {
    switch (t.kind) {
        case Kind::Carve:
        case Kind::Add:
        case Kind::Melt:
            slider("radius (m)", t.radius, garden::kMinToolRadius, 1.0, "%.3f");
            if (t.kind == Kind::Melt) slider("softness (vox)", t.softness, 0.25, 16.0, "%.2f");
            break;
        case Kind::Perturb:
            slider("strength (vox)", t.strength, 0.1, 50.0, "%.2f");
            slider("scale", t.perturbScale, garden::kMinPerturbScale, garden::kMaxPerturbScale, "%.2f");
            break;
        case Kind::Impacts:
            slider("size (m)", t.impactSize, garden::kMinImpactSize, garden::kMaxImpactSize, "%.3f");
            slider("compaction (cm3)", t.compactionCm3, 0.01, 100.0, "%.2f");
            ImGui::SetNextItemWidth(kFieldWidth);
            ImGui::SliderInt("count", &t.impactCount, 1, 500, "%d", ImGuiSliderFlags_Logarithmic);
            break;
        case Kind::None: ImGui::TextDisabled("the trigger picks the blend\non the ground triangle"); break;
        case Kind::Move: ImGui::TextDisabled("move: on the desktop only"); break;
    }
    if (t.kind == Kind::Carve || t.kind == Kind::Add || t.kind == Kind::Perturb) ImGui::Checkbox("reverse", &t.reverse);
    ImGui::TextDisabled("tool stick: size");
}

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
uniform mat4 viewProjection;
out vec2 vUv;
void main() { vUv = uv; gl_Position = viewProjection * vec4(position, 1.0); }
)";
const char* kFragment = R"(#version 330 core
in vec2 vUv;
uniform sampler2D panel;
out vec4 color;
void main() { color = texture(panel, vUv); }
)";

}  // namespace

glm::vec2 panelButtonCenter(PanelButton b) {
    const glm::vec2 c = buttonTopLeft(b) + 0.5f * kButtonSize;
    return c / glm::vec2(kPanelPixelsX, kPanelPixelsY);
}

const char* panelButtonLabel(PanelButton b) {
    const int i = static_cast<int>(b);
    return i >= 0 && i < static_cast<int>(std::size(kLabels)) ? kLabels[i] : "";
}

glm::vec2 panelMorphPoint(const glm::vec3& weights) {
    const garden::MorphTriangleLayout l = garden::morphTriangleLayout(glm::vec2(kMorphX, kBodyY), kMorphSide, kFontLine);
    return garden::triangleToScreen(l, garden::trianglePoint(weights)) / glm::vec2(kPanelPixelsX, kPanelPixelsY);
}

glm::vec2 panelToggleCenter(PanelToggle t) {
    const glm::vec2 c(kButtonInset + static_cast<float>(t) * kToggleStep + 0.5f * kCheckBox, kTogglesY + 0.5f * kCheckBox);
    return c / glm::vec2(kPanelPixelsX, kPanelPixelsY);
}

struct HandPanelUi::Gl {
    garden::gl::Texture texture = garden::gl::Texture::create();
    garden::gl::Framebuffer fbo = garden::gl::Framebuffer::create();
    garden::ShaderProgram program{"hand panel", kVertex, kFragment};
    garden::gl::VertexArray vao = garden::gl::VertexArray::create();
    garden::gl::Buffer vertices = garden::gl::Buffer::create();
    glm::vec2 selector{0.5f, 0.3f};  // the morph triangle's point
    bool selectorSet = false;
};

namespace {

// Makes `ours` current for a scope, then the one before it again.
class ContextScope {
public:
    explicit ContextScope(void* ours) : before_(ImGui::GetCurrentContext()) {
        ImGui::SetCurrentContext(static_cast<ImGuiContext*>(ours));
    }
    ~ContextScope() { ImGui::SetCurrentContext(before_); }
    ContextScope(const ContextScope&) = delete;
    ContextScope& operator=(const ContextScope&) = delete;

private:
    ImGuiContext* before_;
};

}  // namespace

HandPanelUi::HandPanelUi() : gl_(std::make_unique<Gl>()) {
    glBindTexture(GL_TEXTURE_2D, gl_->texture.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kPanelPixelsX, kPanelPixelsY, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenerateMipmap(GL_TEXTURE_2D);
    // Mipmapped: seen from arm's length the text is smaller than its pixels.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, gl_->fbo.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, gl_->texture.get(), 0);
    const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!complete) throw garden::GlError("the hand panel's texture cannot be drawn into");

    glBindVertexArray(gl_->vao.get());
    glBindBuffer(GL_ARRAY_BUFFER, gl_->vertices.get());
    glBufferData(GL_ARRAY_BUFFER, 4 * 5 * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glBindVertexArray(0);

    // A context of its own: the mirror's overlay keeps its windows, fonts
    // and mouse; ours has no platform backend, the board is its screen.
    ImGuiContext* before = ImGui::GetCurrentContext();
    ImGuiContext* ours = ImGui::CreateContext();
    context_ = ours;
    ImGui::SetCurrentContext(ours);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(static_cast<float>(kPanelPixelsX), static_cast<float>(kPanelPixelsY));
    ImGui::StyleColorsDark();
    ImGui::GetStyle().Colors[ImGuiCol_WindowBg] = ImVec4(0.12f, 0.10f, 0.20f, 1.0f);  // opaque: read on any sky
    const bool ok = ImGui_ImplOpenGL3_Init("#version 330 core");
    ImGui::SetCurrentContext(before);
    if (!ok) {
        ImGui::DestroyContext(ours);
        throw garden::GlError("ImGui OpenGL 3 backend failed to initialise for the hand panel");
    }
}

HandPanelUi::~HandPanelUi() {
    ImGuiContext* before = ImGui::GetCurrentContext();
    ImGui::SetCurrentContext(static_cast<ImGuiContext*>(context_));
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(static_cast<ImGuiContext*>(context_));
    ImGui::SetCurrentContext(before == context_ ? nullptr : before);
}

bool HandPanelUi::update(garden::GardenSession& session, const HandPanel& panel, const std::string& profile,
                         XrUserSettings& user, float dt) {
    ContextScope scope(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.DeltaTime = dt > 0.0f ? dt : 1.0f / 90.0f;
    const std::optional<glm::vec2> uv = panel.hovered();
    io.MousePos = uv ? ImVec2(uv->x * kPanelPixelsX, uv->y * kPanelPixelsY) : ImVec2(-FLT_MAX, -FLT_MAX);
    io.MouseDown[0] = panel.pressing();

    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(io.DisplaySize);
    ImGui::Begin("hand panel", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                            ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollWithMouse);
    garden::ToolSettings& t = session.tool();
    for (int i = 0; i < static_cast<int>(PanelButton::Count); ++i) {
        const auto b = static_cast<PanelButton>(i);
        const glm::vec2 p = buttonTopLeft(b);
        ImGui::SetCursorPos(ImVec2(p.x, p.y));
        const bool chosen = b < PanelButton::Undo && t.kind == toolOf(b);
        if (chosen) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyle().Colors[ImGuiCol_ButtonActive]);
        const bool pressed = ImGui::Button(kLabels[i], ImVec2(kButtonSize.x, kButtonSize.y));
        if (chosen) ImGui::PopStyleColor();
        if (!pressed) continue;
        if (b == PanelButton::Undo) session.undo();
        else if (b == PanelButton::Redo) session.redo();
        else t.kind = toolOf(b);
    }

    ImGui::SetCursorPos(ImVec2(kButtonInset, kBodyY));
    ImGui::BeginGroup();
    parameters(t);
    ImGui::EndGroup();

    ImGui::SetCursorPos(ImVec2(kMorphX, kBodyY));
    if (session.hasMorph()) {
        if (!gl_->selectorSet) {
            if (const auto& w = session.morphWeights())
                gl_->selector = garden::trianglePoint(glm::vec3(static_cast<float>(w->barycentric[0]), static_cast<float>(w->barycentric[1]),
                                                                static_cast<float>(w->barycentric[2])));
            gl_->selectorSet = true;
        }
        const garden::MorphSpec& m = *session.garden().morph;
        const char* labels[3] = {m.sources[0].c_str(), m.sources[1].c_str(), m.sources[2].c_str()};
        if (garden::morphTriangleWidget(labels, gl_->selector, kMorphSide)) {
            const glm::vec3 b = garden::triangleWeights(gl_->selector);
            session.setMorphBarycentric({b.x, b.y, b.z});
        }
    } else {
        ImGui::TextDisabled("no morph in this garden");
    }

    bool changed = false;
    ImGui::SetCursorPos(ImVec2(kButtonInset, kTogglesY));
    changed |= ImGui::Checkbox("left-handed", &user.leftHanded);
    ImGui::SetCursorPos(ImVec2(kButtonInset + kToggleStep, kTogglesY));
    changed |= ImGui::Checkbox("seated", &user.seated);

    ImGui::SetCursorPos(ImVec2(kButtonInset, kPanelPixelsY - kFontLine - 8.0f));
    ImGui::TextDisabled("%s", profile.empty() ? "no interaction profile yet" : profile.c_str());
    ImGui::End();
    ImGui::Render();

    GLint framebufferBefore = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebufferBefore);
    glBindFramebuffer(GL_FRAMEBUFFER, gl_->fbo.get());
    glViewport(0, 0, kPanelPixelsX, kPanelPixelsY);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebufferBefore));
    glBindTexture(GL_TEXTURE_2D, gl_->texture.get());
    glGenerateMipmap(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    return changed;
}

void HandPanelUi::draw(const HandPanel& panel, const glm::mat4& viewProjection) const {
    if (!panel.shown()) return;
    const std::array<glm::vec3, 4> c = panel.corners();
    // The texture's first row is the panel's top (ImGui's y grows down, GL
    // stores what it drew bottom row first): v = 1 at the top.
    const float uvs[4][2] = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
    float data[4][5];
    for (int i = 0; i < 4; ++i) {
        data[i][0] = c[static_cast<std::size_t>(i)].x;
        data[i][1] = c[static_cast<std::size_t>(i)].y;
        data[i][2] = c[static_cast<std::size_t>(i)].z;
        data[i][3] = uvs[i][0];
        data[i][4] = uvs[i][1];
    }
    glBindBuffer(GL_ARRAY_BUFFER, gl_->vertices.get());
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(data), data);
    gl_->program.use();
    glUniformMatrix4fv(gl_->program.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    glUniform1i(gl_->program.uniform("panel"), 0);
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

}  // namespace hg::xr
