// Where the mirror window shows an eye's image: as large as fits, its
// aspect kept, centred (bars on the other sides). Eyes need not be square
// (Monado's simulated headset under its main compositor: 640 x 720 per
// eye). Pure math.
#pragma once

#include <glm/vec2.hpp>

namespace hg::xr {

struct MirrorRect {
    glm::ivec2 offset{0};  // from the window's lower left corner, pixels
    glm::ivec2 size{0};
};

// `image` and `window` in pixels; an empty image or window gives an empty rectangle.
MirrorRect fitMirror(glm::ivec2 image, glm::ivec2 window);

}  // namespace hg::xr
