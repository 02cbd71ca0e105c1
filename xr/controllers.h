// The two controllers as OpenXR actions (docs/design.md §8): one action set with
// both hands as subaction paths, grip and aim poses, trigger, squeeze,
// thumbstick, primary and secondary buttons, menu, stick click and a haptic
// output; suggested bindings for khr/simple_controller,
// oculus/touch_controller, valve/index_controller,
// microsoft/motion_controller and htc/vive_controller.
//
// Each frame they become the hands every tool reads (garden::Hands, in the
// headset's space: xr_rig.h takes them into the world). The tool hand is the
// right one unless left-handed; on it A (primary) redoes and B (secondary)
// undoes; the navigation hand keeps its primary and secondary buttons.
#pragma once

#include <openxr/openxr.h>

#include <array>
#include <string>

#include "garden/hands/hand_state.h"

namespace hg::xr {

class Controllers {
public:
    // Creates the action set, its actions and the suggested bindings.
    Controllers(XrInstance instance, bool leftHanded);
    ~Controllers();
    Controllers(const Controllers&) = delete;
    Controllers& operator=(const Controllers&) = delete;

    // Attaches the set and makes the pose spaces (once, after the session exists).
    void attach(XrSession session);
    // Syncs the actions and reads both hands, poses located in `space` at
    // `time`, heights raised by `floorOffset`. Untracked hands when the
    // session is not focused.
    garden::Hands read(XrSpace space, XrTime time, float floorOffset, bool focused);
    // Which hand holds the tool, from the next read on (the hand panel's switch).
    void setLeftHanded(bool leftHanded);
    // A short pulse on the tool hand (a tool starting to touch material).
    void pulseToolHand();
    // The interaction profile the runtime picked ("" : none yet), for the panel.
    std::string interactionProfile() const;
    // Asked again after XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED.
    void refreshProfile();

private:
    XrAction makeAction(const char* name, const char* localized, XrActionType type);
    garden::HandState readHand(int hand, XrSpace space, XrTime time, float floorOffset);
    float readFloat(XrAction a, int hand) const;
    bool readBool(XrAction a, int hand) const;

    XrInstance instance_;
    XrSession session_ = XR_NULL_HANDLE;
    bool leftHanded_;
    std::array<XrPath, 2> hands_{};  // left, right
    XrActionSet set_ = XR_NULL_HANDLE;
    XrAction grip_ = XR_NULL_HANDLE, aim_ = XR_NULL_HANDLE, trigger_ = XR_NULL_HANDLE, squeeze_ = XR_NULL_HANDLE,
             thumbstick_ = XR_NULL_HANDLE, primary_ = XR_NULL_HANDLE, secondary_ = XR_NULL_HANDLE,
             menu_ = XR_NULL_HANDLE, stickClick_ = XR_NULL_HANDLE, haptic_ = XR_NULL_HANDLE;
    std::array<XrSpace, 2> gripSpaces_{}, aimSpaces_{};
    std::string profile_;
};

}  // namespace hg::xr
