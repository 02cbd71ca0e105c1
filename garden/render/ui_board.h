// A board of Dear ImGui widgets standing in the world (the headset's hand
// panel, xr/hand_panel_ui.h): an ImGui context of its own whose screen is
// a texture of fixed pixels, and a quad that puts the texture in a view.
// The texture is drawn again only when what ImGui would draw changed (on a
// software rasterizer drawing and mipmapping it is a cost most frames need
// not pay), and mipmapped: seen from arm's length the text is smaller than
// its pixels. The board is drawn over the picture, not depth tested, so it
// is never hidden by a sculpture.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace hg::garden {

class UiBoard {
public:
    // Needs the current GL context (3.3 core); throws GlError when the
    // texture cannot be drawn into or ImGui's OpenGL backend fails. The
    // ImGui context current before stays current.
    UiBoard(int widthPixels, int heightPixels);
    ~UiBoard();
    UiBoard(const UiBoard&) = delete;
    UiBoard& operator=(const UiBoard&) = delete;

    // Makes the board's ImGui context current for a scope (to set its
    // style, or around newFrame ... render), then the one before again.
    class Current {
    public:
        explicit Current(const UiBoard& board);
        ~Current();
        Current(const Current&) = delete;
        Current& operator=(const Current&) = delete;

    private:
        void* before_;  // ImGuiContext
    };

    // With the board current: starts an ImGui frame whose mouse is at
    // `mousePixels` (from the board's top left; none: off the board).
    void newFrame(const std::optional<glm::vec2>& mousePixels, bool mouseDown, float dt);
    // With the board current: ends the frame and brings the texture up to
    // date (the framebuffer and viewport before stay). True when the
    // texture was drawn again, false when the picture was the same.
    bool render();

    // The texture on a quad (corners top left, top right, bottom right,
    // bottom left), over whatever framebuffer is bound.
    void draw(const std::array<glm::vec3, 4>& corners, const glm::mat4& viewProjection) const;

private:
    struct Gl;
    std::unique_ptr<Gl> gl_;
    void* context_ = nullptr;  // ImGuiContext
    int width_, height_;
};

}  // namespace hg::garden
