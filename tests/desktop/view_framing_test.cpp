// Home frames the garden (garden/desktop/view_framing.h): from wherever the
// user got to, every sculpture's centre is in view afterwards, flying.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "../garden/session_garden.h"
#include "garden/desktop/view_framing.h"

namespace hg::garden {
namespace {

class ViewFraming : public test::SmallGardenSession {};

TEST_F(ViewFraming, EverySculptureIsInViewAfterHome) {
    session->navigator().setMode(NavigationMode::Fly);
    session->navigator().setPose({40.0f, 3.0f, -30.0f}, 2.0f, 0.4f);  // lost, looking away
    const float fovY = static_cast<float>(session->settings().fovY), aspect = 16.0f / 9.0f;
    frameGarden(*session, fovY, aspect);
    EXPECT_EQ(session->navigator().mode(), NavigationMode::Fly);
    const glm::mat4 clip = glm::perspective(fovY, aspect, 0.05f, 500.0f) * session->view();
    for (const Sculpture& s : session->sculptures()) {
        const glm::vec4 p = clip * glm::vec4(s.worldCentre(), 1.0f);
        ASSERT_GT(p.w, 0.0f) << s.name << " is behind the eye";
        EXPECT_LT(std::abs(p.x / p.w), 0.95f) << s.name;
        EXPECT_LT(std::abs(p.y / p.w), 0.95f) << s.name;
    }
    // Looking the way the garden's start looks (-z), down at it.
    EXPECT_NEAR(session->navigator().yaw(), 0.0f, 1e-5);
    EXPECT_LT(session->navigator().pitch(), 0.0f);
    // The same garden framed in a narrow window steps back farther.
    const FramedView wide = gardenFraming(*session, fovY, aspect), narrow = gardenFraming(*session, fovY, 0.5f);
    EXPECT_GT(narrow.eye.z, wide.eye.z);
}

}  // namespace
}  // namespace hg::garden
