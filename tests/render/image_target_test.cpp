// Drawing into textures someone else owns (garden/render/image_target.h),
// as the headset draws into its swapchain images: the colour lands in the
// given texture; the given depth texture is used, or a depth buffer of the
// target's own the size of the image; and the picture is shown scaled in a
// rectangle of another frame buffer with black around it (the mirror).
#include "gl_fixture.h"

#include <vector>

#include "garden/render/gl_objects.h"
#include "garden/render/image_target.h"

namespace hg::garden {
namespace {

constexpr int kW = 64, kH = 48;

class ImageTargetTest : public test::GlTest {
protected:
    static gl::Texture texture(GLint format, GLenum pixelFormat, GLenum type, int w, int h) {
        gl::Texture t = gl::Texture::create();
        glBindTexture(GL_TEXTURE_2D, t.get());
        glTexImage2D(GL_TEXTURE_2D, 0, format, w, h, 0, pixelFormat, type, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
        return t;
    }
    static GLint depthAttachment(GLenum what) {
        GLint v = 0;
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, what, &v);
        return v;
    }
    static GLenum depthAttachmentType() {
        return static_cast<GLenum>(depthAttachment(GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE));
    }
    static float depthAt(int x, int y) {
        float d = -1.0f;
        glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
        return d;
    }
};

TEST_F(ImageTargetTest, DrawsIntoTheGivenTextureWithADepthBufferOfItsOwn) {
    const gl::Texture color = texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, kW, kH);
    ImageTarget target;
    target.bind(color.get(), 0, {kW, kH});
    EXPECT_EQ(depthAttachmentType(), static_cast<GLenum>(GL_RENDERBUFFER));
    EXPECT_GE(depthAttachment(GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE), 24);
    glViewport(0, 0, kW, kH);
    glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
    glClearDepth(0.25);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glClearDepth(1.0);
    EXPECT_NEAR(depthAt(kW - 1, kH - 1), 0.25f, 1e-5f) << "no depth buffer the size of the image";

    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(kW * kH * 4));
    glBindTexture(GL_TEXTURE_2D, color.get());
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    int green = 0;
    for (std::size_t i = 0; i < pixels.size(); i += 4) green += pixels[i] == 0 && pixels[i + 1] == 255 ? 1 : 0;
    EXPECT_EQ(green, kW * kH) << "the clear did not land in the given texture";
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ImageTargetTest, UsesTheGivenDepthTextureAndFollowsTheImageSize) {
    const gl::Texture color = texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, kW, kH);
    const gl::Texture depth = texture(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, kW, kH);
    ImageTarget target;
    target.bind(color.get(), depth.get(), {kW, kH});
    EXPECT_EQ(depthAttachmentType(), static_cast<GLenum>(GL_TEXTURE));
    EXPECT_EQ(static_cast<GLuint>(depthAttachment(GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME)), depth.get());

    // Back to no depth texture, at another size: its own buffer, that size.
    const gl::Texture small = texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 32, 16);
    target.bind(small.get(), 0, {32, 16});
    ASSERT_EQ(depthAttachmentType(), static_cast<GLenum>(GL_RENDERBUFFER));
    GLint width = 0, height = 0;
    glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(depthAttachment(GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME)));
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &width);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_HEIGHT, &height);
    EXPECT_EQ(width, 32);
    EXPECT_EQ(height, 16);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ImageTargetTest, ShowsItsPictureScaledInARectangleWithBlackAround) {
    const gl::Texture color = texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, kW, kH);
    ImageTarget image;
    image.bind(color.get(), 0, {kW, kH});
    // Left half red, right half blue.
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, kW / 2, kH);
    glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(kW / 2, 0, kW / 2, kH);
    glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);

    target_->bind();
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    GLint window = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &window);
    // Twice the image's size, at (64, 80) from the bottom left.
    image.showIn(static_cast<GLuint>(window), {64, 80}, {2 * kW, 2 * kH});
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(window));
    read();
    // Rows are top-down: y from the bottom is row kHeight - 1 - y.
    const auto at = [this](int x, int y) { return pixel(x, kHeight - 1 - y); };
    EXPECT_TRUE(test::reddish(at(64 + kW / 2, 80 + kH))) << "the left half is not on the left";
    const test::Rgba right = at(64 + 3 * kW / 2, 80 + kH);
    EXPECT_GT(right.b, 200);
    EXPECT_LT(right.r, 40);
    for (const glm::ivec2& p : {glm::ivec2(10, 10), glm::ivec2(250, 250), glm::ivec2(60, 100), glm::ivec2(200, 100)})
        EXPECT_LT(at(p.x, p.y).sum(), 10) << "not black beside the picture at " << p.x << ", " << p.y;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace hg::garden
