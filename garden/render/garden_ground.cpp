#include "garden/render/garden_ground.h"

#include <algorithm>

namespace hg::garden {

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
