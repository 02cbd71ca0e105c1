// The mock runtime's spaces, views and swapchains (docs/xr.md): a head
// 1.7 m above the stage floor that does not move (turned HG_MOCK_XR_HEAD_YAW
// degrees to the right, if set), two eyes 64 mm apart,
// controllers where the script puts them (mock_input.cpp); swapchain images
// are GL textures made in the app's current context.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <glm/gtc/quaternion.hpp>

#include "xr/mock_runtime/mock_state.h"

namespace hg::xr::mock {

namespace {

const std::int64_t kColorFormats[] = {GL_SRGB8_ALPHA8, GL_RGBA8};
const std::int64_t kDepthFormats[] = {GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT16};

// HG_MOCK_XR_NO_DEPTH24: no GL_DEPTH_COMPONENT24, as Monado's GL client
// (it has no GL name for VK_FORMAT_X8_D24_UNORM_PACK32); 16-bit depth then.
bool depthFormatOffered(std::int64_t f) {
    const bool monado = std::getenv("HG_MOCK_XR_NO_DEPTH24") != nullptr;
    return monado ? f != GL_DEPTH_COMPONENT24 : f != GL_DEPTH_COMPONENT16;
}

bool stageOffered() { return std::getenv("HG_MOCK_XR_NO_STAGE") == nullptr; }

// LOCAL_FLOOR needs its extension enabled on the session's instance.
bool localFloorOffered(const Session& s) { return s.instance->extensions.count(kLocalFloorExtensionName) != 0; }

// --- spaces and views ------------------------------------------------------------

garden::Pose headPose() {
    garden::Pose p;
    p.position = glm::vec3(0.0f, kEyeHeight, 0.0f);
    if (const char* yaw = std::getenv("HG_MOCK_XR_HEAD_YAW"))
        p.orientation = glm::angleAxis(-glm::radians(static_cast<float>(std::atof(yaw))), glm::vec3(0.0f, 1.0f, 0.0f));
    return p;
}

garden::Pose referencePose(XrReferenceSpaceType t) {
    if (t == XR_REFERENCE_SPACE_TYPE_STAGE) return garden::Pose{};
    garden::Pose head = headPose();  // LOCAL: where the head started; VIEW: where it is (it does not move)
    if (t == kReferenceSpaceLocalFloor) head.position.y = 0.0f;  // the head only turns about the vertical
    return head;
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

}  // namespace

bool validOrientation(const XrQuaternionf& q) {
    const float n = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
    return std::abs(n - 1.0f) < 0.01f;
}

namespace {

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
    std::vector<XrReferenceSpaceType> offered = {XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL};
    if (stageOffered()) offered.push_back(XR_REFERENCE_SPACE_TYPE_STAGE);
    if (localFloorOffered(*asSession(session))) offered.push_back(kReferenceSpaceLocalFloor);
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
        !(t == XR_REFERENCE_SPACE_TYPE_STAGE && stageOffered()) &&
        !(t == kReferenceSpaceLocalFloor && localFloorOffered(*asSession(session))))
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
        eye.position += eye.orientation * glm::vec3(i == 0 ? -kHalfIpd : kHalfIpd, 0.0f, 0.0f);
        views[i].pose = base ? toXr(compose(inverse(*base), eye)) : XrPosef{{0, 0, 0, 1}, {0, 0, 0}};
        // A little wider towards the outside, as headsets are.
        views[i].fov = i == 0 ? XrFovf{-0.85f, 0.75f, 0.8f, -0.8f} : XrFovf{-0.75f, 0.85f, 0.8f, -0.8f};
    }
    return XR_SUCCESS;
}

// --- swapchains ------------------------------------------------------------------

bool isColorFormat(std::int64_t f) { return std::find(std::begin(kColorFormats), std::end(kColorFormats), f) != std::end(kColorFormats); }
bool isDepthFormat(std::int64_t f) {
    return depthFormatOffered(f) && std::find(std::begin(kDepthFormats), std::end(kDepthFormats), f) != std::end(kDepthFormats);
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateSwapchainFormats(XrSession session, uint32_t capacity, uint32_t* count,
                                                         int64_t* formats) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    std::vector<std::int64_t> all(std::begin(kColorFormats), std::end(kColorFormats));
    for (std::int64_t f : kDepthFormats)
        if (depthFormatOffered(f)) all.push_back(f);
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

}  // namespace

void addSpaceFunctions(FunctionTable& t) {
    t["xrEnumerateReferenceSpaces"] = entry(enumerateReferenceSpaces);
    t["xrCreateReferenceSpace"] = entry(createReferenceSpace);
    t["xrGetReferenceSpaceBoundsRect"] = entry(getReferenceSpaceBoundsRect);
    t["xrDestroySpace"] = entry(destroySpace);
    t["xrLocateSpace"] = entry(locateSpace);
    t["xrLocateViews"] = entry(locateViews);
    t["xrEnumerateSwapchainFormats"] = entry(enumerateSwapchainFormats);
    t["xrCreateSwapchain"] = entry(createSwapchain);
    t["xrDestroySwapchain"] = entry(destroySwapchain);
    t["xrEnumerateSwapchainImages"] = entry(enumerateSwapchainImages);
    t["xrAcquireSwapchainImage"] = entry(acquireSwapchainImage);
    t["xrWaitSwapchainImage"] = entry(waitSwapchainImage);
    t["xrReleaseSwapchainImage"] = entry(releaseSwapchainImage);
}

}  // namespace hg::xr::mock
