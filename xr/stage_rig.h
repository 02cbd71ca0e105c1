// Where the headset's space (the stage: metres, y up, floor at 0) sits in
// the garden's world: an origin on the world's ground, a turn about the
// vertical (the navigator's yaw: 0 looks along -z, positive turns right)
// and a scale (world metres per stage metre: 2 makes the user a giant, the
// world seems half as big). Pure math, so tests check it without a headset.
#pragma once

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "garden/hands/hand_state.h"

namespace hg::xr {

struct StageRig {
    glm::vec3 origin{0.0f};
    float yaw = 0.0f;
    float scale = 1.0f;

    glm::quat rotation() const { return glm::angleAxis(-yaw, glm::vec3(0.0f, 1.0f, 0.0f)); }
    glm::vec3 toWorld(const glm::vec3& stage) const { return origin + rotation() * (scale * stage); }
    garden::Pose toWorld(const garden::Pose& stage) const {
        garden::Pose p;
        p.position = toWorld(stage.position);
        p.orientation = rotation() * stage.orientation;
        return p;
    }
    garden::Hands toWorld(garden::Hands h) const {
        for (garden::HandState* s : {&h.tool, &h.navigation}) {
            s->grip = toWorld(s->grip);
            s->aim = toWorld(s->aim);
        }
        return h;
    }
    // Recentering: the rig that puts a head at `headStage` (its pose in the
    // stage) at the world point `eye` (x, z; the floor at eye.y - eyeHeight)
    // looking along `yaw`. The scale stays.
    StageRig recentered(const garden::Pose& headStage, const glm::vec3& eye, float eyeHeight, float headingYaw) const {
        const glm::vec3 f = headStage.forward();
        StageRig r = *this;
        r.yaw = headingYaw - std::atan2(f.x, -f.z);
        const glm::vec3 floor(eye.x, eye.y - eyeHeight, eye.z);
        r.origin = floor - r.rotation() * (r.scale * glm::vec3(headStage.position.x, 0.0f, headStage.position.z));
        return r;
    }

    // The view matrix of an eye at `stage` (its pose in the stage).
    glm::mat4 viewOf(const garden::Pose& stage) const {
        const garden::Pose w = toWorld(stage);
        return glm::mat4_cast(glm::inverse(w.orientation)) * glm::translate(glm::mat4(1.0f), -w.position);
    }
};

}  // namespace hg::xr
