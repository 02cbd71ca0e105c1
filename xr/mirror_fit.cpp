#include "xr/mirror_fit.h"

#include <cmath>

namespace hg::xr {

MirrorRect fitMirror(glm::ivec2 image, glm::ivec2 window) {
    MirrorRect r;
    if (image.x <= 0 || image.y <= 0 || window.x <= 0 || window.y <= 0) return r;
    // Compare the aspects in integers, so an image of the window's aspect fills it exactly.
    const long long wide = static_cast<long long>(image.x) * window.y, tall = static_cast<long long>(image.y) * window.x;
    if (wide >= tall) {  // as wide as the window, bars above and below
        r.size = {window.x, static_cast<int>(std::lround(static_cast<double>(window.x) * image.y / image.x))};
    } else {  // as tall as the window, bars left and right
        r.size = {static_cast<int>(std::lround(static_cast<double>(window.y) * image.x / image.y)), window.y};
    }
    r.offset = (window - r.size) / 2;
    return r;
}

}  // namespace hg::xr
