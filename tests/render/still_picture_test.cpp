// A still view (garden/render/still_picture.h, docs/rendering.md "A still
// view"): composited from the picture held while nothing in it changes,
// with the very pixels a drawn view gives; drawn again as soon as anything
// in it changes; and sharpened to the still quality after a few views held.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdint>
#include <vector>

#include "garden/render/shapes.h"
#include "garden/render/still_picture.h"
#include "gl_fixture.h"

namespace hg::garden::test {
namespace {

const RenderMaterial kRed{{0.9f, 0.1f, 0.1f}, 0.2f, 32.0f};

glm::mat4 at(const glm::vec3& p, float scale = 1.0f) {
    return glm::scale(glm::translate(glm::mat4(1.0f), p), glm::vec3(scale));
}

// The policy alone: drawn, kept, sharpened once the view has been held
// long enough, to each still quality in turn, kept at the last; drawn
// again when the quality asked for changes or the view does.
TEST(StillPicturePolicy, DrawsKeepsSharpensInTurnAndDrawsAgain) {
    StillPicture still;
    RenderQuality moving;
    moving.renderScale = 0.5f;
    RenderQuality sharp = moving;
    sharp.renderScale = 1.0f;
    RenderQuality sharper = sharp;
    sharper.msaaSamples = 8;
    const std::vector<RenderQuality> stills{sharp, sharper};
    const auto kind = [&](bool same, const RenderQuality& q, const std::vector<RenderQuality>& s) {
        return still.step(same, q, s).kind;
    };
    EXPECT_EQ(kind(true, moving, stills), PictureStep::Draw) << "nothing held yet";
    still.drawn(moving, {});
    EXPECT_EQ(kind(false, moving, stills), PictureStep::Draw) << "the view changed";
    still.drawn(moving, {});
    for (int i = 1; i < StillPicture::kViewsBeforeSharpening; ++i) EXPECT_EQ(kind(true, moving, stills), PictureStep::Keep);
    PictureStep step = still.step(true, moving, stills);
    EXPECT_EQ(step.kind, PictureStep::Sharpen) << "held long enough";
    EXPECT_EQ(step.still, 0u) << "to the first still quality";
    still.drawn(sharp, {});
    for (int i = 1; i < StillPicture::kViewsBetweenSharpenings; ++i) EXPECT_EQ(kind(true, moving, stills), PictureStep::Keep);
    step = still.step(true, moving, stills);
    EXPECT_EQ(step.kind, PictureStep::Sharpen);
    EXPECT_EQ(step.still, 1u) << "then to the next";
    still.drawn(sharper, {});
    for (int i = 0; i < 40; ++i) EXPECT_EQ(kind(true, moving, stills), PictureStep::Keep) << "the last: held";
    EXPECT_TRUE(sameQuality(still.quality(), sharper));
    EXPECT_EQ(kind(false, moving, stills), PictureStep::Draw);
    still.drawn(moving, {});

    RenderQuality other = moving;
    other.msaaSamples = 2;
    EXPECT_EQ(kind(true, other, {}), PictureStep::Draw) << "held at neither quality asked for";
    still.drawn(other, {});
    for (int i = 0; i < 40; ++i) EXPECT_EQ(kind(true, other, {}), PictureStep::Keep) << "no still quality: never sharpened";
    EXPECT_EQ(kind(true, other, {other}), PictureStep::Keep) << "held at the still quality already";
}

class StillPictureTest : public GlTest {
protected:
    struct Scene {
        glm::vec3 eye{0.0f, 3.0f, 6.0f};
        glm::vec3 centre{0.0f, 1.0f, 0.0f};
        glm::vec3 light{1.0f};
        GroundStyle ground;
        bool line = false;  // a line from behind the sphere to in front of it
    };

    // One frame of `s`; its stats, its pixels in color_.
    RenderStats frame(const Scene& s) {
        target_->bind();
        View view = makeView(s.eye, {0.0f, 0.8f, 0.0f}, {0.4f, 1.0f, 0.3f});
        view.lights.front().color = s.light;
        renderer_->beginFrame(view);
        renderer_->drawGround(s.ground);
        renderer_->drawChunk(1, at(s.centre, 0.6f), kRed);
        if (s.line) renderer_->drawLines({s.centre + glm::vec3(-1.5f, 0, -1.5f), s.centre + glm::vec3(1.5f, 0, 1.5f)},
                                         {1.0f, 1.0f, 0.0f, 1.0f});
        const RenderStats stats = renderer_->endFrame();
        read();
        return stats;
    }

    // The pixels of `s` drawn from scratch: reuse off, then back on (which
    // forgets what was held, so the next frame is drawn).
    std::vector<std::uint8_t> drawn(const Scene& s) {
        renderer_->setPictureReuse(false);
        frame(s);
        renderer_->setPictureReuse(true);
        return color_;
    }
};

// Held, the view gives the pixels and depth a drawn one does, lines drawn
// over it included, and reports no GPU time; each change in what it shows
// (the camera, a sculpture moved, a light, the ground, a chunk's new mesh
// in the same place of the arena, the quality) draws it again.
TEST_F(StillPictureTest, AStillViewIsCompositedFromThePictureHeldUntilAnythingInItChanges) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    RenderQuality quality;  // shadows and occlusion on: their images are held too
    quality.msaaSamples = 2;
    renderer_->setQuality(quality);
    EXPECT_FALSE(renderer_->pictureReuse()) << "off by default";
    renderer_->setPictureReuse(true);

    Scene scene;
    scene.line = true;
    RenderStats s = frame(scene);
    EXPECT_EQ(s.picturesKept, 0u);
    const std::vector<std::uint8_t> first = color_;
    const std::vector<float> firstDepth = depth_;
    for (int i = 0; i < 4; ++i) {
        s = frame(scene);
        EXPECT_EQ(s.picturesKept, 1u) << "still, view " << i;
        EXPECT_EQ(s.picturesSharpened, 0u) << "no still quality set";
        EXPECT_LT(s.gpuMs(), 0.0f) << "a held view reports no GPU time";
        EXPECT_EQ(color_, first) << "the held picture, lines over it";
        EXPECT_EQ(depth_, firstDepth);
    }
    EXPECT_EQ(drawn(scene), first) << "as drawn";

    const auto drawnAgain = [&](const Scene& changed, const char* what) {
        const RenderStats c = frame(changed);
        EXPECT_EQ(c.picturesKept, 0u) << what;
        const std::vector<std::uint8_t> picture = color_;
        EXPECT_NE(picture, first) << what;
        EXPECT_EQ(drawn(changed), picture) << what << ": the pixels of a view drawn from scratch";
        frame(changed);  // held from here
        EXPECT_EQ(frame(changed).picturesKept, 1u) << what;
        EXPECT_EQ(color_, picture) << what;
        frame(scene);  // back: drawn, then held
    };
    Scene moved = scene;
    moved.eye.x += 0.01f;
    drawnAgain(moved, "the eye moved 1 cm");
    moved = scene;
    moved.centre.x += 0.2f;
    drawnAgain(moved, "the sculpture moved");
    moved = scene;
    moved.light = glm::vec3(0.6f);
    drawnAgain(moved, "the sun dimmed");
    moved = scene;
    moved.ground.color = {0.5f, 0.3f, 0.2f};
    drawnAgain(moved, "the ground's colour");

    // A new mesh for the chunk in the same place of the arena: the same draws.
    poly::Mesh flattened = uvSphereMesh(1.0f, 48, 24);
    for (std::size_t i = 1; i < flattened.positions.size(); i += 3) flattened.positions[i] *= 0.5f;
    const std::size_t firstVertex = renderer_->arena().slot(1)->firstVertex;
    renderer_->upload(1, 2, flattened);
    ASSERT_EQ(renderer_->arena().slot(1)->firstVertex, firstVertex);
    s = frame(scene);
    EXPECT_EQ(s.picturesKept, 0u) << "the chunk's mesh changed";
    EXPECT_NE(color_, first);
    const std::vector<std::uint8_t> flatter = color_;
    EXPECT_EQ(drawn(scene), flatter);
    frame(scene);

    quality.exposure = 1.5f;
    renderer_->setQuality(quality);
    s = frame(scene);
    EXPECT_EQ(s.picturesKept, 0u) << "another quality";
    EXPECT_NE(color_, flatter);
    EXPECT_EQ(frame(scene).picturesKept, 1u);
}

// The automatic mode's moving quality (half size, no multisampling)
// sharpens after a few views held to the first still quality (full size,
// 4x), then after more to the second (shadows and occlusion too): each
// time the pixels of that quality drawn directly, then held; moving again
// draws at the moving quality at once. A sharpened view's GPU time is not
// reported as the moving quality's.
TEST_F(StillPictureTest, AStillViewSharpensToEachStillQualityInTurnAndMovingDrawsAtTheQualitySet) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    RenderQuality moving = plainQuality();
    moving.renderScale = 0.5f;
    RenderQuality sharp = plainQuality();
    sharp.msaaSamples = 4;
    RenderQuality sharper = sharp;
    sharper.shadows = true;
    sharper.ambientOcclusion = true;
    Scene scene;
    Scene walked = scene;
    walked.eye.z -= 0.5f;

    renderer_->setQuality(sharp);
    const std::vector<std::uint8_t> sharpPicture = drawn(scene);
    renderer_->setQuality(sharper);
    const std::vector<std::uint8_t> sharperPicture = drawn(scene);
    renderer_->setQuality(moving);
    const std::vector<std::uint8_t> movingPicture = drawn(scene), walkedPicture = drawn(walked);
    ASSERT_NE(sharpPicture, movingPicture) << "the qualities differ in pixels";
    ASSERT_NE(sharperPicture, sharpPicture);

    renderer_->setPictureReuse(true);
    renderer_->setStillQualities({sharp, sharper});
    EXPECT_EQ(frame(scene).picturesKept, 0u);
    EXPECT_EQ(color_, movingPicture);
    // Held `views` views, then sharpened to `picture`.
    const auto heldThenSharpened = [&](int views, const std::vector<std::uint8_t>& held,
                                       const std::vector<std::uint8_t>& picture, const char* what) {
        for (int i = 1; i < views; ++i) {
            EXPECT_EQ(frame(scene).picturesKept, 1u) << what;
            EXPECT_EQ(color_, held) << what << ": held first";
        }
        const RenderStats s = frame(scene);
        EXPECT_EQ(s.picturesSharpened, 1u) << what;
        EXPECT_EQ(s.picturesKept, 0u) << what;
        EXPECT_LT(s.gpuMs(), 0.0f) << what << ": not the moving quality's time";
        EXPECT_EQ(color_, picture) << what << ": the still quality's pixels";
    };
    heldThenSharpened(StillPicture::kViewsBeforeSharpening, movingPicture, sharpPicture, "the first");
    heldThenSharpened(StillPicture::kViewsBetweenSharpenings, sharpPicture, sharperPicture, "the second");
    for (int i = 0; i < 2 * StillPicture::kViewsBetweenSharpenings; ++i) {
        const RenderStats s = frame(scene);
        EXPECT_EQ(s.picturesKept, 1u);
        EXPECT_EQ(s.picturesSharpened, 0u) << "the last still quality: held";
        EXPECT_EQ(color_, sharperPicture);
    }
    const RenderStats s = frame(walked);
    EXPECT_EQ(s.picturesKept + s.picturesSharpened, 0u);
    EXPECT_EQ(color_, walkedPicture) << "moving: drawn at the quality set";
    EXPECT_TRUE(sameQuality(renderer_->quality(), moving)) << "the quality set is the caller's, untouched";
}

}  // namespace
}  // namespace hg::garden::test
