// One headset through OpenXR (docs/design.md §8): the instance and the HMD system,
// the session on the GLFW window's GL context (XR_KHR_opengl_enable, Xlib
// binding), the stage space, a colour swapchain per eye (sRGB) and a depth
// swapchain per eye when XR_KHR_composition_layer_depth is offered, and the
// session's state machine:
//
//   IDLE -> READY (xrBeginSession) -> SYNCHRONIZED -> VISIBLE -> FOCUSED
//   -> ... -> STOPPING (xrEndSession) -> IDLE -> EXITING (done)
//   LOSS_PENDING or an instance loss: done, the session is gone.
//
// The frame: beginFrame (xrWaitFrame, xrBeginFrame, xrLocateViews), each
// eye's images acquired, drawn and released, endFrame (a projection layer
// with both views, depth attached when there is depth).
#pragma once

#include <openxr/openxr.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

struct GLFWwindow;

namespace hg::xr {

// The eye height the LOCAL space's origin is taken to be at, when neither
// a floor-level space (STAGE) is offered: metres above the floor.
constexpr float kStandingEyeHeight = 1.7f;

// No OpenXR runtime is installed or selected (XR_RUNTIME_JSON), or it
// would not start.
class NoRuntime : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct EyeImages {
    std::uint32_t color = 0;  // GL texture names in the app's context
    std::uint32_t depth = 0;  // 0: no depth swapchain
    int width = 0, height = 0;
};

struct HeadsetFrame {
    XrFrameState state{XR_TYPE_FRAME_STATE};
    std::array<XrView, 2> views{{{XR_TYPE_VIEW}, {XR_TYPE_VIEW}}};
    bool viewsValid = false;  // both views located this frame
};

class Headset {
public:
    // Creates the instance (with XR_KHR_opengl_enable, and the depth layer
    // extension when offered) and finds the HMD. Throws NoRuntime when the
    // loader finds no runtime, XrFailure for anything else.
    explicit Headset(const std::string& applicationName);
    ~Headset();
    Headset(const Headset&) = delete;
    Headset& operator=(const Headset&) = delete;

    // Creates the session on `window`'s context (current on this thread),
    // the reference space and the swapchains.
    void createSession(GLFWwindow* window);

    // Handles every queued event; the session's state follows. Returns true
    // when the interaction profile changed.
    bool pollEvents();
    XrSessionState state() const { return state_; }
    bool running() const { return running_; }  // between xrBeginSession and xrEndSession
    bool focused() const { return state_ == XR_SESSION_STATE_FOCUSED; }
    bool done() const { return done_; }        // EXITING, LOSS_PENDING or instance loss
    bool lost() const { return lost_; }
    const std::string& doneReason() const { return doneReason_; }
    void requestExit();

    HeadsetFrame beginFrame();
    EyeImages acquireEye(int eye);
    void releaseEye(int eye);
    // Submits the frame: both views when `rendered`, no layers otherwise.
    void endFrame(const HeadsetFrame& frame, bool rendered, float nearZ, float farZ);

    XrInstance instance() const { return instance_; }
    XrSession session() const { return session_; }
    XrSpace space() const { return space_; }  // the world's anchor: LOCAL_FLOOR, else STAGE, else LOCAL
    // Added to heights located in space() so that 0 is the floor (LOCAL: the
    // standing eye height).
    float floorOffset() const { return floorOffset_; }
    const char* spaceName() const;  // "LOCAL_FLOOR", "STAGE" or "LOCAL"
    bool depthSubmitted() const { return !depthSwapchains_.empty(); }
    // One eye's image size in pixels (after createSession; 0 before).
    std::array<int, 2> eyeSize() const {
        return colorSwapchains_.empty() ? std::array<int, 2>{0, 0}
                                        : std::array<int, 2>{colorSwapchains_[0].width, colorSwapchains_[0].height};
    }
    // The display's refresh rate (XR_FB_display_refresh_rate), Hz; 0 when
    // the runtime does not say. The predicted display period is not it:
    // Monado paces an app slower than the display to a multiple of it.
    float displayRefreshRate() const { return refreshRate_; }
    std::int64_t colorFormat() const { return colorFormat_; }
    std::string runtimeName() const;
    // OPAQUE when the headset offers it, else its first (a see-through
    // headset may offer only ADDITIVE, and refuses frames in another mode).
    XrEnvironmentBlendMode blendMode() const { return blendMode_; }

private:
    struct Swapchain {
        XrSwapchain handle = XR_NULL_HANDLE;
        std::vector<std::uint32_t> images;
        int width = 0, height = 0;
        std::uint32_t acquired = 0;
    };
    Swapchain makeSwapchain(std::int64_t format, int width, int height, XrSwapchainUsageFlags usage);
    void handleState(XrSessionState s);
    void destroySession();

    XrInstance instance_ = XR_NULL_HANDLE;
    XrSystemId system_ = XR_NULL_SYSTEM_ID;
    XrSession session_ = XR_NULL_HANDLE;
    XrSpace space_ = XR_NULL_HANDLE;
    bool depthExtension_ = false;
    bool refreshRateExtension_ = false;
    XrEnvironmentBlendMode blendMode_ = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    float refreshRate_ = 0.0f;
    bool localFloorExtension_ = false;
    XrReferenceSpaceType spaceType_ = XR_REFERENCE_SPACE_TYPE_LOCAL;
    float floorOffset_ = 0.0f;
    std::int64_t colorFormat_ = 0;
    std::vector<Swapchain> colorSwapchains_, depthSwapchains_;
    std::array<XrCompositionLayerProjectionView, 2> projectionViews_{};
    std::array<XrCompositionLayerDepthInfoKHR, 2> depthInfos_{};
    XrSessionState state_ = XR_SESSION_STATE_UNKNOWN;
    bool running_ = false, done_ = false, lost_ = false;
    std::string doneReason_;
};

}  // namespace hg::xr
