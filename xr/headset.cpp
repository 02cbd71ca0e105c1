#include "xr/headset.h"

#include "xr/xr_platform.h"

#include <algorithm>
#include <cstring>

#include "xr/local_floor.h"
#include "xr/xr_result.h"

namespace hg::xr {

namespace {

constexpr XrViewConfigurationType kViewConfiguration = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;

template <typename F>
F function(XrInstance instance, const char* name) {
    PFN_xrVoidFunction f = nullptr;
    check(xrGetInstanceProcAddr(instance, name, &f), name);
    return reinterpret_cast<F>(f);
}

bool offered(const std::vector<XrExtensionProperties>& all, const char* name) {
    return std::any_of(all.begin(), all.end(), [&](const XrExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

}  // namespace

Headset::Headset(const std::string& applicationName) {
    uint32_t count = 0;
    XrResult r = xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr);
    if (r == XR_ERROR_RUNTIME_UNAVAILABLE || r == XR_ERROR_RUNTIME_FAILURE || r == XR_ERROR_INSTANCE_LOST)
        throw NoRuntime("the OpenXR loader found no runtime (" + XrFailure::resultName(r) +
                        "); install one, or point XR_RUNTIME_JSON at a runtime manifest");
    check(r, "xrEnumerateInstanceExtensionProperties");
    std::vector<XrExtensionProperties> extensions(count, {XR_TYPE_EXTENSION_PROPERTIES});
    check(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, extensions.data()),
          "xrEnumerateInstanceExtensionProperties");
    if (!offered(extensions, XR_KHR_OPENGL_ENABLE_EXTENSION_NAME))
        throw XrFailure("the runtime does not offer " + std::string(XR_KHR_OPENGL_ENABLE_EXTENSION_NAME),
                        XR_ERROR_EXTENSION_NOT_PRESENT);
    depthExtension_ = offered(extensions, XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME);
    refreshRateExtension_ = offered(extensions, XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME);
    localFloorExtension_ = offered(extensions, kLocalFloorExtensionName);
    std::vector<const char*> enabled = {XR_KHR_OPENGL_ENABLE_EXTENSION_NAME};
    if (depthExtension_) enabled.push_back(XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME);
    if (refreshRateExtension_) enabled.push_back(XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME);
    if (localFloorExtension_) enabled.push_back(kLocalFloorExtensionName);

    XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
    std::snprintf(info.applicationInfo.applicationName, XR_MAX_APPLICATION_NAME_SIZE, "%s", applicationName.c_str());
    info.applicationInfo.applicationVersion = 1;
    std::snprintf(info.applicationInfo.engineName, XR_MAX_ENGINE_NAME_SIZE, "Hypergarden");
    info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    info.enabledExtensionCount = static_cast<uint32_t>(enabled.size());
    info.enabledExtensionNames = enabled.data();
    r = xrCreateInstance(&info, &instance_);
    if (r == XR_ERROR_RUNTIME_UNAVAILABLE || r == XR_ERROR_RUNTIME_FAILURE)
        throw NoRuntime("the OpenXR runtime did not start (" + XrFailure::resultName(r) + ")");
    check(r, "xrCreateInstance");

    XrSystemGetInfo system{XR_TYPE_SYSTEM_GET_INFO};
    system.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    r = xrGetSystem(instance_, &system, &system_);
    if (r == XR_ERROR_FORM_FACTOR_UNAVAILABLE) {
        xrDestroyInstance(instance_);
        throw NoRuntime("the OpenXR runtime has no headset connected (XR_ERROR_FORM_FACTOR_UNAVAILABLE)");
    }
    if (XR_FAILED(r)) xrDestroyInstance(instance_);
    check(r, "xrGetSystem");
}

Headset::~Headset() {
    destroySession();
    if (instance_ != XR_NULL_HANDLE) xrDestroyInstance(instance_);
}

std::string Headset::runtimeName() const {
    XrInstanceProperties p{XR_TYPE_INSTANCE_PROPERTIES};
    if (XR_FAILED(xrGetInstanceProperties(instance_, &p))) return "?";
    return p.runtimeName;
}

void Headset::createSession(GLFWwindow* window) {
    // The spec requires the graphics requirements asked before the session.
    auto requirements = function<PFN_xrGetOpenGLGraphicsRequirementsKHR>(instance_, "xrGetOpenGLGraphicsRequirementsKHR");
    XrGraphicsRequirementsOpenGLKHR req{XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR};
    check(requirements(instance_, system_, &req), "xrGetOpenGLGraphicsRequirementsKHR");
    const XrVersion have = XR_MAKE_VERSION(epoxy_gl_version() / 10, epoxy_gl_version() % 10, 0);
    if (have < req.minApiVersionSupported)
        throw XrFailure("the runtime needs a newer OpenGL than " + std::to_string(epoxy_gl_version()),
                        XR_ERROR_GRAPHICS_DEVICE_INVALID);

    // OPAQUE unless the headset lacks it (a see-through one may offer only ADDITIVE).
    uint32_t modeCount = 0;
    check(xrEnumerateEnvironmentBlendModes(instance_, system_, kViewConfiguration, 0, &modeCount, nullptr),
          "xrEnumerateEnvironmentBlendModes");
    std::vector<XrEnvironmentBlendMode> modes(modeCount);
    check(xrEnumerateEnvironmentBlendModes(instance_, system_, kViewConfiguration, modeCount, &modeCount, modes.data()),
          "xrEnumerateEnvironmentBlendModes");
    if (!modes.empty() && std::find(modes.begin(), modes.end(), XR_ENVIRONMENT_BLEND_MODE_OPAQUE) == modes.end())
        blendMode_ = modes.front();

    XrGraphicsBindingOpenGLXlibKHR binding{XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR};
    binding.xDisplay = glfwGetX11Display();
    binding.glxContext = glfwGetGLXContext(window);
    binding.glxDrawable = glfwGetGLXWindow(window);
    // The FB config and visual of the context, as the binding wants them.
    int fbconfigId = 0;
    glXQueryContext(binding.xDisplay, binding.glxContext, GLX_FBCONFIG_ID, &fbconfigId);
    const int attributes[] = {GLX_FBCONFIG_ID, fbconfigId, 0};
    int n = 0;
    if (GLXFBConfig* configs = glXChooseFBConfig(binding.xDisplay, DefaultScreen(binding.xDisplay), attributes, &n)) {
        if (n > 0) {
            binding.glxFBConfig = configs[0];
            if (XVisualInfo* visual = glXGetVisualFromFBConfig(binding.xDisplay, configs[0])) {
                binding.visualid = static_cast<uint32_t>(visual->visualid);
                XFree(visual);
            }
        }
        XFree(configs);
    }
    XrSessionCreateInfo info{XR_TYPE_SESSION_CREATE_INFO};
    info.next = &binding;
    info.systemId = system_;
    check(xrCreateSession(instance_, &info, &session_), "xrCreateSession");

    if (refreshRateExtension_) {
        // Not fatal: without it the frame budget comes from the frames' periods.
        float hz = 0.0f;
        auto rate = function<PFN_xrGetDisplayRefreshRateFB>(instance_, "xrGetDisplayRefreshRateFB");
        if (XR_SUCCEEDED(rate(session_, &hz)) && hz > 0.0f) refreshRate_ = hz;
    }

    // The world's anchor: LOCAL_FLOOR (the floor under where the user
    // stood, facing their way: the garden's start is in front of them
    // wherever the stage's walls are), else the stage (floor level), else
    // LOCAL raised by a standing eye height. A space the runtime lists may
    // still be refused on the way (an API layer older than the extension
    // rejects LOCAL_FLOOR's enum): the next one is taken then.
    uint32_t count = 0;
    check(xrEnumerateReferenceSpaces(session_, 0, &count, nullptr), "xrEnumerateReferenceSpaces");
    std::vector<XrReferenceSpaceType> spaces(count);
    check(xrEnumerateReferenceSpaces(session_, count, &count, spaces.data()), "xrEnumerateReferenceSpaces");
    const auto listed = [&](XrReferenceSpaceType t) { return std::find(spaces.begin(), spaces.end(), t) != spaces.end(); };
    std::vector<XrReferenceSpaceType> candidates;
    if (localFloorExtension_ && listed(kReferenceSpaceLocalFloor)) candidates.push_back(kReferenceSpaceLocalFloor);
    if (listed(XR_REFERENCE_SPACE_TYPE_STAGE)) candidates.push_back(XR_REFERENCE_SPACE_TYPE_STAGE);
    candidates.push_back(XR_REFERENCE_SPACE_TYPE_LOCAL);  // every runtime has it
    for (const XrReferenceSpaceType t : candidates) {
        XrReferenceSpaceCreateInfo space{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
        space.referenceSpaceType = t;
        space.poseInReferenceSpace.orientation.w = 1.0f;
        const XrResult made = xrCreateReferenceSpace(session_, &space, &space_);
        if (t == XR_REFERENCE_SPACE_TYPE_LOCAL) check(made, "xrCreateReferenceSpace");
        if (XR_SUCCEEDED(made)) {
            spaceType_ = t;
            break;
        }
    }
    floorOffset_ = spaceType_ == XR_REFERENCE_SPACE_TYPE_LOCAL ? kStandingEyeHeight : 0.0f;

    // Swapchains: sRGB colour (the renderer writes sRGB-encoded values, and
    // the compositor decodes them), 24-bit depth when submitted.
    check(xrEnumerateSwapchainFormats(session_, 0, &count, nullptr), "xrEnumerateSwapchainFormats");
    std::vector<int64_t> formats(count);
    check(xrEnumerateSwapchainFormats(session_, count, &count, formats.data()), "xrEnumerateSwapchainFormats");
    const auto has = [&](int64_t f) { return std::find(formats.begin(), formats.end(), f) != formats.end(); };
    colorFormat_ = has(GL_SRGB8_ALPHA8) ? GL_SRGB8_ALPHA8 : has(GL_RGBA8) ? GL_RGBA8 : 0;
    if (colorFormat_ == 0) throw XrFailure("the runtime offers neither GL_SRGB8_ALPHA8 nor GL_RGBA8 swapchains",
                                           XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED);
    const int64_t depthFormat = has(GL_DEPTH_COMPONENT24) ? GL_DEPTH_COMPONENT24 : has(GL_DEPTH_COMPONENT32F) ? GL_DEPTH_COMPONENT32F : 0;

    check(xrEnumerateViewConfigurationViews(instance_, system_, kViewConfiguration, 0, &count, nullptr),
          "xrEnumerateViewConfigurationViews");
    std::vector<XrViewConfigurationView> views(count, {XR_TYPE_VIEW_CONFIGURATION_VIEW});
    check(xrEnumerateViewConfigurationViews(instance_, system_, kViewConfiguration, count, &count, views.data()),
          "xrEnumerateViewConfigurationViews");
    if (views.size() != 2) throw XrFailure("the headset has " + std::to_string(views.size()) + " views, not 2",
                                           XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED);
    for (const XrViewConfigurationView& v : views) {
        const int w = static_cast<int>(v.recommendedImageRectWidth), h = static_cast<int>(v.recommendedImageRectHeight);
        colorSwapchains_.push_back(makeSwapchain(colorFormat_, w, h,
                                                 XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT));
        if (depthExtension_ && depthFormat != 0)
            depthSwapchains_.push_back(makeSwapchain(depthFormat, w, h, XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT));
    }
}

Headset::Swapchain Headset::makeSwapchain(std::int64_t format, int width, int height, XrSwapchainUsageFlags usage) {
    XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
    info.usageFlags = usage;
    info.format = format;
    info.sampleCount = 1;
    info.width = static_cast<uint32_t>(width);
    info.height = static_cast<uint32_t>(height);
    info.faceCount = 1;
    info.arraySize = 1;
    info.mipCount = 1;
    Swapchain s;
    s.width = width;
    s.height = height;
    check(xrCreateSwapchain(session_, &info, &s.handle), "xrCreateSwapchain");
    uint32_t count = 0;
    check(xrEnumerateSwapchainImages(s.handle, 0, &count, nullptr), "xrEnumerateSwapchainImages");
    std::vector<XrSwapchainImageOpenGLKHR> images(count, {XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR});
    check(xrEnumerateSwapchainImages(s.handle, count, &count, reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data())),
          "xrEnumerateSwapchainImages");
    for (const auto& i : images) s.images.push_back(i.image);
    return s;
}

void Headset::destroySession() {
    // The swapchains' images are textures of the GL context, current here.
    for (auto* v : {&colorSwapchains_, &depthSwapchains_}) {
        for (Swapchain& s : *v) xrDestroySwapchain(s.handle);
        v->clear();
    }
    if (space_ != XR_NULL_HANDLE) xrDestroySpace(space_);
    space_ = XR_NULL_HANDLE;
    if (session_ != XR_NULL_HANDLE) xrDestroySession(session_);
    session_ = XR_NULL_HANDLE;
    running_ = false;
}

void Headset::handleState(XrSessionState s) {
    state_ = s;
    switch (s) {
        case XR_SESSION_STATE_READY: {
            XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
            begin.primaryViewConfigurationType = kViewConfiguration;
            check(xrBeginSession(session_, &begin), "xrBeginSession");
            running_ = true;
            break;
        }
        case XR_SESSION_STATE_STOPPING:
            check(xrEndSession(session_), "xrEndSession");
            running_ = false;
            break;
        case XR_SESSION_STATE_EXITING:
            done_ = true;
            doneReason_ = "the session ended";
            break;
        case XR_SESSION_STATE_LOSS_PENDING:
            done_ = lost_ = true;
            doneReason_ = "the runtime lost the session (LOSS_PENDING)";
            break;
        default: break;  // IDLE, SYNCHRONIZED, VISIBLE, FOCUSED: the frame loop reads state()
    }
}

bool Headset::pollEvents() {
    bool profileChanged = false;
    for (;;) {
        XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
        const XrResult r = check(xrPollEvent(instance_, &event), "xrPollEvent");
        if (r == XR_EVENT_UNAVAILABLE) break;
        switch (event.type) {
            case XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED: {
                const auto& e = *reinterpret_cast<const XrEventDataSessionStateChanged*>(&event);
                if (e.session == session_) handleState(e.state);
                break;
            }
            case XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING:
                done_ = lost_ = true;
                doneReason_ = "the runtime is going away (instance loss pending)";
                break;
            case XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED: profileChanged = true; break;
            case XR_TYPE_EVENT_DATA_DISPLAY_REFRESH_RATE_CHANGED_FB: {
                const auto& e = *reinterpret_cast<const XrEventDataDisplayRefreshRateChangedFB*>(&event);
                if (e.toDisplayRefreshRate > 0.0f) refreshRate_ = e.toDisplayRefreshRate;
                break;
            }
            default: break;  // events lost, reference space changes: nothing to do
        }
        if (done_) break;
    }
    return profileChanged;
}

void Headset::requestExit() {
    if (running_) check(xrRequestExitSession(session_), "xrRequestExitSession");
}

HeadsetFrame Headset::beginFrame() {
    HeadsetFrame f;
    XrFrameWaitInfo wait{XR_TYPE_FRAME_WAIT_INFO};
    check(xrWaitFrame(session_, &wait, &f.state), "xrWaitFrame");
    XrFrameBeginInfo begin{XR_TYPE_FRAME_BEGIN_INFO};
    check(xrBeginFrame(session_, &begin), "xrBeginFrame");
    if (!f.state.shouldRender) return f;
    XrViewLocateInfo locate{XR_TYPE_VIEW_LOCATE_INFO};
    locate.viewConfigurationType = kViewConfiguration;
    locate.displayTime = f.state.predictedDisplayTime;
    locate.space = space_;
    XrViewState viewState{XR_TYPE_VIEW_STATE};
    uint32_t count = 0;
    check(xrLocateViews(session_, &locate, &viewState, 2, &count, f.views.data()), "xrLocateViews");
    const XrViewStateFlags needed = XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT;
    f.viewsValid = count == 2 && (viewState.viewStateFlags & needed) == needed;
    return f;
}

EyeImages Headset::acquireEye(int eye) {
    EyeImages e;
    for (auto* v : {&colorSwapchains_, &depthSwapchains_}) {
        if (v->empty()) continue;
        Swapchain& s = (*v)[static_cast<std::size_t>(eye)];
        check(xrAcquireSwapchainImage(s.handle, nullptr, &s.acquired), "xrAcquireSwapchainImage");
        XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
        wait.timeout = XR_INFINITE_DURATION;
        check(xrWaitSwapchainImage(s.handle, &wait), "xrWaitSwapchainImage");
        (v == &colorSwapchains_ ? e.color : e.depth) = s.images[s.acquired];
        e.width = s.width;
        e.height = s.height;
    }
    return e;
}

void Headset::releaseEye(int eye) {
    for (auto* v : {&colorSwapchains_, &depthSwapchains_}) {
        if (v->empty()) continue;
        XrSwapchainImageReleaseInfo release{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
        check(xrReleaseSwapchainImage((*v)[static_cast<std::size_t>(eye)].handle, &release), "xrReleaseSwapchainImage");
    }
}

void Headset::endFrame(const HeadsetFrame& frame, bool rendered, float nearZ, float farZ) {
    XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
    const XrCompositionLayerBaseHeader* layers[] = {reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer)};
    if (rendered) {
        for (std::size_t i = 0; i < 2; ++i) {
            XrCompositionLayerProjectionView& v = projectionViews_[i];
            v = {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW};
            v.pose = frame.views[i].pose;
            v.fov = frame.views[i].fov;
            v.subImage.swapchain = colorSwapchains_[i].handle;
            v.subImage.imageRect = {{0, 0}, {colorSwapchains_[i].width, colorSwapchains_[i].height}};
            if (!depthSwapchains_.empty()) {
                XrCompositionLayerDepthInfoKHR& d = depthInfos_[i];
                d = {XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR};
                d.subImage.swapchain = depthSwapchains_[i].handle;
                d.subImage.imageRect = v.subImage.imageRect;
                d.minDepth = 0.0f;
                d.maxDepth = 1.0f;
                d.nearZ = nearZ;
                d.farZ = farZ;
                v.next = &d;
            }
        }
        layer.space = space_;
        layer.viewCount = 2;
        layer.views = projectionViews_.data();
    }
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = frame.state.predictedDisplayTime;
    end.environmentBlendMode = blendMode_;
    end.layerCount = rendered ? 1 : 0;
    end.layers = rendered ? layers : nullptr;
    check(xrEndFrame(session_, &end), "xrEndFrame");
}

const char* Headset::spaceName() const {
    if (spaceType_ == kReferenceSpaceLocalFloor) return "LOCAL_FLOOR";
    return spaceType_ == XR_REFERENCE_SPACE_TYPE_STAGE ? "STAGE" : "LOCAL";
}

}  // namespace hg::xr
