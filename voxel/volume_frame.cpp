#include "voxel/volume_frame.h"

#include <cmath>
#include <sstream>

namespace hg::voxel {

int VolumeFrame::indexOf(int axis, double model) const {
    return static_cast<int>(std::lround((model - modelBox.lo[axis]) / voxelSize));
}

std::string checkResolutionAndBand(int resolution, float band) {
    std::ostringstream why;
    if (resolution < kMinResolution || resolution > kMaxResolution) {
        why << "resolution " << resolution << " is out of range: give " << kMinResolution << " to "
            << kMaxResolution << " voxels along the longest side";
        return why.str();
    }
    if (!(band >= kMinBand && band <= kMaxBand)) {
        why << "band " << band << " is out of range: give " << kMinBand << " to " << kMaxBand << " voxels";
        return why.str();
    }
    return "";
}

std::string makeFrame(const frep::Box3& box, int resolution, float band, VolumeFrame& frame) {
    if (std::string why = checkResolutionAndBand(resolution, band); !why.empty()) return why;
    std::ostringstream why;
    double longest = 0.0;
    for (int a = 0; a < 3; ++a) {
        double e = box.hi[a] - box.lo[a];
        if (!std::isfinite(box.lo[a]) || !std::isfinite(box.hi[a]) || !(e >= 0.0)) {
            why << "the model box is empty or not finite on axis " << "xyz"[a];
            return why.str();
        }
        longest = std::max(longest, e);
    }
    if (!(longest > 0.0)) return "the model box has no extent";
    frame.modelBox = box;
    frame.resolution = resolution;
    frame.voxelSize = longest / resolution;
    frame.band = band;
    const int pad = static_cast<int>(std::ceil(band)) + 1;
    for (int a = 0; a < 3; ++a) {
        int cells = static_cast<int>(std::ceil((box.hi[a] - box.lo[a]) / frame.voxelSize - 1e-9));
        frame.indexBox.lo[a] = -pad;
        frame.indexBox.hi[a] = std::max(cells, 0) + pad;
    }
    return "";
}

}  // namespace hg::voxel
