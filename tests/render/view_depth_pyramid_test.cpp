// The ambient occlusion's depth pyramid (garden/render/view_depth_pyramid.h)
// read back: level 0 is each pixel's view z for perspective, asymmetric
// (headset) and orthographic projections, the sky is the far plane, and
// each coarser level holds real depths of the region below it, never a
// blend of two.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <vector>

#include "garden/render/render_targets.h"
#include "garden/render/view_depth_pyramid.h"
#include "gl_fixture.h"

namespace hg::garden::test {
namespace {

class ViewDepthPyramidTest : public GlTest {
protected:
    // The scene's depth cleared to `left` on the left half and `right` on
    // the right (window depths), with 4 samples a pixel as the high preset.
    void fillDepth(float left, float right) {
        scene_.ensure({kWidth, kHeight}, 4);
        glBindFramebuffer(GL_FRAMEBUFFER, scene_.framebuffer());
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, kWidth / 2, kHeight);
        glClearDepth(left);
        glClear(GL_DEPTH_BUFFER_BIT);
        glScissor(kWidth / 2, 0, kWidth - kWidth / 2, kHeight);
        glClearDepth(right);
        glClear(GL_DEPTH_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        glClearDepth(1.0);
    }

    std::vector<float> level(int l) {
        const glm::ivec2 s = glm::max(pyramid_->size() >> l, glm::ivec2(1));
        std::vector<float> z(static_cast<std::size_t>(s.x) * static_cast<std::size_t>(s.y));
        glBindTexture(GL_TEXTURE_2D, pyramid_->texture());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glGetTexImage(GL_TEXTURE_2D, l, GL_RED, GL_FLOAT, z.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        return z;
    }

    // View z of window depth `d` through `p`, by the inverse projection.
    static float viewZ(const glm::mat4& p, float d) {
        const glm::vec4 v = glm::inverse(p) * glm::vec4(0.0f, 0.0f, 2.0f * d - 1.0f, 1.0f);
        return v.z / v.w;
    }

    void SetUp() override {
        GlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        pyramid_ = std::make_unique<ViewDepthPyramid>();
    }
    void TearDown() override {
        pyramid_.reset();
        scene_ = SceneTargets();
        GlTest::TearDown();
    }

    SceneTargets scene_;
    std::unique_ptr<ViewDepthPyramid> pyramid_;
};

TEST_F(ViewDepthPyramidTest, LevelZeroIsViewZForEveryKindOfProjection) {
    const glm::mat4 projections[] = {
        glm::perspective(glm::radians(kFovY), 1.0f, kNear, kFar),
        // A headset eye: wider to one side than the other.
        glm::frustum(-0.06f, 0.035f, -0.05f, 0.045f, 0.05f, 100.0f),
        glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.5f, 30.0f),
    };
    for (const glm::mat4& p : projections) {
        fillDepth(0.3f, 0.97f);
        pyramid_->build(scene_, p);
        ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        const std::vector<float> z = level(0);
        const float left = viewZ(p, 0.3f), right = viewZ(p, 0.97f);
        ASSERT_LT(left, 0.0f);
        ASSERT_LT(right, left);
        for (int y : {0, kHeight / 3, kHeight - 1}) {
            EXPECT_NEAR(z[y * kWidth + 5], left, 1e-3 * std::abs(left)) << y;
            EXPECT_NEAR(z[y * kWidth + kWidth - 5], right, 1e-3 * std::abs(right)) << y;
        }
        // The sky (depth 1) is the far plane.
        fillDepth(1.0f, 1.0f);
        pyramid_->build(scene_, p);
        EXPECT_NEAR(level(0)[kWidth * kHeight / 2], viewZ(p, 1.0f), 1e-3 * std::abs(viewZ(p, 1.0f)));
    }
}

TEST_F(ViewDepthPyramidTest, CoarserLevelsKeepRealDepthsOfTheirRegion) {
    const glm::mat4 p = glm::perspective(glm::radians(kFovY), 1.0f, kNear, kFar);
    fillDepth(0.5f, 0.9f);
    pyramid_->build(scene_, p);
    const float left = viewZ(p, 0.5f), right = viewZ(p, 0.9f);
    for (int l = 1; l < ViewDepthPyramid::kLevels; ++l) {
        const std::vector<float> z = level(l);
        const int w = kWidth >> l, h = kHeight >> l;
        ASSERT_EQ(z.size(), static_cast<std::size_t>(w * h));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                // Each texel covers 2^l pixels a side, all on one half.
                const float want = x < w / 2 ? left : right;
                ASSERT_NEAR(z[y * w + x], want, 1e-3 * std::abs(want)) << "level " << l << " at " << x << "," << y;
            }
    }
}

}  // namespace
}  // namespace hg::garden::test
