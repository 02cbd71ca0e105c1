// The mock runtime's input (docs/xr.md): paths, action sets and actions,
// suggested bindings, and the controllers, which play a replay script's
// hands (docs/replay-format.md: the tool hand is the right controller, the
// navigation hand the left). The mock's controllers are Oculus Touch
// controllers; an app that suggests no Touch bindings gets
// khr/simple_controller when it suggested those.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "garden/scene/json_reader.h"
#include "xr/mock_runtime/mock_state.h"

namespace hg::xr::mock {

namespace {

const char* const kTouch = "/interaction_profiles/oculus/touch_controller";
const char* const kSimple = "/interaction_profiles/khr/simple_controller";

// What each profile offers per hand (after /user/hand/{left,right}), for the
// check of suggested bindings. Other known profiles are checked by prefix.
const std::vector<std::string> kTouchLeft = {
    "/input/x/click", "/input/x/touch", "/input/y/click", "/input/y/touch", "/input/menu/click",
    "/input/squeeze/value", "/input/trigger/value", "/input/trigger/touch", "/input/thumbstick",
    "/input/thumbstick/x", "/input/thumbstick/y", "/input/thumbstick/click", "/input/thumbstick/touch",
    "/input/thumbrest/touch", "/input/grip/pose", "/input/aim/pose", "/output/haptic"};
const std::vector<std::string> kTouchRight = {
    "/input/a/click", "/input/a/touch", "/input/b/click", "/input/b/touch", "/input/system/click",
    "/input/squeeze/value", "/input/trigger/value", "/input/trigger/touch", "/input/thumbstick",
    "/input/thumbstick/x", "/input/thumbstick/y", "/input/thumbstick/click", "/input/thumbstick/touch",
    "/input/thumbrest/touch", "/input/grip/pose", "/input/aim/pose", "/output/haptic"};
const std::vector<std::string> kSimpleHand = {"/input/select/click", "/input/menu/click", "/input/grip/pose",
                                              "/input/aim/pose", "/output/haptic"};
const std::vector<std::string> kOtherProfiles = {
    "/interaction_profiles/valve/index_controller", "/interaction_profiles/microsoft/motion_controller",
    "/interaction_profiles/htc/vive_controller", "/interaction_profiles/google/daydream_controller",
    "/interaction_profiles/htc/vive_pro", "/interaction_profiles/microsoft/xbox_controller",
    "/interaction_profiles/oculus/go_controller", "/interaction_profiles/valve/index_controller"};

ActionSet* asSet(XrActionSet h) { return reinterpret_cast<ActionSet*>(h); }
Action* asAction(XrAction h) { return reinterpret_cast<Action*>(h); }

bool validPathString(const std::string& s) {
    if (s.size() < 2 || s[0] != '/' || s.back() == '/') return false;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') return false;
        if (!(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' ||
              c == '_' || c == '.' || c == '/'))
            return false;
    }
    return true;
}

bool validName(const char* name) {
    if (!name || !*name) return false;
    for (const char* c = name; *c; ++c)
        if (!(std::islower(static_cast<unsigned char>(*c)) || std::isdigit(static_cast<unsigned char>(*c)) || *c == '-' ||
              *c == '_' || *c == '.'))
            return false;
    return true;
}

bool bindingAllowed(const std::string& profile, const std::string& binding) {
    const bool left = binding.rfind("/user/hand/left/", 0) == 0, right = binding.rfind("/user/hand/right/", 0) == 0;
    if (!left && !right) return false;
    const std::string rest = binding.substr(left ? 15 : 16);
    const auto in = [&](const std::vector<std::string>& v) { return std::find(v.begin(), v.end(), rest) != v.end(); };
    if (profile == kTouch) return in(left ? kTouchLeft : kTouchRight);
    if (profile == kSimple) return in(kSimpleHand);
    return rest.rfind("/input/", 0) == 0 || rest == "/output/haptic";
}

// Where the script's buttons go on a Touch controller: primary (and redo)
// on A / X, secondary (and undo) on B / Y.
bool buttonValue(const garden::HandState& h, const std::string& component) {
    if (component == "/input/a/click" || component == "/input/x/click")
        return h.pressed(garden::kButtonPrimary) || h.pressed(garden::kButtonRedo);
    if (component == "/input/b/click" || component == "/input/y/click")
        return h.pressed(garden::kButtonSecondary) || h.pressed(garden::kButtonUndo);
    if (component == "/input/menu/click") return h.pressed(garden::kButtonMenu);
    if (component == "/input/thumbstick/click") return h.pressed(garden::kButtonThumbstick);
    if (component == "/input/select/click" || component == "/input/trigger/click") return h.trigger > 0.5f;
    if (component == "/input/squeeze/click") return h.squeeze > 0.5f;
    return false;
}

float floatValue(const garden::HandState& h, const std::string& component) {
    if (component == "/input/trigger/value") return h.trigger;
    if (component == "/input/squeeze/value") return h.squeeze;
    if (component == "/input/thumbstick/x") return h.thumbstick.x;
    if (component == "/input/thumbstick/y") return h.thumbstick.y;
    return buttonValue(h, component) ? 1.0f : 0.0f;
}

// One action's value on the hands that `subaction` selects (both when
// null): the largest magnitude over its bindings, as the spec combines them.
struct Value {
    bool active = false;
    float scalar = 0.0f;
    XrVector2f vec{0.0f, 0.0f};
};

Value evaluate(const Action& a, const garden::Hands& hands, XrPath subaction) {
    Value v;
    const std::string* sub = pathString(subaction);
    for (const std::string& b : a.bindings) {
        const bool left = b.rfind("/user/hand/left/", 0) == 0;
        if (sub && b.rfind(*sub + "/", 0) != 0) continue;
        const garden::HandState& h = left ? hands.navigation : hands.tool;
        if (!h.tracked) continue;
        v.active = true;
        const std::string component = b.substr(left ? 15 : 16);
        if (a.type == XR_ACTION_TYPE_VECTOR2F_INPUT) {
            if (component == "/input/thumbstick" || component == "/input/trackpad") {
                if (std::hypot(h.thumbstick.x, h.thumbstick.y) > std::hypot(v.vec.x, v.vec.y))
                    v.vec = {h.thumbstick.x, h.thumbstick.y};
            }
        } else {
            const float f = a.type == XR_ACTION_TYPE_BOOLEAN_INPUT ? (floatValue(h, component) > 0.5f ? 1.0f : 0.0f)
                                                                     : floatValue(h, component);
            if (std::abs(f) > std::abs(v.scalar)) v.scalar = f;
        }
    }
    return v;
}

// The common checks of xrGetActionState*: "" or the error.
XrResult checkStateCall(XrSession session, const XrActionStateGetInfo* info, XrActionType type, const Action** action) {
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!info || info->type != XR_TYPE_ACTION_STATE_GET_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (!isLive(rt.actions, info->action)) return XR_ERROR_HANDLE_INVALID;
    const Action* a = asAction(info->action);
    if (!asSession(session)->attached.count(a->set)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (a->type != type) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (info->subactionPath != XR_NULL_PATH &&
        std::find(a->subactions.begin(), a->subactions.end(), info->subactionPath) == a->subactions.end())
        return XR_ERROR_PATH_UNSUPPORTED;
    *action = a;
    return XR_SUCCESS;
}

bool focused(const Session& s) { return s.state == XR_SESSION_STATE_FOCUSED && s.syncCount > 0; }

// --- paths -----------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL stringToPath(XrInstance instance, const char* string, XrPath* path) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (!string || !path) return XR_ERROR_VALIDATION_FAILURE;
    if (!validPathString(string)) return XR_ERROR_PATH_FORMAT_INVALID;
    *path = pathOf(string);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL pathToString(XrInstance instance, XrPath path, uint32_t capacity, uint32_t* count,
                                            char* buffer) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().instances, instance)) return XR_ERROR_HANDLE_INVALID;
    const std::string* s = pathString(path);
    if (!s || !count) return s ? XR_ERROR_VALIDATION_FAILURE : XR_ERROR_PATH_INVALID;
    *count = static_cast<uint32_t>(s->size() + 1);
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < *count) return XR_ERROR_SIZE_INSUFFICIENT;
    std::memcpy(buffer, s->c_str(), *count);
    return XR_SUCCESS;
}

// --- action sets and actions -----------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL createActionSet(XrInstance instance, const XrActionSetCreateInfo* info, XrActionSet* out) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (!info || !out || info->type != XR_TYPE_ACTION_SET_CREATE_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (!validName(info->actionSetName)) return XR_ERROR_PATH_FORMAT_INVALID;
    if (info->localizedActionSetName[0] == '\0') return XR_ERROR_LOCALIZED_NAME_INVALID;
    for (const ActionSet* s : rt.actionSets)
        if (s->name == info->actionSetName) return XR_ERROR_NAME_DUPLICATED;
    auto set = std::make_unique<ActionSet>();
    set->name = info->actionSetName;
    *out = reinterpret_cast<XrActionSet>(set.get());
    rt.actionSets.insert(set.release());
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroyActionSet(XrActionSet set) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.actionSets, set)) return XR_ERROR_HANDLE_INVALID;
    for (Action* a : asSet(set)->actions) {
        rt.actions.erase(a);
        delete a;
    }
    for (Session* s : rt.sessions) s->attached.erase(asSet(set));
    rt.actionSets.erase(asSet(set));
    delete asSet(set);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL createAction(XrActionSet set, const XrActionCreateInfo* info, XrAction* out) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.actionSets, set)) return XR_ERROR_HANDLE_INVALID;
    if (!info || !out || info->type != XR_TYPE_ACTION_CREATE_INFO) return XR_ERROR_VALIDATION_FAILURE;
    ActionSet& s = *asSet(set);
    if (s.attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    if (!validName(info->actionName)) return XR_ERROR_PATH_FORMAT_INVALID;
    if (info->localizedActionName[0] == '\0') return XR_ERROR_LOCALIZED_NAME_INVALID;
    for (const Action* a : s.actions)
        if (a->name == info->actionName) return XR_ERROR_NAME_DUPLICATED;
    switch (info->actionType) {
        case XR_ACTION_TYPE_BOOLEAN_INPUT: case XR_ACTION_TYPE_FLOAT_INPUT: case XR_ACTION_TYPE_VECTOR2F_INPUT:
        case XR_ACTION_TYPE_POSE_INPUT: case XR_ACTION_TYPE_VIBRATION_OUTPUT: break;
        default: return XR_ERROR_VALIDATION_FAILURE;
    }
    auto a = std::make_unique<Action>();
    a->set = &s;
    a->name = info->actionName;
    a->type = info->actionType;
    for (uint32_t i = 0; i < info->countSubactionPaths; ++i) {
        const std::string* p = pathString(info->subactionPaths[i]);
        if (!p || (*p != "/user/hand/left" && *p != "/user/hand/right" && *p != "/user/head" && *p != "/user/gamepad"))
            return XR_ERROR_PATH_UNSUPPORTED;
        a->subactions.push_back(info->subactionPaths[i]);
    }
    *out = reinterpret_cast<XrAction>(a.get());
    s.actions.push_back(a.get());
    rt.actions.insert(a.release());
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroyAction(XrAction action) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.actions, action)) return XR_ERROR_HANDLE_INVALID;
    Action* a = asAction(action);
    auto& v = a->set->actions;
    v.erase(std::remove(v.begin(), v.end(), a), v.end());
    rt.actions.erase(a);
    delete a;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL suggestBindings(XrInstance instance, const XrInteractionProfileSuggestedBinding* info) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.instances, instance)) return XR_ERROR_HANDLE_INVALID;
    if (!info || info->type != XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING || info->countSuggestedBindings == 0 ||
        !info->suggestedBindings)
        return XR_ERROR_VALIDATION_FAILURE;
    const std::string* profile = pathString(info->interactionProfile);
    if (!profile) return XR_ERROR_PATH_INVALID;
    if (*profile != kTouch && *profile != kSimple &&
        std::find(kOtherProfiles.begin(), kOtherProfiles.end(), *profile) == kOtherProfiles.end())
        return XR_ERROR_PATH_UNSUPPORTED;
    std::vector<std::pair<Action*, XrPath>> bindings;
    for (uint32_t i = 0; i < info->countSuggestedBindings; ++i) {
        const XrActionSuggestedBinding& b = info->suggestedBindings[i];
        if (!isLive(rt.actions, b.action)) return XR_ERROR_HANDLE_INVALID;
        if (asAction(b.action)->set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
        const std::string* path = pathString(b.binding);
        if (!path) return XR_ERROR_PATH_INVALID;
        if (!bindingAllowed(*profile, *path)) return XR_ERROR_PATH_UNSUPPORTED;
        bindings.emplace_back(asAction(b.action), b.binding);
    }
    rt.suggested[info->interactionProfile] = bindings;  // replaces an earlier suggestion
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL attachActionSets(XrSession session, const XrSessionActionSetsAttachInfo* info) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!info || info->type != XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO || info->countActionSets == 0)
        return XR_ERROR_VALIDATION_FAILURE;
    Session& s = *asSession(session);
    if (!s.attached.empty()) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    for (uint32_t i = 0; i < info->countActionSets; ++i)
        if (!isLive(rt.actionSets, info->actionSets[i])) return XR_ERROR_HANDLE_INVALID;
    // The Touch bindings when suggested, else the simple controller's.
    XrPath profile = XR_NULL_PATH;
    for (const char* p : {kTouch, kSimple})
        if (rt.suggested.count(pathOf(p))) {
            profile = pathOf(p);
            break;
        }
    for (uint32_t i = 0; i < info->countActionSets; ++i) {
        ActionSet* set = asSet(info->actionSets[i]);
        set->attached = true;
        s.attached.insert(set);
        for (Action* a : set->actions) a->bindings.clear();
    }
    if (profile != XR_NULL_PATH) {
        for (const auto& [action, binding] : rt.suggested[profile])
            if (s.attached.count(action->set)) action->bindings.push_back(*pathString(binding));
        s.profile = profile;
        rt.log.profile = *pathString(profile);
        XrEventDataInteractionProfileChanged e{};
        e.type = XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED;
        e.session = session;
        XrEventDataBuffer b{};
        std::memcpy(&b, &e, sizeof e);
        rt.events.push_back(b);
    }
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL getCurrentInteractionProfile(XrSession session, XrPath topLevel,
                                                            XrInteractionProfileState* state) {
    Lock lock(runtime().mutex);
    if (!isLive(runtime().sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!state || state->type != XR_TYPE_INTERACTION_PROFILE_STATE) return XR_ERROR_VALIDATION_FAILURE;
    const Session& s = *asSession(session);
    if (s.attached.empty()) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    const std::string* p = pathString(topLevel);
    if (!p || (*p != "/user/hand/left" && *p != "/user/hand/right" && *p != "/user/head" && *p != "/user/gamepad"))
        return XR_ERROR_PATH_UNSUPPORTED;
    state->interactionProfile = (*p == "/user/hand/left" || *p == "/user/hand/right") ? s.profile : XR_NULL_PATH;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL syncActions(XrSession session, const XrActionsSyncInfo* info) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!info || info->type != XR_TYPE_ACTIONS_SYNC_INFO) return XR_ERROR_VALIDATION_FAILURE;
    Session& s = *asSession(session);
    for (uint32_t i = 0; i < info->countActiveActionSets; ++i) {
        if (!isLive(rt.actionSets, info->activeActionSets[i].actionSet)) return XR_ERROR_HANDLE_INVALID;
        if (!s.attached.count(asSet(info->activeActionSets[i].actionSet))) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    }
    if (s.lossPending) return XR_SESSION_LOSS_PENDING;
    if (s.state != XR_SESSION_STATE_FOCUSED) return XR_SESSION_NOT_FOCUSED;
    ++s.syncCount;
    return XR_SUCCESS;
}

template <typename State>
void fillCommon(State* state, bool active, bool changed) {
    state->isActive = active ? XR_TRUE : XR_FALSE;
    state->changedSinceLastSync = changed ? XR_TRUE : XR_FALSE;
    state->lastChangeTime = 0;
}

XRAPI_ATTR XrResult XRAPI_CALL getBoolean(XrSession session, const XrActionStateGetInfo* info, XrActionStateBoolean* state) {
    Lock lock(runtime().mutex);
    const Action* a = nullptr;
    if (XrResult r = checkStateCall(session, info, XR_ACTION_TYPE_BOOLEAN_INPUT, &a); r != XR_SUCCESS) return r;
    if (!state || state->type != XR_TYPE_ACTION_STATE_BOOLEAN) return XR_ERROR_VALIDATION_FAILURE;
    const Session& s = *asSession(session);
    const Value now = focused(s) ? evaluate(*a, scriptedHands(s, false), info->subactionPath) : Value{};
    const Value before = focused(s) ? evaluate(*a, scriptedHands(s, true), info->subactionPath) : Value{};
    state->currentState = now.scalar > 0.5f ? XR_TRUE : XR_FALSE;
    fillCommon(state, now.active, (now.scalar > 0.5f) != (before.scalar > 0.5f));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL getFloat(XrSession session, const XrActionStateGetInfo* info, XrActionStateFloat* state) {
    Lock lock(runtime().mutex);
    const Action* a = nullptr;
    if (XrResult r = checkStateCall(session, info, XR_ACTION_TYPE_FLOAT_INPUT, &a); r != XR_SUCCESS) return r;
    if (!state || state->type != XR_TYPE_ACTION_STATE_FLOAT) return XR_ERROR_VALIDATION_FAILURE;
    const Session& s = *asSession(session);
    const Value now = focused(s) ? evaluate(*a, scriptedHands(s, false), info->subactionPath) : Value{};
    const Value before = focused(s) ? evaluate(*a, scriptedHands(s, true), info->subactionPath) : Value{};
    state->currentState = now.scalar;
    fillCommon(state, now.active, now.scalar != before.scalar);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL getVector2f(XrSession session, const XrActionStateGetInfo* info,
                                           XrActionStateVector2f* state) {
    Lock lock(runtime().mutex);
    const Action* a = nullptr;
    if (XrResult r = checkStateCall(session, info, XR_ACTION_TYPE_VECTOR2F_INPUT, &a); r != XR_SUCCESS) return r;
    if (!state || state->type != XR_TYPE_ACTION_STATE_VECTOR2F) return XR_ERROR_VALIDATION_FAILURE;
    const Session& s = *asSession(session);
    const Value now = focused(s) ? evaluate(*a, scriptedHands(s, false), info->subactionPath) : Value{};
    const Value before = focused(s) ? evaluate(*a, scriptedHands(s, true), info->subactionPath) : Value{};
    state->currentState = now.vec;
    fillCommon(state, now.active, now.vec.x != before.vec.x || now.vec.y != before.vec.y);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL getPose(XrSession session, const XrActionStateGetInfo* info, XrActionStatePose* state) {
    Lock lock(runtime().mutex);
    const Action* a = nullptr;
    if (XrResult r = checkStateCall(session, info, XR_ACTION_TYPE_POSE_INPUT, &a); r != XR_SUCCESS) return r;
    if (!state || state->type != XR_TYPE_ACTION_STATE_POSE) return XR_ERROR_VALIDATION_FAILURE;
    const Session& s = *asSession(session);
    state->isActive = focused(s) && evaluate(*a, scriptedHands(s, false), info->subactionPath).active ? XR_TRUE : XR_FALSE;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL createActionSpace(XrSession session, const XrActionSpaceCreateInfo* info, XrSpace* out) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!info || !out || info->type != XR_TYPE_ACTION_SPACE_CREATE_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (!isLive(rt.actions, info->action)) return XR_ERROR_HANDLE_INVALID;
    Action* a = asAction(info->action);
    if (a->type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (info->subactionPath != XR_NULL_PATH &&
        std::find(a->subactions.begin(), a->subactions.end(), info->subactionPath) == a->subactions.end())
        return XR_ERROR_PATH_UNSUPPORTED;
    auto sp = std::make_unique<Space>();
    sp->session = asSession(session);
    sp->isAction = true;
    sp->action = a;
    sp->subaction = info->subactionPath;
    sp->offset = info->poseInActionSpace;
    *out = reinterpret_cast<XrSpace>(sp.get());
    rt.spaces.insert(sp.release());
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL applyHaptic(XrSession session, const XrHapticActionInfo* info,
                                           const XrHapticBaseHeader* feedback) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!info || !feedback || info->type != XR_TYPE_HAPTIC_ACTION_INFO || feedback->type != XR_TYPE_HAPTIC_VIBRATION)
        return XR_ERROR_VALIDATION_FAILURE;
    if (!isLive(rt.actions, info->action)) return XR_ERROR_HANDLE_INVALID;
    const Action* a = asAction(info->action);
    if (!asSession(session)->attached.count(a->set)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (a->type != XR_ACTION_TYPE_VIBRATION_OUTPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (asSession(session)->state != XR_SESSION_STATE_FOCUSED) return XR_SESSION_NOT_FOCUSED;
    ++rt.log.hapticPulses;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL stopHaptic(XrSession session, const XrHapticActionInfo* info) {
    Lock lock(runtime().mutex);
    Runtime& rt = runtime();
    if (!isLive(rt.sessions, session)) return XR_ERROR_HANDLE_INVALID;
    if (!info || info->type != XR_TYPE_HAPTIC_ACTION_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (!isLive(rt.actions, info->action)) return XR_ERROR_HANDLE_INVALID;
    const Action* a = asAction(info->action);
    if (!asSession(session)->attached.count(a->set)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (a->type != XR_ACTION_TYPE_VIBRATION_OUTPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    return XR_SUCCESS;
}

}  // namespace

XrPath pathOf(const std::string& s) {
    Runtime& rt = runtime();
    const auto it = rt.pathIds.find(s);
    if (it != rt.pathIds.end()) return it->second;
    rt.paths.push_back(s);
    const XrPath id = rt.paths.size() - 1;
    rt.pathIds[s] = id;
    return id;
}

const std::string* pathString(XrPath p) {
    const Runtime& rt = runtime();
    return p == XR_NULL_PATH || p >= rt.paths.size() ? nullptr : &rt.paths[p];
}

garden::Hands scriptedHands(const Session& s, bool previous) {
    const Runtime& rt = runtime();
    if (!rt.script || s.syncCount == 0) return {};
    if (previous && s.syncCount == 1) return {};
    long long frame = static_cast<long long>(s.syncCount) - (previous ? 2 : 1);
    for (const garden::ReplayStep& step : rt.script->steps) {
        if (frame < step.frames) return step.hands;
        frame -= step.frames;
    }
    return {};  // after the script: both controllers put down (untracked)
}

void loadScriptFromEnvironment(Runtime& rt) {
    rt.script.reset();
    rt.scriptError.clear();
    const char* path = std::getenv("HG_MOCK_XR_SCRIPT");
    if (!path || !*path) return;
    try {
        rt.script = garden::loadReplayScript(path);
    } catch (const garden::JsonError& e) {
        rt.scriptError = std::string("HG_MOCK_XR_SCRIPT ") + path + ": " + e.what();
    }
}

void addInputFunctions(FunctionTable& t) {
    t["xrStringToPath"] = entry(stringToPath);
    t["xrPathToString"] = entry(pathToString);
    t["xrCreateActionSet"] = entry(createActionSet);
    t["xrDestroyActionSet"] = entry(destroyActionSet);
    t["xrCreateAction"] = entry(createAction);
    t["xrDestroyAction"] = entry(destroyAction);
    t["xrSuggestInteractionProfileBindings"] = entry(suggestBindings);
    t["xrAttachSessionActionSets"] = entry(attachActionSets);
    t["xrGetCurrentInteractionProfile"] = entry(getCurrentInteractionProfile);
    t["xrSyncActions"] = entry(syncActions);
    t["xrGetActionStateBoolean"] = entry(getBoolean);
    t["xrGetActionStateFloat"] = entry(getFloat);
    t["xrGetActionStateVector2f"] = entry(getVector2f);
    t["xrGetActionStatePose"] = entry(getPose);
    t["xrCreateActionSpace"] = entry(createActionSpace);
    t["xrApplyHapticFeedback"] = entry(applyHaptic);
    t["xrStopHapticFeedback"] = entry(stopHaptic);
}

}  // namespace hg::xr::mock
