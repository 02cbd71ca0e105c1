// The mock OpenXR runtime (docs/xr.md): the loader negotiation and the
// function table, the instance and its events (states raised on demand, the
// control file), the readback, and the system: one stereo HMD, 90 Hz, two
// 512 x 512 views. The session and frames are in mock_session.cpp, spaces,
// views and swapchains in mock_spaces.cpp, the controllers (a replay
// script's hands) in mock_input.cpp. Misuse answers with the error code the
// OpenXR 1.0 specification gives for it.
#include <openxr/openxr_reflection.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <memory>
#include <thread>
#include <utility>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>

#include "xr/mock_runtime/loader_negotiation.h"
#include "xr/mock_runtime/mock_control.h"
#include "xr/mock_runtime/mock_state.h"

namespace hg::xr::mock {

Runtime& runtime() {
    static Runtime rt;
    return rt;
}

std::int64_t nowNs() {
    static const auto start = std::chrono::steady_clock::now();
    // Never 0: XrTime 0 is invalid.
    return 1000000 + std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count();
}

XrPosef toXr(const garden::Pose& p) {
    XrPosef x{};
    x.orientation = {p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w};
    x.position = {p.position.x, p.position.y, p.position.z};
    return x;
}

namespace {

struct Extension {
    const char* name;
    uint32_t version;
};
const Extension kExtensions[] = {{XR_KHR_OPENGL_ENABLE_EXTENSION_NAME, XR_KHR_opengl_enable_SPEC_VERSION},
                                 {XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME, XR_KHR_composition_layer_depth_SPEC_VERSION},
                                 {XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME, XR_FB_display_refresh_rate_SPEC_VERSION},
                                 {kLocalFloorExtensionName, 1}};

// What the runtime offers: all of kExtensions, less XR_FB_display_refresh_rate
// under HG_MOCK_XR_NO_REFRESH_RATE and XR_EXT_local_floor under
// HG_MOCK_XR_NO_LOCAL_FLOOR.
std::vector<Extension> offeredExtensions() {
    std::vector<Extension> v;
    for (const Extension& e : kExtensions)
        if ((std::strcmp(e.name, XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME) != 0 || !std::getenv("HG_MOCK_XR_NO_REFRESH_RATE")) &&
            (std::strcmp(e.name, kLocalFloorExtensionName) != 0 || !std::getenv("HG_MOCK_XR_NO_LOCAL_FLOOR")))
            v.push_back(e);
    return v;
}

// --- events ----------------------------------------------------------------

void pushEvent(const void* event, std::size_t size) {
    XrEventDataBuffer b{};
    std::memcpy(&b, event, size);
    runtime().events.push_back(b);
}

}  // namespace

void queueState(Session& s, XrSessionState state) {
    XrEventDataSessionStateChanged e{};
    e.type = XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED;
    e.session = reinterpret_cast<XrSession>(&s);
    e.state = state;
    e.time = nowNs();
    s.queuedState = state;
    pushEvent(&e, sizeof e);
}

void queueStopping(Session& s) {
    if (s.queuedState == XR_SESSION_STATE_FOCUSED) queueState(s, XR_SESSION_STATE_VISIBLE);
    if (s.queuedState == XR_SESSION_STATE_VISIBLE) queueState(s, XR_SESSION_STATE_SYNCHRONIZED);
    if (s.queuedState == XR_SESSION_STATE_SYNCHRONIZED) queueState(s, XR_SESSION_STATE_STOPPING);
}

XrEnvironmentBlendMode offeredBlendMode() {
    const char* mode = std::getenv("HG_MOCK_XR_BLEND_MODE");
    return mode && std::strcmp(mode, "additive") == 0 ? XR_ENVIRONMENT_BLEND_MODE_ADDITIVE : XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
}

int raiseEvent(const std::string& event) {
    Runtime& rt = runtime();
    Session* s = rt.sessions.empty() ? nullptr : *rt.sessions.begin();
    if (event == "instance_loss") {
        XrEventDataInstanceLossPending e{};
        e.type = XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING;
        e.lossTime = nowNs() + kFramePeriodNs;
        pushEvent(&e, sizeof e);
        for (Instance* i : rt.instances) i->lost = true;
        return 0;
    }
    if (event == "refresh_60") {
        // The display now runs at 60 Hz (XR_FB_display_refresh_rate's event;
        // the frames keep the mock's 90 Hz pacing).
        if (s && s->instance->extensions.count(XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME)) {
            XrEventDataDisplayRefreshRateChangedFB e{};
            e.type = XR_TYPE_EVENT_DATA_DISPLAY_REFRESH_RATE_CHANGED_FB;
            e.fromDisplayRefreshRate = s->refreshHz;
            e.toDisplayRefreshRate = s->refreshHz = 60.0f;
            pushEvent(&e, sizeof e);
        }
        return 0;
    }
    if (event != "loss" && event != "exit" && event != "unfocus" && event != "focus") return -1;
    if (!s) return 0;
    if (event == "loss" && !s->lossPending) {
        s->lossPending = true;
        queueState(*s, XR_SESSION_STATE_LOSS_PENDING);
    } else if (event == "exit" && s->running && !s->lossPending) {
        s->exitRequested = true;
        queueStopping(*s);
    } else if (event == "unfocus" && s->queuedState == XR_SESSION_STATE_FOCUSED) {
        queueState(*s, XR_SESSION_STATE_VISIBLE);
    } else if (event == "focus" && s->queuedState == XR_SESSION_STATE_VISIBLE) {
        queueState(*s, XR_SESSION_STATE_FOCUSED);
    }
    return 0;
}

namespace {

void pollControlFile() {
    const char* path = std::getenv("HG_MOCK_XR_CONTROL");
    if (!path || !std::filesystem::exists(path)) return;
    std::ifstream in(path);
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(in, line))
        if (!line.empty()) lines.push_back(line);
    in.close();
    std::filesystem::remove(path);
    for (const std::string& l : lines)
        if (raiseEvent(l) != 0) std::fprintf(stderr, "hg_mock_openxr: unknown event '%s' in %s\n", l.c_str(), path);
}

void scheduleEventsFromEnvironment(Runtime& rt) {
    rt.scheduledEvents.clear();
    const char* spec = std::getenv("HG_MOCK_XR_EVENTS");
    if (!spec) return;
    std::stringstream in(spec);
    std::string item;
    while (std::getline(in, item, ',')) {
        const auto colon = item.find(':');
        if (colon == std::string::npos) continue;
        rt.scheduledEvents.emplace(std::strtoull(item.substr(0, colon).c_str(), nullptr, 10), item.substr(colon + 1));
    }
}

}  // namespace

// --- readback ------------------------------------------------------------------

namespace {
std::string readbackDir() {
    const char* d = std::getenv("HG_MOCK_XR_READBACK");
    return d ? d : "";
}

}  // namespace

void writeFrameLog() {
    const std::string dir = readbackDir();
    if (dir.empty()) return;
    const FrameLog& l = runtime().log;
    nlohmann::json j;
    j["frames_ended"] = l.framesEnded;
    j["frames_with_two_views"] = l.framesWithTwoViews;
    j["last_frame"] = {{"layers", l.layerTypes}, {"views", l.viewCount}, {"depth_views", l.depthViews},
                       {"depth_format", l.depthFormat},
                       {"image_size", {l.imageWidth, l.imageHeight}}};
    j["interaction_profile"] = l.profile;
    j["haptic_pulses"] = l.hapticPulses;
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/frames.json", tmp = path + ".tmp";
    std::ofstream(tmp) << j.dump(2) << "\n";
    std::filesystem::rename(tmp, path);
}

void writeViewImage(const Swapchain& sc, const XrRect2Di& rect, const std::string& name) {
    const std::string dir = readbackDir();
    if (dir.empty() || sc.lastReleased < 0 || !glXGetCurrentContext()) return;
    std::vector<std::uint8_t> all(static_cast<std::size_t>(sc.width) * sc.height * 4);
    glBindTexture(GL_TEXTURE_2D, sc.images[static_cast<std::size_t>(sc.lastReleased)]);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, all.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    const int w = rect.extent.width, h = rect.extent.height;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y) {
        const std::size_t srcRow = static_cast<std::size_t>(rect.offset.y + h - 1 - y);
        std::memcpy(&out[static_cast<std::size_t>(y) * w * 4], &all[(srcRow * sc.width + rect.offset.x) * 4],
                    static_cast<std::size_t>(w) * 4);
    }
    std::filesystem::create_directories(dir);
    stbi_write_png((dir + "/" + name).c_str(), w, h, 4, out.data(), w * 4);
}

namespace {

// --- instance ------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL enumerateInstanceExtensionProperties(const char* layerName, uint32_t capacity,
                                                                     uint32_t* count, XrExtensionProperties* props) {
    if (layerName && *layerName) return XR_ERROR_API_LAYER_NOT_PRESENT;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    const std::vector<Extension> offered = offeredExtensions();
    const auto n = static_cast<uint32_t>(offered.size());
    *count = n;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < n) return XR_ERROR_SIZE_INSUFFICIENT;
    for (uint32_t i = 0; i < n; ++i) {
        if (props[i].type != XR_TYPE_EXTENSION_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
        std::snprintf(props[i].extensionName, XR_MAX_EXTENSION_NAME_SIZE, "%s", offered[i].name);
        props[i].extensionVersion = offered[i].version;
    }
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateApiLayerProperties(uint32_t, uint32_t* count, XrApiLayerProperties*) {
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = 0;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL createInstance(const XrInstanceCreateInfo* info, XrInstance* out) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!info || !out || info->type != XR_TYPE_INSTANCE_CREATE_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (info->applicationInfo.applicationName[0] == '\0') return XR_ERROR_NAME_INVALID;
    if (XR_VERSION_MAJOR(info->applicationInfo.apiVersion) != 1) return XR_ERROR_API_VERSION_UNSUPPORTED;
    if (!rt.instances.empty()) return XR_ERROR_LIMIT_REACHED;
    auto inst = std::make_unique<Instance>();
    for (uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
        const std::string name = info->enabledExtensionNames[i];
        const std::vector<Extension> offered = offeredExtensions();
        if (std::none_of(offered.begin(), offered.end(), [&](const Extension& e) { return name == e.name; }))
            return XR_ERROR_EXTENSION_NOT_PRESENT;
        inst->extensions.insert(name);
    }
    rt.events.clear();
    rt.suggested.clear();
    rt.log = FrameLog{};
    loadScriptFromEnvironment(rt);
    if (!rt.scriptError.empty()) {
        std::fprintf(stderr, "hg_mock_openxr: %s\n", rt.scriptError.c_str());
        return XR_ERROR_RUNTIME_FAILURE;
    }
    scheduleEventsFromEnvironment(rt);
    *out = reinterpret_cast<XrInstance>(inst.get());
    rt.instances.insert(inst.release());
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroyInstance(XrInstance instance) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.instances, instance)) return XR_ERROR_HANDLE_INVALID;
    // Children go with their parent (the spec destroys them too).
    for (Action* a : rt.actions) delete a;
    for (ActionSet* s : rt.actionSets) delete s;
    for (Space* s : rt.spaces) delete s;
    for (Swapchain* s : rt.swapchains) delete s;
    for (Session* s : rt.sessions) delete s;
    rt.actions.clear();
    rt.actionSets.clear();
    rt.spaces.clear();
    rt.swapchains.clear();
    rt.sessions.clear();
    rt.events.clear();
    rt.instances.erase(asInstance(instance));
    delete asInstance(instance);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL getInstanceProperties(XrInstance instance, XrInstanceProperties* props) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (!props || props->type != XR_TYPE_INSTANCE_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
    props->runtimeVersion = XR_MAKE_VERSION(0, 1, 0);
    std::snprintf(props->runtimeName, XR_MAX_RUNTIME_NAME_SIZE, "Hypergarden mock runtime");
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL resultToString(XrInstance instance, XrResult value, char buffer[XR_MAX_RESULT_STRING_SIZE]) {
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
#define HG_RESULT_CASE(name, val) \
    case name: std::snprintf(buffer, XR_MAX_RESULT_STRING_SIZE, "%s", #name); return XR_SUCCESS;
    switch (value) { XR_LIST_ENUM_XrResult(HG_RESULT_CASE) default: break; }
#undef HG_RESULT_CASE
    std::snprintf(buffer, XR_MAX_RESULT_STRING_SIZE, "XR_%s_%d", value < 0 ? "UNKNOWN_FAILURE" : "UNKNOWN_SUCCESS",
                  static_cast<int>(value));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL structureTypeToString(XrInstance instance, XrStructureType value,
                                                     char buffer[XR_MAX_STRUCTURE_NAME_SIZE]) {
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
#define HG_TYPE_CASE(name, val) \
    case name: std::snprintf(buffer, XR_MAX_STRUCTURE_NAME_SIZE, "%s", #name); return XR_SUCCESS;
    switch (value) { XR_LIST_ENUM_XrStructureType(HG_TYPE_CASE) default: break; }
#undef HG_TYPE_CASE
    std::snprintf(buffer, XR_MAX_STRUCTURE_NAME_SIZE, "XR_UNKNOWN_STRUCTURE_TYPE_%d", static_cast<int>(value));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL pollEvent(XrInstance instance, XrEventDataBuffer* buffer) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (!buffer || buffer->type != XR_TYPE_EVENT_DATA_BUFFER) return XR_ERROR_VALIDATION_FAILURE;
    pollControlFile();
    if (rt.events.empty()) return XR_EVENT_UNAVAILABLE;
    *buffer = rt.events.front();
    rt.events.pop_front();
    if (buffer->type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
        const auto* e = reinterpret_cast<const XrEventDataSessionStateChanged*>(buffer);
        if (isLive(rt.sessions, e->session)) asSession(e->session)->state = e->state;
    }
    return XR_SUCCESS;
}

// --- system --------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL getSystem(XrInstance instance, const XrSystemGetInfo* info, XrSystemId* id) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (!info || !id || info->type != XR_TYPE_SYSTEM_GET_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (info->formFactor != XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY) return XR_ERROR_FORM_FACTOR_UNSUPPORTED;
    *id = kSystemId;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL getSystemProperties(XrInstance instance, XrSystemId id, XrSystemProperties* p) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (id != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (!p || p->type != XR_TYPE_SYSTEM_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
    p->systemId = kSystemId;
    p->vendorId = 0x4867;
    std::snprintf(p->systemName, XR_MAX_SYSTEM_NAME_SIZE, "Hypergarden mock HMD");
    p->graphicsProperties = {kMaxImageSize, kMaxImageSize, kMaxLayers};
    p->trackingProperties = {XR_TRUE, XR_TRUE};
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateViewConfigurations(XrInstance instance, XrSystemId id, uint32_t capacity,
                                                           uint32_t* count, XrViewConfigurationType* types) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (id != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = 1;
    if (capacity == 0) return XR_SUCCESS;
    types[0] = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    return XR_SUCCESS;
}

// The checks every call about the stereo view configuration makes first.
XrResult checkStereo(XrInstance instance, XrSystemId id, XrViewConfigurationType type) {
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (id != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL getViewConfigurationProperties(XrInstance instance, XrSystemId id,
                                                              XrViewConfigurationType type,
                                                              XrViewConfigurationProperties* p) {
    Lock lock(runtime().mutex);
    if (const XrResult r = checkStereo(instance, id, type); r != XR_SUCCESS) return r;
    if (!p || p->type != XR_TYPE_VIEW_CONFIGURATION_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
    p->viewConfigurationType = type;
    p->fovMutable = XR_FALSE;
    return XR_SUCCESS;
}

// HG_MOCK_XR_VIEW_SIZE=WxH: the recommended size of each view (512 x 512
// unless set; Monado's simulated headset has 640 x 720).
std::pair<std::uint32_t, std::uint32_t> viewSize() {
    unsigned w = 0, h = 0;
    const char* spec = std::getenv("HG_MOCK_XR_VIEW_SIZE");
    if (spec && std::sscanf(spec, "%ux%u", &w, &h) == 2 && w > 0 && h > 0 && w <= kMaxImageSize && h <= kMaxImageSize)
        return {w, h};
    return {kViewWidth, kViewHeight};
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateViewConfigurationViews(XrInstance instance, XrSystemId id,
                                                               XrViewConfigurationType type, uint32_t capacity,
                                                               uint32_t* count, XrViewConfigurationView* views) {
    Lock lock(runtime().mutex);
    if (const XrResult r = checkStereo(instance, id, type); r != XR_SUCCESS) return r;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = 2;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
    for (int i = 0; i < 2; ++i) {
        if (views[i].type != XR_TYPE_VIEW_CONFIGURATION_VIEW) return XR_ERROR_VALIDATION_FAILURE;
        const auto [width, height] = viewSize();
        views[i].recommendedImageRectWidth = width;
        views[i].recommendedImageRectHeight = height;
        views[i].maxImageRectWidth = kMaxImageSize;
        views[i].maxImageRectHeight = kMaxImageSize;
        views[i].recommendedSwapchainSampleCount = 1;
        views[i].maxSwapchainSampleCount = 1;
    }
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateEnvironmentBlendModes(XrInstance instance, XrSystemId id,
                                                              XrViewConfigurationType type, uint32_t capacity,
                                                              uint32_t* count, XrEnvironmentBlendMode* modes) {
    Lock lock(runtime().mutex);
    if (const XrResult r = checkStereo(instance, id, type); r != XR_SUCCESS) return r;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = 1;
    if (capacity == 0) return XR_SUCCESS;
    modes[0] = offeredBlendMode();
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL getOpenGLGraphicsRequirements(XrInstance instance, XrSystemId id,
                                                             XrGraphicsRequirementsOpenGLKHR* r) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (id != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (!r || r->type != XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR) return XR_ERROR_VALIDATION_FAILURE;
    r->minApiVersionSupported = XR_MAKE_VERSION(3, 3, 0);
    r->maxApiVersionSupported = XR_MAKE_VERSION(4, 6, 0);
    asInstance(instance)->graphicsRequirementsQueried = true;
    return XR_SUCCESS;
}

// --- dispatch ----------------------------------------------------------------------

const FunctionTable& functions() {
    static const FunctionTable table = [] {
        FunctionTable t{
            {"xrEnumerateInstanceExtensionProperties", entry(enumerateInstanceExtensionProperties)},
            {"xrEnumerateApiLayerProperties", entry(enumerateApiLayerProperties)},
            {"xrCreateInstance", entry(createInstance)},
            {"xrDestroyInstance", entry(destroyInstance)},
            {"xrGetInstanceProperties", entry(getInstanceProperties)},
            {"xrResultToString", entry(resultToString)},
            {"xrStructureTypeToString", entry(structureTypeToString)},
            {"xrPollEvent", entry(pollEvent)},
            {"xrGetSystem", entry(getSystem)},
            {"xrGetSystemProperties", entry(getSystemProperties)},
            {"xrEnumerateViewConfigurations", entry(enumerateViewConfigurations)},
            {"xrGetViewConfigurationProperties", entry(getViewConfigurationProperties)},
            {"xrEnumerateViewConfigurationViews", entry(enumerateViewConfigurationViews)},
            {"xrEnumerateEnvironmentBlendModes", entry(enumerateEnvironmentBlendModes)},
            {"xrGetOpenGLGraphicsRequirementsKHR", entry(getOpenGLGraphicsRequirements)},
        };
        addSessionFunctions(t);
        addSpaceFunctions(t);
        addInputFunctions(t);
        return t;
    }();
    return table;
}

XRAPI_ATTR XrResult XRAPI_CALL getInstanceProcAddr(XrInstance instance, const char* name, PFN_xrVoidFunction* function) {
    if (!name || !function) return XR_ERROR_VALIDATION_FAILURE;
    *function = nullptr;
    const std::string n = name;
    const bool global = n == "xrEnumerateInstanceExtensionProperties" || n == "xrEnumerateApiLayerProperties" ||
                        n == "xrCreateInstance" || n == "xrGetInstanceProcAddr";
    if (!instance && !global) return XR_ERROR_HANDLE_INVALID;
    if (instance) {
        Lock lock(runtime().mutex);
        if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
        // An extension's functions only for an instance that enabled it.
        if (n == "xrGetDisplayRefreshRateFB" &&
            !asInstance(instance)->extensions.count(XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME))
            return XR_ERROR_FUNCTION_UNSUPPORTED;
    }
    if (n == "xrGetInstanceProcAddr") {
        *function = entry(getInstanceProcAddr);
        return XR_SUCCESS;
    }
    const auto it = functions().find(n);
    if (it == functions().end()) return XR_ERROR_FUNCTION_UNSUPPORTED;
    *function = it->second;
    return XR_SUCCESS;
}

}  // namespace
}  // namespace hg::xr::mock

extern "C" {

__attribute__((visibility("default"))) XrResult xrNegotiateLoaderRuntimeInterface(const XrNegotiateLoaderInfo* loaderInfo,
                                                                                  XrNegotiateRuntimeRequest* request) {
    if (!loaderInfo || !request || loaderInfo->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
        loaderInfo->structVersion != XR_LOADER_INFO_STRUCT_VERSION || loaderInfo->structSize != sizeof(XrNegotiateLoaderInfo) ||
        request->structType != XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST ||
        request->structVersion != XR_RUNTIME_INFO_STRUCT_VERSION || request->structSize != sizeof(XrNegotiateRuntimeRequest))
        return XR_ERROR_INITIALIZATION_FAILED;
    if (loaderInfo->minInterfaceVersion > XR_CURRENT_LOADER_RUNTIME_VERSION ||
        loaderInfo->maxInterfaceVersion < XR_CURRENT_LOADER_RUNTIME_VERSION ||
        XR_VERSION_MAJOR(loaderInfo->maxApiVersion) < 1 || XR_VERSION_MAJOR(loaderInfo->minApiVersion) > 1)
        return XR_ERROR_INITIALIZATION_FAILED;
    request->runtimeInterfaceVersion = XR_CURRENT_LOADER_RUNTIME_VERSION;
    request->runtimeApiVersion = XR_CURRENT_API_VERSION;
    request->getInstanceProcAddr = hg::xr::mock::getInstanceProcAddr;
    return XR_SUCCESS;
}

__attribute__((visibility("default"))) int hgMockXrRaise(const char* event) {
    std::lock_guard<std::recursive_mutex> lock(hg::xr::mock::runtime().mutex);
    return event ? hg::xr::mock::raiseEvent(event) : -1;
}

__attribute__((visibility("default"))) void hgMockXrFrameInfo(HgMockXrFrameInfo* out) {
    std::lock_guard<std::recursive_mutex> lock(hg::xr::mock::runtime().mutex);
    const hg::xr::mock::Runtime& rt = hg::xr::mock::runtime();
    const hg::xr::mock::FrameLog& l = rt.log;
    *out = HgMockXrFrameInfo{l.framesEnded, l.framesWithTwoViews, l.layerCount, l.viewCount, l.depthViews,
                             l.imageWidth, l.imageHeight,
                             rt.sessions.empty() ? 0 : static_cast<std::int32_t>((*rt.sessions.begin())->state),
                             l.hapticPulses};
}

}  // extern "C"
