// The mock OpenXR runtime's instance, system, session state machine, frame
// loop, spaces, views, swapchains and events (docs/xr.md). One stereo HMD
// standing 1.7 m above the stage floor, 90 Hz, two 512 x 512 views; the
// controllers come from a replay script (mock_input.cpp). Misuse answers
// with the error code the OpenXR 1.0 specification gives for it.
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

using Lock = std::lock_guard<std::recursive_mutex>;

Instance* asInstance(XrInstance h) { return reinterpret_cast<Instance*>(h); }
Session* asSession(XrSession h) { return reinterpret_cast<Session*>(h); }
Space* asSpace(XrSpace h) { return reinterpret_cast<Space*>(h); }
Swapchain* asSwapchain(XrSwapchain h) { return reinterpret_cast<Swapchain*>(h); }

const char* const kExtensions[] = {XR_KHR_OPENGL_ENABLE_EXTENSION_NAME, XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME};
const std::int64_t kColorFormats[] = {GL_SRGB8_ALPHA8, GL_RGBA8};
const std::int64_t kDepthFormats[] = {GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32F};

bool stageOffered() { return std::getenv("HG_MOCK_XR_NO_STAGE") == nullptr; }

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

namespace {

// Down from wherever the session is to STOPPING, one state at a time.
void queueStopping(Session& s) {
    if (s.queuedState == XR_SESSION_STATE_FOCUSED) queueState(s, XR_SESSION_STATE_VISIBLE);
    if (s.queuedState == XR_SESSION_STATE_VISIBLE) queueState(s, XR_SESSION_STATE_SYNCHRONIZED);
    if (s.queuedState == XR_SESSION_STATE_SYNCHRONIZED) queueState(s, XR_SESSION_STATE_STOPPING);
}

int raise(const std::string& event) {
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
        if (raise(l) != 0) std::fprintf(stderr, "hg_mock_openxr: unknown event '%s' in %s\n", l.c_str(), path);
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

// --- readback ------------------------------------------------------------------

std::string readbackDir() {
    const char* d = std::getenv("HG_MOCK_XR_READBACK");
    return d ? d : "";
}

void writeFrameLog() {
    const std::string dir = readbackDir();
    if (dir.empty()) return;
    const FrameLog& l = runtime().log;
    nlohmann::json j;
    j["frames_ended"] = l.framesEnded;
    j["frames_with_two_views"] = l.framesWithTwoViews;
    j["last_frame"] = {{"layers", l.layerTypes}, {"views", l.viewCount}, {"depth_views", l.depthViews},
                       {"image_size", {l.imageWidth, l.imageHeight}}};
    j["interaction_profile"] = l.profile;
    j["haptic_pulses"] = l.hapticPulses;
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/frames.json", tmp = path + ".tmp";
    std::ofstream(tmp) << j.dump(2) << "\n";
    std::filesystem::rename(tmp, path);
}

// The last released image of a view, as a PNG (rows top-down). Needs the
// app's GL context current, as xrDestroySwapchain does in a real runtime.
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

// --- instance ------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL enumerateInstanceExtensionProperties(const char* layerName, uint32_t capacity,
                                                                     uint32_t* count, XrExtensionProperties* props) {
    if (layerName && *layerName) return XR_ERROR_API_LAYER_NOT_PRESENT;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    const uint32_t n = sizeof kExtensions / sizeof kExtensions[0];
    *count = n;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < n) return XR_ERROR_SIZE_INSUFFICIENT;
    for (uint32_t i = 0; i < n; ++i) {
        if (props[i].type != XR_TYPE_EXTENSION_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
        std::snprintf(props[i].extensionName, XR_MAX_EXTENSION_NAME_SIZE, "%s", kExtensions[i]);
        props[i].extensionVersion = i == 0 ? XR_KHR_opengl_enable_SPEC_VERSION : XR_KHR_composition_layer_depth_SPEC_VERSION;
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
        if (std::find_if(std::begin(kExtensions), std::end(kExtensions), [&](const char* e) { return name == e; }) ==
            std::end(kExtensions))
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

XRAPI_ATTR XrResult XRAPI_CALL getViewConfigurationProperties(XrInstance instance, XrSystemId id,
                                                              XrViewConfigurationType type,
                                                              XrViewConfigurationProperties* p) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (id != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (!p || p->type != XR_TYPE_VIEW_CONFIGURATION_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
    p->viewConfigurationType = type;
    p->fovMutable = XR_FALSE;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateViewConfigurationViews(XrInstance instance, XrSystemId id,
                                                               XrViewConfigurationType type, uint32_t capacity,
                                                               uint32_t* count, XrViewConfigurationView* views) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (id != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = 2;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
    for (int i = 0; i < 2; ++i) {
        if (views[i].type != XR_TYPE_VIEW_CONFIGURATION_VIEW) return XR_ERROR_VALIDATION_FAILURE;
        views[i].recommendedImageRectWidth = kViewWidth;
        views[i].recommendedImageRectHeight = kViewHeight;
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
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (id != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = 1;
    if (capacity == 0) return XR_SUCCESS;
    modes[0] = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
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

// --- spaces and views ------------------------------------------------------------

garden::Pose headPose() {
    garden::Pose p;
    p.position = glm::vec3(0.0f, kEyeHeight, 0.0f);
    return p;
}

garden::Pose referencePose(XrReferenceSpaceType t) {
    if (t == XR_REFERENCE_SPACE_TYPE_STAGE) return garden::Pose{};
    return headPose();  // LOCAL: where the head started; VIEW: where it is (it does not move)
}

garden::Pose fromXr(const XrPosef& x) {
    garden::Pose p;
    p.position = glm::vec3(x.position.x, x.position.y, x.position.z);
    p.orientation = glm::quat(x.orientation.w, x.orientation.x, x.orientation.y, x.orientation.z);
    return p;
}

garden::Pose compose(const garden::Pose& a, const garden::Pose& b) {
    garden::Pose p;
    p.position = a.position + a.orientation * b.position;
    p.orientation = a.orientation * b.orientation;
    return p;
}

garden::Pose inverse(const garden::Pose& a) {
    garden::Pose p;
    p.orientation = glm::inverse(a.orientation);
    p.position = p.orientation * -a.position;
    return p;
}

bool validOrientation(const XrQuaternionf& q) {
    const float n = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
    return std::abs(n - 1.0f) < 0.01f;
}

// The space's origin in stage coordinates; none when untracked.
std::optional<garden::Pose> stagePose(const Space& sp) {
    const garden::Pose offset = fromXr(sp.offset);
    if (!sp.isAction) return compose(referencePose(sp.reference), offset);
    const garden::Hands hands = scriptedHands(*sp.session, false);
    const std::string* sub = pathString(sp.subaction);
    const bool left = sub && *sub == "/user/hand/left";
    const garden::HandState& h = left ? hands.navigation : hands.tool;
    if (!h.tracked) return std::nullopt;
    // Which pose (grip or aim) the action is bound to on that hand.
    const std::string* binding = nullptr;
    for (const std::string& b : sp.action->bindings)
        if (b.rfind(left ? "/user/hand/left/" : "/user/hand/right/", 0) == 0) binding = &b;
    if (!binding) return std::nullopt;
    const bool aim = binding->find("/input/aim/pose") != std::string::npos;
    return compose(aim ? h.aim : h.grip, offset);
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateReferenceSpaces(XrSession session, uint32_t capacity, uint32_t* count,
                                                        XrReferenceSpaceType* spaces) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    const std::vector<XrReferenceSpaceType> offered =
        stageOffered() ? std::vector<XrReferenceSpaceType>{XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL,
                                                           XR_REFERENCE_SPACE_TYPE_STAGE}
                       : std::vector<XrReferenceSpaceType>{XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL};
    *count = static_cast<uint32_t>(offered.size());
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < offered.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    std::copy(offered.begin(), offered.end(), spaces);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL createReferenceSpace(XrSession session, const XrReferenceSpaceCreateInfo* info,
                                                    XrSpace* out) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!info || !out || info->type != XR_TYPE_REFERENCE_SPACE_CREATE_INFO) return XR_ERROR_VALIDATION_FAILURE;
    const XrReferenceSpaceType t = info->referenceSpaceType;
    if (t != XR_REFERENCE_SPACE_TYPE_VIEW && t != XR_REFERENCE_SPACE_TYPE_LOCAL &&
        !(t == XR_REFERENCE_SPACE_TYPE_STAGE && stageOffered()))
        return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    if (!validOrientation(info->poseInReferenceSpace.orientation)) return XR_ERROR_POSE_INVALID;
    auto sp = std::make_unique<Space>();
    sp->session = asSession(session);
    sp->reference = t;
    sp->offset = info->poseInReferenceSpace;
    *out = reinterpret_cast<XrSpace>(sp.get());
    rt.spaces.insert(sp.release());
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL getReferenceSpaceBoundsRect(XrSession session, XrReferenceSpaceType t, XrExtent2Df* b) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!b) return XR_ERROR_VALIDATION_FAILURE;
    if (t != XR_REFERENCE_SPACE_TYPE_STAGE || !stageOffered()) return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    *b = {3.0f, 3.0f};
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroySpace(XrSpace space) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().spaces, space)) return XR_ERROR_HANDLE_INVALID;
    runtime().spaces.erase(asSpace(space));
    delete asSpace(space);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL locateSpace(XrSpace space, XrSpace base, XrTime time, XrSpaceLocation* location) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.spaces, space) || !isLive(rt.spaces, base)) return XR_ERROR_HANDLE_INVALID;
    if (!location || location->type != XR_TYPE_SPACE_LOCATION) return XR_ERROR_VALIDATION_FAILURE;
    if (time <= 0) return XR_ERROR_TIME_INVALID;
    const auto a = stagePose(*asSpace(space)), b = stagePose(*asSpace(base));
    if (!a || !b) {
        location->locationFlags = 0;
        location->pose = XrPosef{{0, 0, 0, 1}, {0, 0, 0}};
        return XR_SUCCESS;
    }
    location->pose = toXr(compose(inverse(*b), *a));
    location->locationFlags = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
                              XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT | XR_SPACE_LOCATION_POSITION_TRACKED_BIT;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL locateViews(XrSession session, const XrViewLocateInfo* info, XrViewState* state,
                                           uint32_t capacity, uint32_t* count, XrView* views) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!info || !state || !count || info->type != XR_TYPE_VIEW_LOCATE_INFO || state->type != XR_TYPE_VIEW_STATE)
        return XR_ERROR_VALIDATION_FAILURE;
    if (!isLive(rt.spaces, info->space)) return XR_ERROR_HANDLE_INVALID;
    if (info->viewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
        return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (info->displayTime <= 0) return XR_ERROR_TIME_INVALID;
    *count = 2;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
    const auto base = stagePose(*asSpace(info->space));
    state->viewStateFlags = base ? XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT |
                                       XR_VIEW_STATE_ORIENTATION_TRACKED_BIT | XR_VIEW_STATE_POSITION_TRACKED_BIT
                                 : 0;
    for (int i = 0; i < 2; ++i) {
        if (views[i].type != XR_TYPE_VIEW) return XR_ERROR_VALIDATION_FAILURE;
        garden::Pose eye = headPose();
        eye.position.x += i == 0 ? -kHalfIpd : kHalfIpd;
        views[i].pose = base ? toXr(compose(inverse(*base), eye)) : XrPosef{{0, 0, 0, 1}, {0, 0, 0}};
        // A little wider towards the outside, as headsets are.
        views[i].fov = i == 0 ? XrFovf{-0.85f, 0.75f, 0.8f, -0.8f} : XrFovf{-0.75f, 0.85f, 0.8f, -0.8f};
    }
    return XR_SUCCESS;
}

// --- swapchains ------------------------------------------------------------------

bool isColorFormat(std::int64_t f) { return std::find(std::begin(kColorFormats), std::end(kColorFormats), f) != std::end(kColorFormats); }
bool isDepthFormat(std::int64_t f) { return std::find(std::begin(kDepthFormats), std::end(kDepthFormats), f) != std::end(kDepthFormats); }

XRAPI_ATTR XrResult XRAPI_CALL enumerateSwapchainFormats(XrSession session, uint32_t capacity, uint32_t* count,
                                                         int64_t* formats) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    std::vector<std::int64_t> all(std::begin(kColorFormats), std::end(kColorFormats));
    all.insert(all.end(), std::begin(kDepthFormats), std::end(kDepthFormats));
    *count = static_cast<uint32_t>(all.size());
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < all.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    std::copy(all.begin(), all.end(), formats);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL createSwapchain(XrSession session, const XrSwapchainCreateInfo* info, XrSwapchain* out) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!info || !out || info->type != XR_TYPE_SWAPCHAIN_CREATE_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (!isColorFormat(info->format) && !isDepthFormat(info->format)) return XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED;
    if (info->width == 0 || info->height == 0 || info->width > kMaxImageSize || info->height > kMaxImageSize ||
        info->sampleCount != 1 || info->faceCount != 1 || info->arraySize != 1 || info->mipCount != 1)
        return XR_ERROR_FEATURE_UNSUPPORTED;
    // The images are textures of the app's context, which must be current.
    if (!glXGetCurrentContext()) {
        std::fprintf(stderr, "hg_mock_openxr: xrCreateSwapchain needs the session's GL context current\n");
        return XR_ERROR_RUNTIME_FAILURE;
    }
    auto sc = std::make_unique<Swapchain>();
    sc->session = asSession(session);
    sc->format = info->format;
    sc->width = info->width;
    sc->height = info->height;
    sc->images.resize(kImagesPerSwapchain);
    glGenTextures(static_cast<GLsizei>(kImagesPerSwapchain), sc->images.data());
    const bool depth = isDepthFormat(info->format);
    for (GLuint t : sc->images) {
        glBindTexture(GL_TEXTURE_2D, t);
        glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(info->format), static_cast<GLsizei>(info->width),
                     static_cast<GLsizei>(info->height), 0, depth ? GL_DEPTH_COMPONENT : GL_RGBA,
                     depth ? (info->format == GL_DEPTH_COMPONENT32F ? GL_FLOAT : GL_UNSIGNED_INT) : GL_UNSIGNED_BYTE,
                     nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    *out = reinterpret_cast<XrSwapchain>(sc.get());
    rt.swapchains.insert(sc.release());
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroySwapchain(XrSwapchain swapchain) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.swapchains, swapchain)) return XR_ERROR_HANDLE_INVALID;
    Swapchain* sc = asSwapchain(swapchain);
    if (isLive(rt.sessions, sc->session)) {
        Session& s = *sc->session;
        for (int v = 0; v < 2; ++v)
            if (s.lastViewSwapchain[static_cast<std::size_t>(v)] == sc) {
                writeViewImage(*sc, s.lastViewRect[static_cast<std::size_t>(v)], v == 0 ? "left.png" : "right.png");
                s.lastViewSwapchain[static_cast<std::size_t>(v)] = nullptr;
            }
    }
    if (glXGetCurrentContext()) glDeleteTextures(static_cast<GLsizei>(sc->images.size()), sc->images.data());
    rt.swapchains.erase(sc);
    delete sc;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateSwapchainImages(XrSwapchain swapchain, uint32_t capacity, uint32_t* count,
                                                        XrSwapchainImageBaseHeader* images) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().swapchains, swapchain)) return XR_ERROR_HANDLE_INVALID;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    const Swapchain& sc = *asSwapchain(swapchain);
    *count = static_cast<uint32_t>(sc.images.size());
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < sc.images.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    auto* gl = reinterpret_cast<XrSwapchainImageOpenGLKHR*>(images);
    for (std::size_t i = 0; i < sc.images.size(); ++i) {
        if (gl[i].type != XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR) return XR_ERROR_VALIDATION_FAILURE;
        gl[i].image = sc.images[i];
    }
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL acquireSwapchainImage(XrSwapchain swapchain, const XrSwapchainImageAcquireInfo* info,
                                                     uint32_t* index) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().swapchains, swapchain)) return XR_ERROR_HANDLE_INVALID;
    if (!index || (info && info->type != XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    Swapchain& sc = *asSwapchain(swapchain);
    if (sc.acquired.size() == sc.images.size()) return XR_ERROR_CALL_ORDER_INVALID;
    *index = sc.nextAcquire;
    sc.acquired.push_back(sc.nextAcquire);
    sc.nextAcquire = (sc.nextAcquire + 1) % static_cast<uint32_t>(sc.images.size());
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL waitSwapchainImage(XrSwapchain swapchain, const XrSwapchainImageWaitInfo* info) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().swapchains, swapchain)) return XR_ERROR_HANDLE_INVALID;
    if (!info || info->type != XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO) return XR_ERROR_VALIDATION_FAILURE;
    Swapchain& sc = *asSwapchain(swapchain);
    // Only the oldest acquired image may be waited on, once.
    if (sc.acquired.empty() || sc.waited > 0) return XR_ERROR_CALL_ORDER_INVALID;
    sc.waited = 1;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL releaseSwapchainImage(XrSwapchain swapchain, const XrSwapchainImageReleaseInfo* info) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().swapchains, swapchain)) return XR_ERROR_HANDLE_INVALID;
    if (info && info->type != XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO) return XR_ERROR_VALIDATION_FAILURE;
    Swapchain& sc = *asSwapchain(swapchain);
    if (sc.acquired.empty() || sc.waited == 0) return XR_ERROR_CALL_ORDER_INVALID;
    sc.lastReleased = static_cast<int>(sc.acquired.front());
    sc.acquired.pop_front();
    sc.waited = 0;
    return XR_SUCCESS;
}

// --- frames ------------------------------------------------------------------------

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
        for (auto it = range.first; it != range.second; ++it) raise(it->second);
        // The next display refresh on the 90 Hz grid, one period ahead.
        const std::int64_t now = nowNs();
        const std::int64_t next = (now / kFramePeriodNs + 1) * kFramePeriodNs;
        sleepUntil = s.lastDisplayTime > 0 ? std::min(next, s.lastDisplayTime) : 0;
        state->predictedDisplayTime = std::max(next + kFramePeriodNs, s.lastDisplayTime + kFramePeriodNs);
        state->predictedDisplayPeriod = kFramePeriodNs;
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
    if (info->environmentBlendMode != XR_ENVIRONMENT_BLEND_MODE_OPAQUE) return XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED;
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
            {"xrCreateSession", entry(createSession)},
            {"xrDestroySession", entry(destroySession)},
            {"xrBeginSession", entry(beginSession)},
            {"xrEndSession", entry(endSession)},
            {"xrRequestExitSession", entry(requestExitSession)},
            {"xrEnumerateReferenceSpaces", entry(enumerateReferenceSpaces)},
            {"xrCreateReferenceSpace", entry(createReferenceSpace)},
            {"xrGetReferenceSpaceBoundsRect", entry(getReferenceSpaceBoundsRect)},
            {"xrDestroySpace", entry(destroySpace)},
            {"xrLocateSpace", entry(locateSpace)},
            {"xrLocateViews", entry(locateViews)},
            {"xrEnumerateSwapchainFormats", entry(enumerateSwapchainFormats)},
            {"xrCreateSwapchain", entry(createSwapchain)},
            {"xrDestroySwapchain", entry(destroySwapchain)},
            {"xrEnumerateSwapchainImages", entry(enumerateSwapchainImages)},
            {"xrAcquireSwapchainImage", entry(acquireSwapchainImage)},
            {"xrWaitSwapchainImage", entry(waitSwapchainImage)},
            {"xrReleaseSwapchainImage", entry(releaseSwapchainImage)},
            {"xrWaitFrame", entry(waitFrame)},
            {"xrBeginFrame", entry(beginFrame)},
            {"xrEndFrame", entry(endFrame)},
        };
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
    return event ? hg::xr::mock::raise(event) : -1;
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
