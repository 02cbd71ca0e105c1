// The mock runtime's objects and its one global state (xr/mock_runtime):
// what mock_runtime.cpp (instance, session, frames, swapchains, events)
// and mock_input.cpp (paths, actions, bindings, scripted hands) share.
// Every entry point locks Runtime::mutex; handles are pointers to these
// objects, checked against the live sets so a stale or made-up handle
// answers XR_ERROR_HANDLE_INVALID instead of crashing.
#pragma once

// Our headers before X11's, whose macros (None, Status) collide with names.
#include "garden/replay/replay_script.h"

#define XR_USE_PLATFORM_XLIB
#define XR_USE_GRAPHICS_API_OPENGL
#include <epoxy/gl.h>
#include <epoxy/glx.h>
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include "xr/local_floor.h"
#undef None
#undef Status

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace hg::xr::mock {

constexpr XrSystemId kSystemId = 1;
constexpr std::int64_t kFramePeriodNs = 11111111;  // 90 Hz
constexpr float kEyeHeight = 1.7f;                 // the head above the stage floor
constexpr float kHalfIpd = 0.032f;
constexpr std::uint32_t kViewWidth = 512, kViewHeight = 512;
constexpr std::uint32_t kMaxImageSize = 4096;
constexpr std::uint32_t kImagesPerSwapchain = 3;
constexpr std::uint32_t kMaxLayers = 16;

struct Session;
struct ActionSet;

struct Instance {
    std::set<std::string> extensions;
    bool graphicsRequirementsQueried = false;
    bool lost = false;
};

struct Action {
    ActionSet* set = nullptr;
    std::string name;
    XrActionType type = XR_ACTION_TYPE_BOOLEAN_INPUT;
    std::vector<XrPath> subactions;
    std::vector<std::string> bindings;  // for the session's interaction profile, set on attach
};

struct ActionSet {
    std::string name;
    std::vector<Action*> actions;
    bool attached = false;
};

struct Space {
    Session* session = nullptr;
    bool isAction = false;
    XrReferenceSpaceType reference = XR_REFERENCE_SPACE_TYPE_STAGE;
    Action* action = nullptr;
    XrPath subaction = XR_NULL_PATH;
    XrPosef offset{};
};

struct Swapchain {
    Session* session = nullptr;
    std::int64_t format = 0;
    std::uint32_t width = 0, height = 0;
    std::vector<GLuint> images;
    std::uint32_t nextAcquire = 0;
    std::deque<std::uint32_t> acquired;  // acquired, in order, not yet released
    std::uint32_t waited = 0;            // of those, how many were waited on
    int lastReleased = -1;
};

struct Session {
    Instance* instance = nullptr;
    XrGraphicsBindingOpenGLXlibKHR binding{};
    XrSessionState state = XR_SESSION_STATE_UNKNOWN;        // as the app has seen it (polled)
    XrSessionState queuedState = XR_SESSION_STATE_UNKNOWN;  // the last one queued
    bool running = false;
    bool exitRequested = false;
    bool lossPending = false;
    bool focusedAfterFirstFrame = false;
    float refreshHz = 1e9f / static_cast<float>(kFramePeriodNs);  // XR_FB_display_refresh_rate's
    int waitsOutstanding = 0;  // xrWaitFrame calls not yet followed by xrBeginFrame
    bool frameBegun = false;
    std::uint64_t waitCount = 0;
    std::uint64_t syncCount = 0;  // focused xrSyncActions: the script's frame is syncCount - 1
    XrPath profile = XR_NULL_PATH;
    std::set<ActionSet*> attached;
    std::int64_t lastDisplayTime = 0;
    // The last frame's projection views: swapchain and sub-image rectangle.
    std::array<Swapchain*, 2> lastViewSwapchain{};
    std::array<XrRect2Di, 2> lastViewRect{};
};

struct FrameLog {
    std::uint64_t framesEnded = 0, framesWithTwoViews = 0, hapticPulses = 0;
    std::uint32_t layerCount = 0, viewCount = 0, depthViews = 0, imageWidth = 0, imageHeight = 0;
    std::int64_t depthFormat = 0;  // the last depth view's swapchain format (GL)
    std::vector<std::string> layerTypes;
    std::string profile;
};

struct Runtime {
    std::recursive_mutex mutex;
    std::set<Instance*> instances;
    std::set<Session*> sessions;
    std::set<Space*> spaces;
    std::set<Swapchain*> swapchains;
    std::set<ActionSet*> actionSets;
    std::set<Action*> actions;
    std::deque<XrEventDataBuffer> events;
    std::vector<std::string> paths{""};  // XrPath n is paths[n]; 0 is XR_NULL_PATH
    std::map<std::string, XrPath> pathIds;
    // Suggested bindings per interaction profile: (action, binding path).
    std::map<XrPath, std::vector<std::pair<Action*, XrPath>>> suggested;
    std::optional<garden::ReplayScript> script;
    std::string scriptError;
    std::multimap<std::uint64_t, std::string> scheduledEvents;  // xrWaitFrame count -> event
    FrameLog log;
};

Runtime& runtime();

// Paths (mock_input.cpp).
XrPath pathOf(const std::string& s);  // interned; no format check
const std::string* pathString(XrPath p);
// The scripted hands of the current script frame; none before the first
// focused sync or without a script. `previous`: the frame before.
garden::Hands scriptedHands(const Session& s, bool previous);
void loadScriptFromEnvironment(Runtime& rt);

// Events and states (mock_runtime.cpp).
void queueState(Session& s, XrSessionState state);
// Down from wherever the session is to STOPPING, one state at a time.
void queueStopping(Session& s);
// "loss", "exit", "unfocus", "focus" or "instance_loss" now; -1 for another name.
int raiseEvent(const std::string& event);
// The readback (HG_MOCK_XR_READBACK): the frame log, and a view's last
// released image as a PNG (rows top-down; needs the app's GL context
// current, as xrDestroySwapchain has it in a real runtime).
void writeFrameLog();
void writeViewImage(const Swapchain& sc, const XrRect2Di& rect, const std::string& name);
bool validOrientation(const XrQuaternionf& q);  // of unit length
// The one environment blend mode offered: OPAQUE, or ADDITIVE under
// HG_MOCK_XR_BLEND_MODE=additive (a see-through headset).
XrEnvironmentBlendMode offeredBlendMode();
XrPosef toXr(const garden::Pose& p);
std::int64_t nowNs();

// The entry points each file implements, by name, for xrGetInstanceProcAddr.
using FunctionTable = std::map<std::string, PFN_xrVoidFunction>;
void addSessionFunctions(FunctionTable& table);  // mock_session.cpp
void addSpaceFunctions(FunctionTable& table);    // mock_spaces.cpp: spaces, views, swapchains
void addInputFunctions(FunctionTable& table);    // mock_input.cpp

using Lock = std::lock_guard<std::recursive_mutex>;

inline Instance* asInstance(XrInstance h) { return reinterpret_cast<Instance*>(h); }
inline Session* asSession(XrSession h) { return reinterpret_cast<Session*>(h); }
inline Space* asSpace(XrSpace h) { return reinterpret_cast<Space*>(h); }
inline Swapchain* asSwapchain(XrSwapchain h) { return reinterpret_cast<Swapchain*>(h); }

// Casts an entry point of any signature for the table.
template <typename F>
PFN_xrVoidFunction entry(F* f) {
    return reinterpret_cast<PFN_xrVoidFunction>(f);
}

template <typename T>
bool isLive(const std::set<T*>& live, const void* handle) {
    return handle && live.count(static_cast<T*>(const_cast<void*>(handle))) != 0;
}

}  // namespace hg::xr::mock
