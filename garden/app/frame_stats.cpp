#include "garden/app/frame_stats.h"

namespace hg::garden {

const char* stageName(Stage s) {
    switch (s) {
        case Stage::Input: return "input";
        case Stage::Lod: return "lod";
        case Stage::Morph: return "morph";
        case Stage::Remesh: return "remesh";
        case Stage::Upload: return "upload";
        case Stage::Render: return "render";
        case Stage::Count: break;
    }
    return "?";
}

void FrameHistory::push(const FrameStats& s) {
    if (frames_.size() == capacity_) frames_.erase(frames_.begin());
    frames_.push_back(s);
}

}  // namespace hg::garden
