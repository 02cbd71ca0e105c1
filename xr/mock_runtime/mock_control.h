// What the mock OpenXR runtime (libhg_mock_openxr.so) offers tests besides
// the OpenXR API: C functions a test finds with dlsym in the library the
// loader opened (dlopen with RTLD_NOLOAD), and environment variables a
// test sets before xrCreateInstance (docs/xr.md):
//
//   HG_MOCK_XR_SCRIPT    a replay script (docs/replay-format.md): its tool
//                        hand is the right controller, its navigation hand
//                        the left, frame by frame from the first focused
//                        xrSyncActions; its commands are ignored here
//   HG_MOCK_XR_EVENTS    "FRAME:EVENT,..." session changes raised at a
//                        frame (xrWaitFrame count): loss, exit, unfocus,
//                        focus, instance_loss
//   HG_MOCK_XR_CONTROL   a file polled at every xrPollEvent: each line an
//                        EVENT as above, raised now (the file is removed)
//   HG_MOCK_XR_READBACK  a folder: frames.json (every submitted frame's
//                        layers, rewritten at each xrEndFrame) and, when the
//                        session ends, left.png and right.png (the last
//                        released colour images)
//   HG_MOCK_XR_NO_STAGE  set: only VIEW and LOCAL spaces are offered
#pragma once

#include <cstdint>

extern "C" {

struct HgMockXrFrameInfo {
    std::uint64_t framesEnded;        // xrEndFrame calls that succeeded
    std::uint64_t framesWithTwoViews; // ... whose projection layer had two views
    std::uint32_t layerCount;         // layers of the last frame
    std::uint32_t viewCount;          // views of its projection layer (0: none)
    std::uint32_t depthViews;         // views carrying XrCompositionLayerDepthInfoKHR
    std::uint32_t imageWidth, imageHeight;  // the left view's sub-image
    std::int32_t sessionState;        // XrSessionState now
    std::uint64_t hapticPulses;       // xrApplyHapticFeedback calls
};

// Raises a session change now, as HG_MOCK_XR_CONTROL does: "loss", "exit",
// "unfocus", "focus" or "instance_loss". 0 on success, -1 for an unknown name.
int hgMockXrRaise(const char* event);
void hgMockXrFrameInfo(HgMockXrFrameInfo* out);

typedef int (*PFN_hgMockXrRaise)(const char*);
typedef void (*PFN_hgMockXrFrameInfo)(HgMockXrFrameInfo*);

}  // extern "C"
