#include "xr/controllers.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

#include "xr/xr_result.h"

namespace hg::xr {

namespace {

constexpr float kHapticSeconds = 0.03f;

garden::Pose toPose(const XrPosef& p, float floorOffset) {
    garden::Pose g;
    g.position = glm::vec3(p.position.x, p.position.y + floorOffset, p.position.z);
    g.orientation = glm::quat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
    return g;
}

}  // namespace

Controllers::Controllers(XrInstance instance, bool leftHanded) : instance_(instance), leftHanded_(leftHanded) {
    check(xrStringToPath(instance_, "/user/hand/left", &hands_[0]), "xrStringToPath");
    check(xrStringToPath(instance_, "/user/hand/right", &hands_[1]), "xrStringToPath");
    XrActionSetCreateInfo set{XR_TYPE_ACTION_SET_CREATE_INFO};
    std::snprintf(set.actionSetName, XR_MAX_ACTION_SET_NAME_SIZE, "garden");
    std::snprintf(set.localizedActionSetName, XR_MAX_LOCALIZED_ACTION_SET_NAME_SIZE, "Garden");
    check(xrCreateActionSet(instance_, &set, &set_), "xrCreateActionSet");
    grip_ = makeAction("grip_pose", "Hand grip", XR_ACTION_TYPE_POSE_INPUT);
    aim_ = makeAction("aim_pose", "Hand aim", XR_ACTION_TYPE_POSE_INPUT);
    trigger_ = makeAction("trigger", "Tool (trigger)", XR_ACTION_TYPE_FLOAT_INPUT);
    squeeze_ = makeAction("squeeze", "Grab the world (squeeze)", XR_ACTION_TYPE_FLOAT_INPUT);
    thumbstick_ = makeAction("thumbstick", "Move and turn", XR_ACTION_TYPE_VECTOR2F_INPUT);
    primary_ = makeAction("primary", "Primary button", XR_ACTION_TYPE_BOOLEAN_INPUT);
    secondary_ = makeAction("secondary", "Secondary button", XR_ACTION_TYPE_BOOLEAN_INPUT);
    menu_ = makeAction("menu", "Menu", XR_ACTION_TYPE_BOOLEAN_INPUT);
    stickClick_ = makeAction("thumbstick_click", "Walk or fly", XR_ACTION_TYPE_BOOLEAN_INPUT);
    haptic_ = makeAction("haptic", "Touching material", XR_ACTION_TYPE_VIBRATION_OUTPUT);

    // Per profile: (action, component) for both hands, then one-hand extras.
    using Bind = std::pair<XrAction, const char*>;
    const Bind poses[] = {{grip_, "input/grip/pose"}, {aim_, "input/aim/pose"}, {haptic_, "output/haptic"}};
    struct Profile {
        const char* path;
        std::vector<Bind> both;
        std::vector<Bind> left, right;
    };
    const std::vector<Profile> profiles = {
        {"/interaction_profiles/khr/simple_controller",
         {{trigger_, "input/select/click"}, {menu_, "input/menu/click"}}, {}, {}},
        {"/interaction_profiles/oculus/touch_controller",
         {{trigger_, "input/trigger/value"}, {squeeze_, "input/squeeze/value"}, {thumbstick_, "input/thumbstick"},
          {stickClick_, "input/thumbstick/click"}},
         {{primary_, "input/x/click"}, {secondary_, "input/y/click"}, {menu_, "input/menu/click"}},
         {{primary_, "input/a/click"}, {secondary_, "input/b/click"}}},
        {"/interaction_profiles/valve/index_controller",
         {{trigger_, "input/trigger/value"}, {squeeze_, "input/squeeze/value"}, {thumbstick_, "input/thumbstick"},
          {stickClick_, "input/thumbstick/click"}, {primary_, "input/a/click"}, {secondary_, "input/b/click"}},
         {}, {}},
        {"/interaction_profiles/microsoft/motion_controller",
         {{trigger_, "input/trigger/value"}, {squeeze_, "input/squeeze/click"}, {thumbstick_, "input/thumbstick"},
          {stickClick_, "input/thumbstick/click"}, {primary_, "input/trackpad/click"}, {menu_, "input/menu/click"}},
         {}, {}},
        {"/interaction_profiles/htc/vive_controller",
         {{trigger_, "input/trigger/value"}, {squeeze_, "input/squeeze/click"}, {thumbstick_, "input/trackpad"},
          {stickClick_, "input/trackpad/click"}, {menu_, "input/menu/click"}},
         {}, {}},
    };
    for (const Profile& p : profiles) {
        std::vector<XrActionSuggestedBinding> bindings;
        const auto add = [&](XrAction a, const char* hand, const char* component) {
            XrActionSuggestedBinding b{a, XR_NULL_PATH};
            const std::string path = std::string("/user/hand/") + hand + "/" + component;
            check(xrStringToPath(instance_, path.c_str(), &b.binding), "xrStringToPath");
            bindings.push_back(b);
        };
        for (const char* hand : {"left", "right"}) {
            for (const Bind& b : poses) add(b.first, hand, b.second);
            for (const Bind& b : p.both) add(b.first, hand, b.second);
        }
        for (const Bind& b : p.left) add(b.first, "left", b.second);
        for (const Bind& b : p.right) add(b.first, "right", b.second);
        XrInteractionProfileSuggestedBinding suggested{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
        check(xrStringToPath(instance_, p.path, &suggested.interactionProfile), "xrStringToPath");
        suggested.countSuggestedBindings = static_cast<uint32_t>(bindings.size());
        suggested.suggestedBindings = bindings.data();
        check(xrSuggestInteractionProfileBindings(instance_, &suggested), "xrSuggestInteractionProfileBindings");
    }
}

Controllers::~Controllers() {
    for (auto* spaces : {&gripSpaces_, &aimSpaces_})
        for (XrSpace s : *spaces)
            if (s != XR_NULL_HANDLE && session_ != XR_NULL_HANDLE) xrDestroySpace(s);
    if (set_ != XR_NULL_HANDLE) xrDestroyActionSet(set_);
}

XrAction Controllers::makeAction(const char* name, const char* localized, XrActionType type) {
    XrActionCreateInfo info{XR_TYPE_ACTION_CREATE_INFO};
    std::snprintf(info.actionName, XR_MAX_ACTION_NAME_SIZE, "%s", name);
    std::snprintf(info.localizedActionName, XR_MAX_LOCALIZED_ACTION_NAME_SIZE, "%s", localized);
    info.actionType = type;
    info.countSubactionPaths = 2;
    info.subactionPaths = hands_.data();
    XrAction a = XR_NULL_HANDLE;
    check(xrCreateAction(set_, &info, &a), "xrCreateAction");
    return a;
}

void Controllers::attach(XrSession session) {
    session_ = session;
    XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    attach.countActionSets = 1;
    attach.actionSets = &set_;
    check(xrAttachSessionActionSets(session_, &attach), "xrAttachSessionActionSets");
    for (std::size_t h = 0; h < 2; ++h) {
        XrActionSpaceCreateInfo info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
        info.subactionPath = hands_[h];
        info.poseInActionSpace.orientation.w = 1.0f;
        info.action = grip_;
        check(xrCreateActionSpace(session_, &info, &gripSpaces_[h]), "xrCreateActionSpace");
        info.action = aim_;
        check(xrCreateActionSpace(session_, &info, &aimSpaces_[h]), "xrCreateActionSpace");
    }
}

void Controllers::refreshProfile() {
    XrInteractionProfileState state{XR_TYPE_INTERACTION_PROFILE_STATE};
    check(xrGetCurrentInteractionProfile(session_, hands_[leftHanded_ ? 0 : 1], &state), "xrGetCurrentInteractionProfile");
    profile_.clear();
    if (state.interactionProfile == XR_NULL_PATH) return;
    char text[XR_MAX_PATH_LENGTH];
    uint32_t n = 0;
    check(xrPathToString(instance_, state.interactionProfile, sizeof text, &n, text), "xrPathToString");
    profile_ = text;
}

std::string Controllers::interactionProfile() const { return profile_; }

float Controllers::readFloat(XrAction a, int hand) const {
    XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
    get.action = a;
    get.subactionPath = hands_[static_cast<std::size_t>(hand)];
    XrActionStateFloat s{XR_TYPE_ACTION_STATE_FLOAT};
    check(xrGetActionStateFloat(session_, &get, &s), "xrGetActionStateFloat");
    return s.isActive ? s.currentState : 0.0f;
}

bool Controllers::readBool(XrAction a, int hand) const {
    XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
    get.action = a;
    get.subactionPath = hands_[static_cast<std::size_t>(hand)];
    XrActionStateBoolean s{XR_TYPE_ACTION_STATE_BOOLEAN};
    check(xrGetActionStateBoolean(session_, &get, &s), "xrGetActionStateBoolean");
    return s.isActive && s.currentState;
}

garden::HandState Controllers::readHand(int hand, XrSpace space, XrTime time, float floorOffset) {
    garden::HandState h;
    const auto index = static_cast<std::size_t>(hand);
    XrSpaceLocation grip{XR_TYPE_SPACE_LOCATION}, aim{XR_TYPE_SPACE_LOCATION};
    check(xrLocateSpace(gripSpaces_[index], space, time, &grip), "xrLocateSpace");
    check(xrLocateSpace(aimSpaces_[index], space, time, &aim), "xrLocateSpace");
    const XrSpaceLocationFlags valid = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT;
    h.tracked = (grip.locationFlags & valid) == valid && (aim.locationFlags & valid) == valid;
    if (!h.tracked) return h;
    h.grip = toPose(grip.pose, floorOffset);
    h.aim = toPose(aim.pose, floorOffset);
    h.trigger = readFloat(trigger_, hand);
    // The trigger's depth past the press threshold (0.5, where the tool
    // acts) is the pen's pressure: a light pull 0.1, all the way in 1.
    h.pressure = 0.1f + 0.9f * std::clamp((h.trigger - 0.5f) / 0.5f, 0.0f, 1.0f);
    h.squeeze = readFloat(squeeze_, hand);
    XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
    get.action = thumbstick_;
    get.subactionPath = hands_[index];
    XrActionStateVector2f stick{XR_TYPE_ACTION_STATE_VECTOR2F};
    check(xrGetActionStateVector2f(session_, &get, &stick), "xrGetActionStateVector2f");
    if (stick.isActive) h.thumbstick = glm::vec2(stick.currentState.x, stick.currentState.y);
    const bool tool = hand == (leftHanded_ ? 0 : 1);
    if (readBool(primary_, hand)) h.buttons |= tool ? garden::kButtonRedo : garden::kButtonPrimary;
    if (readBool(secondary_, hand)) h.buttons |= tool ? garden::kButtonUndo : garden::kButtonSecondary;
    if (readBool(menu_, hand)) h.buttons |= garden::kButtonMenu;
    if (readBool(stickClick_, hand)) h.buttons |= garden::kButtonThumbstick;
    return h;
}

garden::Hands Controllers::read(XrSpace space, XrTime time, float floorOffset, bool focused) {
    garden::Hands hands;
    if (!focused) return hands;
    XrActiveActionSet active{set_, XR_NULL_PATH};
    XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    if (check(xrSyncActions(session_, &sync), "xrSyncActions") != XR_SUCCESS) return hands;
    const int tool = leftHanded_ ? 0 : 1;
    hands.tool = readHand(tool, space, time, floorOffset);
    hands.navigation = readHand(1 - tool, space, time, floorOffset);
    // The gesture button: the other hand's trigger held while the tool hand
    // points and draws (the navigation hand's trigger has no other use).
    if (hands.navigation.tracked && hands.navigation.trigger > 0.5f) hands.tool.buttons |= garden::kButtonGesture;
    return hands;
}

void Controllers::pulseToolHand() {
    XrHapticActionInfo info{XR_TYPE_HAPTIC_ACTION_INFO};
    info.action = haptic_;
    info.subactionPath = hands_[leftHanded_ ? 0 : 1];
    XrHapticVibration v{XR_TYPE_HAPTIC_VIBRATION};
    v.duration = static_cast<XrDuration>(kHapticSeconds * 1e9f);
    v.frequency = XR_FREQUENCY_UNSPECIFIED;
    v.amplitude = 0.6f;
    check(xrApplyHapticFeedback(session_, &info, reinterpret_cast<const XrHapticBaseHeader*>(&v)), "xrApplyHapticFeedback");
}

}  // namespace hg::xr

namespace hg::xr {

void Controllers::setLeftHanded(bool leftHanded) {
    if (leftHanded == leftHanded_) return;
    leftHanded_ = leftHanded;
    if (session_ != XR_NULL_HANDLE) refreshProfile();  // the profile shown is the tool hand's
}

}  // namespace hg::xr
