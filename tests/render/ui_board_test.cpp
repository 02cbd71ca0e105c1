// The headset's board of ImGui widgets (garden/render/ui_board.h) on a real
// GL context: its picture lands on the quad the right way up and over
// whatever is nearer (never depth tested), the texture is drawn again only
// when the picture changed (keeping the frame buffer and viewport), the
// mouse in board pixels presses a button, and the ImGui context that was
// current stays current.
#include "gl_fixture.h"

#include <imgui.h>

#include <array>
#include <optional>

#include "garden/render/ui_board.h"

namespace hg::garden {
namespace {

constexpr int kBoard = 64;

class UiBoardTest : public test::GlTest {
protected:
    // One frame whose picture is `top` over the board's upper half and
    // `bottom` over its lower half; whether the texture was drawn again.
    static bool paint(UiBoard& board, ImU32 top, ImU32 bottom) {
        UiBoard::Current current(board);
        board.newFrame(std::nullopt, false, 1.0f / 60.0f);
        ImDrawList* list = ImGui::GetBackgroundDrawList();
        list->AddRectFilled(ImVec2(0, 0), ImVec2(kBoard, kBoard / 2), top);
        list->AddRectFilled(ImVec2(0, kBoard / 2), ImVec2(kBoard, kBoard), bottom);
        return board.render();
    }

    // The board over the middle of the target (clip space, no camera),
    // after clearing to blue with the nearest depth, so that a depth-tested
    // quad would draw nothing.
    void show(const UiBoard& board) {
        target_->bind();
        glEnable(GL_DEPTH_TEST);
        glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
        glClearDepth(0.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glClearDepth(1.0);
        const std::array<glm::vec3, 4> corners = {glm::vec3(-0.5f, 0.5f, 0.0f), glm::vec3(0.5f, 0.5f, 0.0f),
                                                  glm::vec3(0.5f, -0.5f, 0.0f), glm::vec3(-0.5f, -0.5f, 0.0f)};
        board.draw(corners, glm::mat4(1.0f));
        read();
    }
};

constexpr ImU32 kRed = IM_COL32(255, 0, 0, 255), kGreen = IM_COL32(0, 255, 0, 255);

TEST_F(UiBoardTest, ShowsItsPictureTheRightWayUpOverWhateverIsNearer) {
    UiBoard board(kBoard, kBoard);
    paint(board, kRed, kGreen);
    show(board);
    // The quad spans rows 64..192 (top-down): its upper half red, lower green.
    EXPECT_TRUE(test::reddish(pixel(128, 96))) << "the board's top is not at the quad's top";
    EXPECT_TRUE(test::greenish(pixel(128, 160)));
    const test::Rgba outside = pixel(20, 20);
    EXPECT_GT(outside.b, 200) << "the board drew outside its quad";
    EXPECT_LT(outside.r, 20);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(UiBoardTest, DrawingTheTextureKeepsTheFramebufferAndViewport) {
    UiBoard board(kBoard, kBoard);
    target_->bind();
    glViewport(3, 5, 70, 90);
    GLint before = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &before);
    ASSERT_TRUE(paint(board, kRed, kGreen));
    GLint after = 0, viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &after);
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(after, before);
    EXPECT_EQ(viewport[0], 3);
    EXPECT_EQ(viewport[1], 5);
    EXPECT_EQ(viewport[2], 70);
    EXPECT_EQ(viewport[3], 90);
}

TEST_F(UiBoardTest, DrawsItsTextureAgainOnlyWhenThePictureChanged) {
    UiBoard board(kBoard, kBoard);
    EXPECT_TRUE(paint(board, kRed, kRed)) << "the first picture is always drawn";
    EXPECT_FALSE(paint(board, kRed, kRed)) << "the same picture was drawn again";
    EXPECT_TRUE(paint(board, kGreen, kGreen)) << "a new picture was not drawn";
    show(board);
    EXPECT_TRUE(test::greenish(pixel(128, 96)));
    EXPECT_TRUE(test::greenish(pixel(128, 160)));
}

TEST_F(UiBoardTest, TheMouseInBoardPixelsPressesAButton) {
    UiBoard board(kBoard, kBoard);
    // A frame with a button over the board's middle; whether it was pressed.
    auto frame = [&board](std::optional<glm::vec2> mouse, bool down) {
        UiBoard::Current current(board);
        board.newFrame(mouse, down, 1.0f / 60.0f);
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(kBoard, kBoard));
        ImGui::Begin("board", nullptr, ImGuiWindowFlags_NoDecoration);
        ImGui::SetCursorPos(ImVec2(16, 16));
        const bool pressed = ImGui::Button("go", ImVec2(32, 32));
        ImGui::End();
        board.render();
        return pressed;
    };
    const glm::vec2 onButton(32.0f, 32.0f), offButton(4.0f, 60.0f);
    frame(offButton, false);
    frame(offButton, true);
    EXPECT_FALSE(frame(offButton, false)) << "a click beside the button pressed it";
    frame(std::nullopt, true);
    EXPECT_FALSE(frame(std::nullopt, false)) << "a click off the board pressed the button";
    frame(onButton, false);
    frame(onButton, true);
    EXPECT_TRUE(frame(onButton, false)) << "a click on the button did not press it";
}

TEST_F(UiBoardTest, TheImGuiContextThatWasCurrentStaysCurrent) {
    ImGuiContext* window = ImGui::CreateContext();
    {
        UiBoard board(kBoard, kBoard);
        EXPECT_EQ(ImGui::GetCurrentContext(), window);
        {
            UiBoard::Current current(board);
            EXPECT_NE(ImGui::GetCurrentContext(), window);
        }
        EXPECT_EQ(ImGui::GetCurrentContext(), window);
    }
    EXPECT_EQ(ImGui::GetCurrentContext(), window);
    ImGui::DestroyContext(window);
}

}  // namespace
}  // namespace hg::garden
