#include "garden/render/garden_ground.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

namespace hg::garden {

glm::mat4 gardenProjection(float fovY, glm::ivec2 size) {
    return glm::perspective(fovY, static_cast<float>(size.x) / static_cast<float>(std::max(size.y, 1)), kGardenNearPlane,
                            kGardenFarPlane);
}

GroundStyle gardenGround(const glm::vec3& lawnColor, const glm::vec2& gardenSize) {
    GroundStyle ground;
    ground.color = lawnColor;
    ground.lineColor = lawnColor * 0.88f;  // faint: scale, not a tiled floor
    ground.gardenHalfExtent = 0.5f * gardenSize;
    ground.halfExtent = std::max(kGardenFarPlane, std::max(ground.gardenHalfExtent.x, ground.gardenHalfExtent.y));
    ground.gridReach = kGardenGridReach;
    ground.stripeWidth = kGardenStripeWidth;
    return ground;
}

}  // namespace hg::garden
