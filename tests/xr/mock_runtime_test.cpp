// The mock OpenXR runtime through the loader: the session's states in the
// order the specification gives, states raised on demand, and misuse
// answered with the error code the specification prescribes (one test per
// kind the program could hit).
#include "mock_xr_fixture.h"

#include <algorithm>
#include <vector>

#include "xr/local_floor.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <vector>

namespace hg::xr::test {
namespace {

using MockRuntime = MockXr;

TEST_F(MockRuntime, SessionGoesThroughEveryStateToExiting) {
    makeSession();
    beginSession();
    XrSpace space = stageSpace();
    // The first frame makes the session visible, then focused.
    const XrFrameState f = waitAndBegin();
    EXPECT_EQ(f.predictedDisplayPeriod, 11111111) << "90 Hz";
    EXPECT_GT(f.predictedDisplayTime, 0);
    EXPECT_EQ(endFrame(f.predictedDisplayTime), XR_SUCCESS);
    ASSERT_TRUE(pollUntil(XR_SESSION_STATE_FOCUSED));
    auto frameInfo = mockFunction<PFN_hgMockXrFrameInfo>("hgMockXrFrameInfo");
    ASSERT_NE(frameInfo, nullptr);
    HgMockXrFrameInfo info{};
    frameInfo(&info);
    EXPECT_EQ(info.framesEnded, 1u);
    EXPECT_EQ(info.layerCount, 0u) << "an empty frame";
    EXPECT_EQ(info.sessionState, XR_SESSION_STATE_FOCUSED);
    ASSERT_EQ(xrRequestExitSession(session), XR_SUCCESS);
    ASSERT_TRUE(pollUntil(XR_SESSION_STATE_STOPPING));
    ASSERT_EQ(xrEndSession(session), XR_SUCCESS);
    ASSERT_TRUE(pollUntil(XR_SESSION_STATE_EXITING));
    const std::vector<XrSessionState> expected = {
        XR_SESSION_STATE_IDLE,    XR_SESSION_STATE_READY,        XR_SESSION_STATE_SYNCHRONIZED,
        XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_FOCUSED,      XR_SESSION_STATE_VISIBLE,
        XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_STOPPING, XR_SESSION_STATE_IDLE,
        XR_SESSION_STATE_EXITING};
    EXPECT_EQ(seen, expected);
    xrDestroySpace(space);
}

TEST_F(MockRuntime, LossIsRaisedOnDemand) {
    makeSession();
    beginSession();
    auto raise = mockFunction<PFN_hgMockXrRaise>("hgMockXrRaise");
    ASSERT_NE(raise, nullptr) << "the test reaches the mock through dlsym";
    EXPECT_EQ(raise("no such event"), -1);
    ASSERT_EQ(raise("loss"), 0);
    ASSERT_TRUE(pollUntil(XR_SESSION_STATE_LOSS_PENDING));
    XrFrameState state{XR_TYPE_FRAME_STATE};
    EXPECT_EQ(xrWaitFrame(session, nullptr, &state), XR_SESSION_LOSS_PENDING);
}

TEST_F(MockRuntime, ControlFileRaisesStatesNow) {
    const std::string control = ::testing::TempDir() + "hg_mock_xr_control_" + std::to_string(::getpid());
    ::setenv("HG_MOCK_XR_CONTROL", control.c_str(), 1);
    makeSession();
    beginSession();
    const XrFrameState f = waitAndBegin();
    ASSERT_EQ(endFrame(f.predictedDisplayTime), XR_SUCCESS);
    ASSERT_TRUE(pollUntil(XR_SESSION_STATE_FOCUSED));
    std::ofstream(control) << "unfocus\n";
    ASSERT_TRUE(pollUntil(XR_SESSION_STATE_VISIBLE));
    EXPECT_FALSE(std::filesystem::exists(control)) << "read once, then removed";
    std::ofstream(control) << "exit\n";
    ASSERT_TRUE(pollUntil(XR_SESSION_STATE_STOPPING));
    ASSERT_EQ(xrEndSession(session), XR_SUCCESS);
    ASSERT_TRUE(pollUntil(XR_SESSION_STATE_EXITING));
}

TEST_F(MockRuntime, HandleInvalid) {
    const XrSession bogus = reinterpret_cast<XrSession>(static_cast<std::uintptr_t>(0x1234));
    XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
    begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    EXPECT_EQ(xrBeginSession(bogus, &begin), XR_ERROR_HANDLE_INVALID);
    makeSession();
    XrSpace space = stageSpace();
    ASSERT_EQ(xrDestroySpace(space), XR_SUCCESS);
    EXPECT_EQ(xrDestroySpace(space), XR_ERROR_HANDLE_INVALID) << "a destroyed handle";
}

TEST_F(MockRuntime, CallOrderInvalid) {
    makeSession();
    beginSession();
    EXPECT_EQ(xrBeginFrame(session, nullptr), XR_ERROR_CALL_ORDER_INVALID) << "xrBeginFrame without xrWaitFrame";
    XrFrameState state{XR_TYPE_FRAME_STATE};
    ASSERT_EQ(xrWaitFrame(session, nullptr, &state), XR_SUCCESS);
    EXPECT_EQ(endFrame(state.predictedDisplayTime), XR_ERROR_CALL_ORDER_INVALID) << "xrEndFrame without xrBeginFrame";
    XrSwapchain s = makeSwapchain(GL_SRGB8_ALPHA8);
    EXPECT_EQ(xrReleaseSwapchainImage(s, nullptr), XR_ERROR_CALL_ORDER_INVALID) << "release before acquire";
    uint32_t index = 0;
    ASSERT_EQ(xrAcquireSwapchainImage(s, nullptr, &index), XR_SUCCESS);
    EXPECT_EQ(xrReleaseSwapchainImage(s, nullptr), XR_ERROR_CALL_ORDER_INVALID) << "release before wait";
    xrDestroySwapchain(s);
}

TEST_F(MockRuntime, SessionNotRunning) {
    makeSession();
    XrFrameState state{XR_TYPE_FRAME_STATE};
    EXPECT_EQ(xrWaitFrame(session, nullptr, &state), XR_ERROR_SESSION_NOT_RUNNING);
    EXPECT_EQ(xrRequestExitSession(session), XR_ERROR_SESSION_NOT_RUNNING);
    EXPECT_EQ(xrEndSession(session), XR_ERROR_SESSION_NOT_RUNNING);
}

TEST_F(MockRuntime, SessionNotReady) {
    makeSession();  // READY is queued, not yet polled
    XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
    begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    EXPECT_EQ(xrBeginSession(session, &begin), XR_ERROR_SESSION_NOT_READY);
}

TEST_F(MockRuntime, SessionRunningAndNotStopping) {
    makeSession();
    beginSession();
    XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
    begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    EXPECT_EQ(xrBeginSession(session, &begin), XR_ERROR_SESSION_RUNNING);
    EXPECT_EQ(xrEndSession(session), XR_ERROR_SESSION_NOT_STOPPING);
}

TEST_F(MockRuntime, ValidationFailure) {
    XrSystemGetInfo wrongType{XR_TYPE_SESSION_BEGIN_INFO};
    XrSystemId id = 0;
    EXPECT_EQ(xrGetSystem(instance, &wrongType, &id), XR_ERROR_VALIDATION_FAILURE) << "a struct of the wrong type";
    makeSession();
    beginSession();
    XrSpace space = stageSpace();
    XrSwapchain s = makeSwapchain(GL_SRGB8_ALPHA8);
    uint32_t index = 0;
    ASSERT_EQ(xrAcquireSwapchainImage(s, nullptr, &index), XR_SUCCESS);
    XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
    ASSERT_EQ(xrWaitSwapchainImage(s, &wait), XR_SUCCESS);
    ASSERT_EQ(xrReleaseSwapchainImage(s, nullptr), XR_SUCCESS);
    const XrFrameState f = waitAndBegin();
    XrCompositionLayerProjectionView view{XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW};
    view.pose.orientation.w = 1.0f;
    view.subImage.swapchain = s;
    view.subImage.imageRect = {{0, 0}, {64, 64}};
    XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
    layer.space = space;
    layer.viewCount = 1;  // a stereo headset takes two
    layer.views = &view;
    EXPECT_EQ(endFrame(f.predictedDisplayTime, reinterpret_cast<XrCompositionLayerBaseHeader*>(&layer)),
              XR_ERROR_VALIDATION_FAILURE);
    xrDestroySwapchain(s);
    xrDestroySpace(space);
}

TEST_F(MockRuntime, LayerInvalidAndSwapchainRectInvalid) {
    makeSession();
    beginSession();
    XrSpace space = stageSpace();
    XrSwapchain s = makeSwapchain(GL_SRGB8_ALPHA8);
    const XrFrameState f = waitAndBegin();
    std::array<XrCompositionLayerProjectionView, 2> views{};
    for (auto& v : views) {
        v.type = XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW;
        v.pose.orientation.w = 1.0f;
        v.subImage.swapchain = s;
        v.subImage.imageRect = {{0, 0}, {64, 64}};
    }
    XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
    layer.space = space;
    layer.viewCount = 2;
    layer.views = views.data();
    const auto* l = reinterpret_cast<XrCompositionLayerBaseHeader*>(&layer);
    EXPECT_EQ(endFrame(f.predictedDisplayTime, l), XR_ERROR_LAYER_INVALID) << "no image of the swapchain was released";
    uint32_t index = 0;
    ASSERT_EQ(xrAcquireSwapchainImage(s, nullptr, &index), XR_SUCCESS);
    XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
    ASSERT_EQ(xrWaitSwapchainImage(s, &wait), XR_SUCCESS);
    ASSERT_EQ(xrReleaseSwapchainImage(s, nullptr), XR_SUCCESS);
    views[1].subImage.imageRect = {{32, 0}, {64, 64}};
    EXPECT_EQ(endFrame(f.predictedDisplayTime, l), XR_ERROR_SWAPCHAIN_RECT_INVALID) << "past the image's edge";
    views[1].subImage.imageRect = {{0, 0}, {64, 64}};
    EXPECT_EQ(endFrame(f.predictedDisplayTime, l), XR_SUCCESS);
    xrDestroySwapchain(s);
    xrDestroySpace(space);
}

TEST_F(MockRuntime, TimeInvalid) {
    makeSession();
    beginSession();
    waitAndBegin();
    EXPECT_EQ(endFrame(0), XR_ERROR_TIME_INVALID);
}

TEST_F(MockRuntime, GraphicsRequirementsCallMissing) {
    EXPECT_EQ(createSession(), XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING);
}

TEST_F(MockRuntime, SwapchainFormatUnsupported) {
    makeSession();
    XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
    info.format = GL_RGB565;
    info.width = info.height = 64;
    info.sampleCount = info.faceCount = info.arraySize = info.mipCount = 1;
    XrSwapchain s = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateSwapchain(session, &info, &s), XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED);
}

TEST_F(MockRuntime, LocalFloorOnlyWithItsExtension) {
    // This instance did not enable XR_EXT_local_floor: the space is neither
    // listed nor made.
    makeSession();
    uint32_t count = 0;
    ASSERT_EQ(xrEnumerateReferenceSpaces(session, 0, &count, nullptr), XR_SUCCESS);
    std::vector<XrReferenceSpaceType> spaces(count);
    ASSERT_EQ(xrEnumerateReferenceSpaces(session, count, &count, spaces.data()), XR_SUCCESS);
    EXPECT_EQ(std::count(spaces.begin(), spaces.end(), kReferenceSpaceLocalFloor), 0);
    XrReferenceSpaceCreateInfo info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    info.referenceSpaceType = kReferenceSpaceLocalFloor;
    info.poseInReferenceSpace.orientation.w = 1.0f;
    XrSpace space = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateReferenceSpace(session, &info, &space), XR_ERROR_REFERENCE_SPACE_UNSUPPORTED);
}

class MockActions : public MockXr {
protected:
    void makeActions() {
        XrActionSetCreateInfo set{XR_TYPE_ACTION_SET_CREATE_INFO};
        std::strcpy(set.actionSetName, "test");
        std::strcpy(set.localizedActionSetName, "Test");
        ASSERT_EQ(xrCreateActionSet(instance, &set, &actionSet), XR_SUCCESS);
        hands[0] = path("/user/hand/left");
        hands[1] = path("/user/hand/right");
        XrActionCreateInfo a{XR_TYPE_ACTION_CREATE_INFO};
        std::strcpy(a.actionName, "trigger");
        std::strcpy(a.localizedActionName, "Trigger");
        a.actionType = XR_ACTION_TYPE_FLOAT_INPUT;
        a.countSubactionPaths = 2;
        a.subactionPaths = hands;
        ASSERT_EQ(xrCreateAction(actionSet, &a, &trigger), XR_SUCCESS);
    }
    XrResult suggest(const char* profile, const char* binding) {
        XrActionSuggestedBinding b{trigger, path(binding)};
        XrInteractionProfileSuggestedBinding s{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
        s.interactionProfile = path(profile);
        s.countSuggestedBindings = 1;
        s.suggestedBindings = &b;
        return xrSuggestInteractionProfileBindings(instance, &s);
    }
    XrResult attach() {
        XrSessionActionSetsAttachInfo info{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
        info.countActionSets = 1;
        info.actionSets = &actionSet;
        return xrAttachSessionActionSets(session, &info);
    }
    XrActionSet actionSet = XR_NULL_HANDLE;
    XrAction trigger = XR_NULL_HANDLE;
    XrPath hands[2] = {};
};

TEST_F(MockActions, ActionSetNotAttached) {
    makeSession();
    makeActions();
    XrActiveActionSet active{actionSet, XR_NULL_PATH};
    XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    EXPECT_EQ(xrSyncActions(session, &sync), XR_ERROR_ACTIONSET_NOT_ATTACHED);
    XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
    get.action = trigger;
    XrActionStateFloat state{XR_TYPE_ACTION_STATE_FLOAT};
    EXPECT_EQ(xrGetActionStateFloat(session, &get, &state), XR_ERROR_ACTIONSET_NOT_ATTACHED);
}

TEST_F(MockActions, ActionSetsAlreadyAttached) {
    makeSession();
    makeActions();
    ASSERT_EQ(suggest("/interaction_profiles/oculus/touch_controller", "/user/hand/right/input/trigger/value"), XR_SUCCESS);
    ASSERT_EQ(attach(), XR_SUCCESS);
    EXPECT_EQ(attach(), XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
    EXPECT_EQ(suggest("/interaction_profiles/oculus/touch_controller", "/user/hand/left/input/trigger/value"),
              XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
}

TEST_F(MockActions, PathUnsupportedAndFormatInvalid) {
    makeActions();
    // Touch controllers have A on the right hand only.
    EXPECT_EQ(suggest("/interaction_profiles/oculus/touch_controller", "/user/hand/left/input/a/click"),
              XR_ERROR_PATH_UNSUPPORTED);
    EXPECT_EQ(suggest("/interaction_profiles/acme/teapot", "/user/hand/left/input/trigger/value"), XR_ERROR_PATH_UNSUPPORTED);
    XrPath p = XR_NULL_PATH;
    EXPECT_EQ(xrStringToPath(instance, "/user//hand", &p), XR_ERROR_PATH_FORMAT_INVALID);
    EXPECT_EQ(xrStringToPath(instance, "user/Hand", &p), XR_ERROR_PATH_FORMAT_INVALID);
}

TEST_F(MockActions, ActionTypeMismatch) {
    makeSession();
    makeActions();
    ASSERT_EQ(suggest("/interaction_profiles/oculus/touch_controller", "/user/hand/right/input/trigger/value"), XR_SUCCESS);
    ASSERT_EQ(attach(), XR_SUCCESS);
    XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
    get.action = trigger;
    XrActionStateBoolean state{XR_TYPE_ACTION_STATE_BOOLEAN};
    EXPECT_EQ(xrGetActionStateBoolean(session, &get, &state), XR_ERROR_ACTION_TYPE_MISMATCH);
}

}  // namespace
}  // namespace hg::xr::test
