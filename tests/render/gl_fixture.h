// Real GL contexts for the renderer tests: a hidden GLFW window (GL 3.3
// core, Mesa llvmpipe under Xvfb) with an offscreen target to render into
// and read back. Without DISPLAY the tests skip with the reason, unless
// HG_REQUIRE_GL=1 says this run must exercise GL (CI), where they fail.
#pragma once

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "garden/render/gl_context.h"
#include "garden/render/offscreen_target.h"
#include "garden/render/renderer.h"

namespace hg::garden::test {

constexpr double kPi = 3.14159265358979323846;

inline bool displayAvailable() {
    const char* display = std::getenv("DISPLAY");
    return display && *display;
}

inline bool glRequired() {
    const char* require = std::getenv("HG_REQUIRE_GL");
    return require && std::string(require) == "1";
}

// Use as the first statement of SetUp or a test body.
#define HG_REQUIRE_DISPLAY()                                                                           \
    do {                                                                                               \
        if (!::hg::garden::test::displayAvailable()) {                                                 \
            if (::hg::garden::test::glRequired()) FAIL() << "no X display: run under xvfb-run -a "     \
                                                            "(HG_REQUIRE_GL=1 forbids skipping)";      \
            GTEST_SKIP() << "no X display: run under xvfb-run -a";                                     \
        }                                                                                              \
    } while (0)

struct Rgba {
    int r, g, b, a;
    int sum() const { return r + g + b; }
};

// A camera, an image and a renderer; helpers to read what was drawn.
class GlTest : public ::testing::Test {
protected:
    static constexpr int kWidth = 256;
    static constexpr int kHeight = 256;
    static constexpr float kFovY = 45.0f;  // degrees
    static constexpr float kNear = 0.05f;
    static constexpr float kFar = 200.0f;

    void SetUp() override {
        HG_REQUIRE_DISPLAY();
        WindowOptions options;
        options.width = kWidth;
        options.height = kHeight;
        options.title = "hg_render_tests";
        options.visible = false;
        options.vsync = false;
        window_ = std::make_unique<GlWindow>(options);
        target_ = std::make_unique<OffscreenTarget>(kWidth, kHeight);
        renderer_ = std::make_unique<Renderer>();
        ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }

    void TearDown() override {
        // GL objects go while their context is still current.
        renderer_.reset();
        target_.reset();
        window_.reset();
    }

    // Looking from `eye` at `at`, y up; one white light from `lightDir`.
    View makeView(const glm::vec3& eye, const glm::vec3& at, const glm::vec3& lightDir = {0.3f, 1.0f, 0.6f}) const {
        View v;
        v.view = glm::lookAt(eye, at, glm::vec3(0, 1, 0));
        v.projection = glm::perspective(glm::radians(kFovY), float(kWidth) / float(kHeight), kNear, kFar);
        v.eye = eye;
        v.viewport = {kWidth, kHeight};
        v.clearColor = {0.2f, 0.3f, 0.8f, 1.0f};
        v.lights = {DirectionalLight{lightDir, glm::vec3(1.0f)}};
        v.ambient = glm::vec3(0.2f);
        return v;
    }

    void read() {
        color_ = target_->readColor();
        depth_ = target_->readDepth();
    }

    Rgba pixel(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 4;
        return {color_[i], color_[i + 1], color_[i + 2], color_[i + 3]};
    }
    float depth(int x, int y) const { return depth_[static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)]; }

    int count(const std::function<bool(const Rgba&)>& is) const {
        int n = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) n += is(pixel(x, y)) ? 1 : 0;
        return n;
    }

    // Eye distance along the view axis from a window depth value.
    static double eyeDepth(float windowDepth) {
        const double ndc = 2.0 * windowDepth - 1.0;
        return 2.0 * kNear * kFar / (kFar + kNear - ndc * (kFar - kNear));
    }

    // The world ray through the centre of pixel (x, y) (rows top-down).
    glm::vec3 rayDirection(const View& v, int x, int y) const {
        const glm::vec4 viewport(0, 0, kWidth, kHeight);
        const glm::vec3 win(float(x) + 0.5f, float(kHeight - 1 - y) + 0.5f, 1.0f);
        const glm::vec3 far = glm::unProject(win, v.view, v.projection, viewport);
        return glm::normalize(far - v.eye);
    }

    // The pixel (x, y, rows top-down) where world point p lands.
    glm::ivec2 worldToPixel(const View& v, const glm::vec3& p) const {
        const glm::vec3 win = glm::project(p, v.view, v.projection, glm::vec4(0, 0, kWidth, kHeight));
        return {static_cast<int>(win.x), kHeight - 1 - static_cast<int>(win.y)};
    }

    // Projected radius in pixels of a sphere of radius r at distance d on
    // the view axis: its outline is the circle where the cone from the eye
    // touches it, of half-angle asin(r / d).
    static double discRadiusPixels(double r, double d) {
        const double tanAlpha = r / std::sqrt(d * d - r * r);
        return tanAlpha / std::tan(0.5 * kFovY * kPi / 180.0) * (0.5 * kHeight);
    }

    std::unique_ptr<GlWindow> window_;
    std::unique_ptr<OffscreenTarget> target_;
    std::unique_ptr<Renderer> renderer_;
    std::vector<std::uint8_t> color_;
    std::vector<float> depth_;
};

// One sample per pixel, no shadows, no occlusion: each surface one shade
// where the light is even, for tests that compare colours.
inline RenderQuality plainQuality() {
    RenderQuality q;
    q.msaaSamples = 1;
    q.shadows = false;
    q.ambientOcclusion = false;
    return q;
}

// Mostly red, green, blue: one material colour against the others.
inline bool reddish(const Rgba& p) { return p.r > p.g + 40 && p.r > p.b + 40; }
inline bool greenish(const Rgba& p) { return p.g > p.r + 40 && p.g > p.b + 40; }

}  // namespace hg::garden::test
