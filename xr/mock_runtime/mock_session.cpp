// The mock runtime's session (docs/xr.md): its state machine (IDLE, READY,
// SYNCHRONIZED, VISIBLE, FOCUSED, STOPPING, IDLE, EXITING; LOSS_PENDING on
// demand) and the frame loop (xrWaitFrame paced at 90 Hz, xrBeginFrame,
// xrEndFrame with its layers checked and logged for the readback).
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <thread>

#include "xr/mock_runtime/mock_state.h"

namespace hg::xr::mock {

namespace {

// --- session -------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL createSession(XrInstance instance, const XrSessionCreateInfo* info, XrSession* out) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.instances, instance)) return XR_ERROR_HANDLE_INVALID;
    Instance* inst = asInstance(instance);
    if (inst->lost) return XR_ERROR_INSTANCE_LOST;
    if (!info || !out || info->type != XR_TYPE_SESSION_CREATE_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (info->systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (!inst->extensions.count(XR_KHR_OPENGL_ENABLE_EXTENSION_NAME)) return XR_ERROR_GRAPHICS_DEVICE_INVALID;
    if (!inst->graphicsRequirementsQueried) return XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING;
    const XrGraphicsBindingOpenGLXlibKHR* binding = nullptr;
    for (auto* n = static_cast<const XrBaseInStructure*>(info->next); n; n = n->next)
        if (n->type == XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR)
            binding = reinterpret_cast<const XrGraphicsBindingOpenGLXlibKHR*>(n);
    if (!binding || !binding->xDisplay || !binding->glxContext) return XR_ERROR_GRAPHICS_DEVICE_INVALID;
    if (!rt.sessions.empty()) return XR_ERROR_LIMIT_REACHED;
    auto s = std::make_unique<Session>();
    s->instance = inst;
    s->binding = *binding;
    s->binding.next = nullptr;
    queueState(*s, XR_SESSION_STATE_IDLE);
    queueState(*s, XR_SESSION_STATE_READY);
    *out = reinterpret_cast<XrSession>(s.get());
    rt.sessions.insert(s.release());
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroySession(XrSession session) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    Session* s = asSession(session);
    writeFrameLog();
    for (auto it = rt.spaces.begin(); it != rt.spaces.end();)
        if ((*it)->session == s) {
            delete *it;
            it = rt.spaces.erase(it);
        } else {
            ++it;
        }
    for (auto it = rt.swapchains.begin(); it != rt.swapchains.end();)
        if ((*it)->session == s) {
            if (glXGetCurrentContext() && !(*it)->images.empty())
                glDeleteTextures(static_cast<GLsizei>((*it)->images.size()), (*it)->images.data());
            delete *it;
            it = rt.swapchains.erase(it);
        } else {
            ++it;
        }
    // Its state events die with it.
    rt.events.erase(std::remove_if(rt.events.begin(), rt.events.end(),
                                   [&](const XrEventDataBuffer& b) {
                                       return b.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED &&
                                              reinterpret_cast<const XrEventDataSessionStateChanged*>(&b)->session ==
                                                  session;
                                   }),
                    rt.events.end());
    rt.sessions.erase(s);
    delete s;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL beginSession(XrSession session, const XrSessionBeginInfo* info) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().sessions, session)) return XR_ERROR_HANDLE_INVALID;
    Session& s = *asSession(session);
    if (!info || info->type != XR_TYPE_SESSION_BEGIN_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (info->primaryViewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
        return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (s.lossPending) return XR_SESSION_LOSS_PENDING;
    if (s.running) return XR_ERROR_SESSION_RUNNING;
    if (s.state != XR_SESSION_STATE_READY) return XR_ERROR_SESSION_NOT_READY;
    s.running = true;
    s.focusedAfterFirstFrame = false;
    queueState(s, XR_SESSION_STATE_SYNCHRONIZED);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL endSession(XrSession session) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().sessions, session)) return XR_ERROR_HANDLE_INVALID;
    Session& s = *asSession(session);
    if (s.lossPending) return XR_SESSION_LOSS_PENDING;
    if (!s.running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (s.state != XR_SESSION_STATE_STOPPING) return XR_ERROR_SESSION_NOT_STOPPING;
    s.running = false;
    s.frameBegun = false;
    s.waitsOutstanding = 0;
    queueState(s, XR_SESSION_STATE_IDLE);
    queueState(s, s.exitRequested ? XR_SESSION_STATE_EXITING : XR_SESSION_STATE_READY);
    writeFrameLog();
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL requestExitSession(XrSession session) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().sessions, session)) return XR_ERROR_HANDLE_INVALID;
    Session& s = *asSession(session);
    if (s.lossPending) return XR_SESSION_LOSS_PENDING;
    if (!s.running) return XR_ERROR_SESSION_NOT_RUNNING;
    s.exitRequested = true;
    queueStopping(s);
    return XR_SUCCESS;
}

// --- frames ------------------------------------------------------------------------

constexpr std::int64_t kMonadoFirstPeriodNs = 16000000;

// HG_MOCK_XR_APP_PERIODS=N: the display periods one app frame is paced to
// (1 unless set to a whole number above 1).
std::int64_t appPeriods() {
    const char* n = std::getenv("HG_MOCK_XR_APP_PERIODS");
    const long v = n ? std::strtol(n, nullptr, 10) : 1;
    return v > 1 ? v : 1;
}

XRAPI_ATTR XrResult XRAPI_CALL waitFrame(XrSession session, const XrFrameWaitInfo* info, XrFrameState* state) {
    std::int64_t sleepUntil = 0;
    {
        Lock lock(runtime().mutex);
        Runtime& rt = runtime();
        if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
        if (!state || state->type != XR_TYPE_FRAME_STATE || (info && info->type != XR_TYPE_FRAME_WAIT_INFO))
            return XR_ERROR_VALIDATION_FAILURE;
        Session& s = *asSession(session);
        if (!s.running) return XR_ERROR_SESSION_NOT_RUNNING;
        ++s.waitCount;
        const auto range = rt.scheduledEvents.equal_range(s.waitCount);
        for (auto it = range.first; it != range.second; ++it) raiseEvent(it->second);
        // The next display refresh on the 90 Hz grid, one period ahead.
        // With HG_MOCK_XR_APP_PERIODS, Monado's app pacing: the first frame
        // a placeholder period (16 ms, before it knows the display), then a
        // multiple of the display's period for an app slower than it.
        const std::int64_t n = appPeriods();
        const std::int64_t period = n == 1 ? kFramePeriodNs : s.waitCount == 1 ? kMonadoFirstPeriodNs : n * kFramePeriodNs;
        const std::int64_t now = nowNs();
        const std::int64_t next = (now / kFramePeriodNs + 1) * kFramePeriodNs;
        sleepUntil = s.lastDisplayTime > 0 ? std::min(next, s.lastDisplayTime) : 0;
        state->predictedDisplayTime = std::max(next + kFramePeriodNs, s.lastDisplayTime + period);
        state->predictedDisplayPeriod = period;
        state->shouldRender = s.state == XR_SESSION_STATE_VISIBLE || s.state == XR_SESSION_STATE_FOCUSED;
        s.lastDisplayTime = state->predictedDisplayTime;
        ++s.waitsOutstanding;
        if (s.lossPending) return XR_SESSION_LOSS_PENDING;
    }
    // Throttle to the display outside the lock, as a compositor does.
    const std::int64_t wait = sleepUntil - nowNs();
    if (wait > 0 && std::getenv("HG_MOCK_XR_NO_THROTTLE") == nullptr)
        std::this_thread::sleep_for(std::chrono::nanoseconds(wait));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL beginFrame(XrSession session, const XrFrameBeginInfo* info) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (info && info->type != XR_TYPE_FRAME_BEGIN_INFO) return XR_ERROR_VALIDATION_FAILURE;
    Session& s = *asSession(session);
    if (!s.running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (s.waitsOutstanding == 0) return XR_ERROR_CALL_ORDER_INVALID;
    --s.waitsOutstanding;
    const bool discarded = s.frameBegun;
    s.frameBegun = true;
    if (s.lossPending) return XR_SESSION_LOSS_PENDING;
    return discarded ? XR_FRAME_DISCARDED : XR_SUCCESS;
}

// Checks one projection layer; records its views for the readback.
XrResult checkProjection(Session& s, const XrCompositionLayerProjection& p, FrameLog& log) {
    Runtime& rt = runtime();
    if (!isLive(rt.spaces, p.space)) return XR_ERROR_HANDLE_INVALID;
    if (p.viewCount != 2 || !p.views) return XR_ERROR_VALIDATION_FAILURE;
    log.viewCount = p.viewCount;
    log.depthViews = 0;
    for (uint32_t v = 0; v < p.viewCount; ++v) {
        const XrCompositionLayerProjectionView& view = p.views[v];
        if (view.type != XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW) return XR_ERROR_VALIDATION_FAILURE;
        if (!validOrientation(view.pose.orientation)) return XR_ERROR_POSE_INVALID;
        const XrSwapchainSubImage& sub = view.subImage;
        if (!isLive(rt.swapchains, sub.swapchain)) return XR_ERROR_HANDLE_INVALID;
        const Swapchain& sc = *asSwapchain(sub.swapchain);
        if (sc.lastReleased < 0) return XR_ERROR_LAYER_INVALID;
        if (sub.imageRect.offset.x < 0 || sub.imageRect.offset.y < 0 || sub.imageRect.extent.width <= 0 ||
            sub.imageRect.extent.height <= 0 ||
            static_cast<uint32_t>(sub.imageRect.offset.x + sub.imageRect.extent.width) > sc.width ||
            static_cast<uint32_t>(sub.imageRect.offset.y + sub.imageRect.extent.height) > sc.height)
            return XR_ERROR_SWAPCHAIN_RECT_INVALID;
        if (sub.imageArrayIndex != 0) return XR_ERROR_VALIDATION_FAILURE;
        for (auto* n = static_cast<const XrBaseInStructure*>(view.next); n; n = n->next) {
            if (n->type != XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR) continue;
            if (!s.instance->extensions.count(XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME))
                return XR_ERROR_VALIDATION_FAILURE;
            const auto* d = reinterpret_cast<const XrCompositionLayerDepthInfoKHR*>(n);
            if (!isLive(rt.swapchains, d->subImage.swapchain)) return XR_ERROR_HANDLE_INVALID;
            if (asSwapchain(d->subImage.swapchain)->lastReleased < 0) return XR_ERROR_LAYER_INVALID;
            if (d->minDepth < 0.0f || d->maxDepth > 1.0f || d->minDepth > d->maxDepth || d->nearZ == d->farZ)
                return XR_ERROR_VALIDATION_FAILURE;
            ++log.depthViews;
            log.depthFormat = asSwapchain(d->subImage.swapchain)->format;
        }
        if (v == 0) {
            log.imageWidth = static_cast<uint32_t>(sub.imageRect.extent.width);
            log.imageHeight = static_cast<uint32_t>(sub.imageRect.extent.height);
        }
    }
    for (std::size_t v = 0; v < 2; ++v) {
        s.lastViewSwapchain[v] = asSwapchain(p.views[v].subImage.swapchain);
        s.lastViewRect[v] = p.views[v].subImage.imageRect;
    }
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL endFrame(XrSession session, const XrFrameEndInfo* info) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!info || info->type != XR_TYPE_FRAME_END_INFO) return XR_ERROR_VALIDATION_FAILURE;
    Session& s = *asSession(session);
    if (!s.running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (!s.frameBegun) return XR_ERROR_CALL_ORDER_INVALID;
    if (info->displayTime <= 0) return XR_ERROR_TIME_INVALID;
    if (info->environmentBlendMode != offeredBlendMode()) return XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED;
    if (info->layerCount > kMaxLayers) return XR_ERROR_LAYER_LIMIT_EXCEEDED;
    if (info->layerCount > 0 && !info->layers) return XR_ERROR_VALIDATION_FAILURE;
    FrameLog log = rt.log;
    log.layerTypes.clear();
    log.viewCount = 0;
    log.depthViews = 0;
    for (uint32_t i = 0; i < info->layerCount; ++i) {
        const XrCompositionLayerBaseHeader* l = info->layers[i];
        if (!l) return XR_ERROR_LAYER_INVALID;
        if (l->type == XR_TYPE_COMPOSITION_LAYER_PROJECTION) {
            if (XrResult r = checkProjection(s, *reinterpret_cast<const XrCompositionLayerProjection*>(l), log); r != XR_SUCCESS)
                return r;
            log.layerTypes.push_back("projection");
        } else if (l->type == XR_TYPE_COMPOSITION_LAYER_QUAD) {
            log.layerTypes.push_back("quad");
        } else {
            return XR_ERROR_LAYER_INVALID;
        }
    }
    log.layerCount = info->layerCount;
    ++log.framesEnded;
    if (log.viewCount == 2) ++log.framesWithTwoViews;
    rt.log = log;
    s.frameBegun = false;
    // The compositor shows the session's frames: it becomes visible, and
    // (the mock has no system menu to take focus away) focused.
    if (!s.focusedAfterFirstFrame && s.queuedState == XR_SESSION_STATE_SYNCHRONIZED && !s.exitRequested) {
        s.focusedAfterFirstFrame = true;
        queueState(s, XR_SESSION_STATE_VISIBLE);
        queueState(s, XR_SESSION_STATE_FOCUSED);
    }
    if (s.lossPending) return XR_SESSION_LOSS_PENDING;
    return XR_SUCCESS;
}

}  // namespace

namespace {

// XR_FB_display_refresh_rate: the display's 90 Hz (until the "refresh_60"
// event), whatever the app's pacing.
XRAPI_ATTR XrResult XRAPI_CALL getDisplayRefreshRate(XrSession session, float* rate) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!rate) return XR_ERROR_VALIDATION_FAILURE;
    *rate = asSession(session)->refreshHz;
    return asSession(session)->lossPending ? XR_SESSION_LOSS_PENDING : XR_SUCCESS;
}

}  // namespace

void addSessionFunctions(FunctionTable& t) {
    t["xrGetDisplayRefreshRateFB"] = entry(getDisplayRefreshRate);
    t["xrCreateSession"] = entry(createSession);
    t["xrDestroySession"] = entry(destroySession);
    t["xrBeginSession"] = entry(beginSession);
    t["xrEndSession"] = entry(endSession);
    t["xrRequestExitSession"] = entry(requestExitSession);
    t["xrWaitFrame"] = entry(waitFrame);
    t["xrBeginFrame"] = entry(beginFrame);
    t["xrEndFrame"] = entry(endFrame);
}

}  // namespace hg::xr::mock
