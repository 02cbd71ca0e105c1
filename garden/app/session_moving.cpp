// GardenSession's move tool (docs/design.md §6: select, move, rotate a sculpture
// with a gizmo): the tool hand's trigger on a sculpture selects it and drags
// it on a horizontal plane (near level, at the distance it was grabbed); held with the secondary button (the desktop's
// Shift), or started on the selected sculpture's ring, the drag turns it
// about its pivot instead. The drag shows live and becomes one undoable,
// journalled move when the trigger lets go.
#include <cmath>

#include <glm/geometric.hpp>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_gizmos.h"
#include "garden/scene/to_glm.h"

namespace hg::garden {

namespace {

constexpr double kPi = 3.14159265358979323846;
// A pointer nearer the pivot than this (metres) gives no usable angle.
constexpr float kMinTurnRadius = 1e-3f;
// Farther than this along the ray, a plane hit is the horizon, not a place.
constexpr float kMaxDragDistance = 1000.0f;
// A ray whose direction rises or falls less than this (about 9 degrees)
// meets a horizontal plane too far or too unsteadily to drag on it.
constexpr float kMinPlaneSlope = 0.15f;

// Where the aim ray meets the horizontal plane y = height, in front of it.
std::optional<glm::vec3> planeHit(const Pose& aim, float height) {
    const glm::vec3 d = aim.forward();
    if (std::fabs(d.y) < 1e-4f) return std::nullopt;
    const float t = (height - aim.position.y) / d.y;
    if (!(t > 0.0f) || t > kMaxDragDistance) return std::nullopt;
    return aim.position + d * t;
}

// The angle of a point about the vertical through `pivot`, counted as the
// placement's yaw is (counter-clockwise seen from above).
std::optional<double> angleAbout(const glm::vec3& pivot, const glm::vec3& p) {
    const float dx = p.x - pivot.x, dz = p.z - pivot.z;
    if (std::hypot(dx, dz) < kMinTurnRadius) return std::nullopt;
    return std::atan2(-static_cast<double>(dz), static_cast<double>(dx));
}

}  // namespace

std::string checkPlacementValues(const Placement& placement) {
    for (double c : placement.position)
        if (!std::isfinite(c)) return "the position is not a finite point";
    if (!std::isfinite(placement.yawDegrees)) return "the yaw is not a finite angle";
    if (!(std::isfinite(placement.scale) && placement.scale >= kMinSculptureScale && placement.scale <= kMaxSculptureScale))
        return "the scale must be in [" + std::to_string(kMinSculptureScale) + ", " + std::to_string(kMaxSculptureScale) +
               "] metres per model unit";
    return "";
}

std::string GardenSession::checkPlacement(int sculpture, const Placement& placement) const {
    if (sculpture < 0 || sculpture >= static_cast<int>(sculptures_.size())) return "no such sculpture";
    return checkPlacementValues(placement);
}

std::string GardenSession::moveSculptureLive(int sculpture, const Placement& placement) {
    if (stroking()) endStroke();
    if (std::string why = checkPlacement(sculpture, placement); !why.empty()) return why;
    if (liveMove_ != sculpture) {
        endLiveMove();
        liveMove_ = sculpture;
        liveMoveFrom_ = sculptures_[static_cast<std::size_t>(sculpture)].placement;
    }
    placeSculpture(sculpture, placement, false);
    return "";
}

void GardenSession::endLiveMove() {
    if (liveMove_ < 0) return;
    const int sculpture = liveMove_;
    liveMove_ = -1;
    if (selected_ == sculpture) select(sculpture);  // the orbit follows, now the hand let go
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    const Placement& to = s.placement;
    const Placement& from = liveMoveFrom_;
    if (to.position == from.position && to.yawDegrees == from.yawDegrees && to.scale == from.scale) return;
    const MoveAction move{s.name, to};
    undoOrder_.push_back(UndoEntry{sculpture, move, from, std::nullopt, std::nullopt});
    redoOrder_.clear();
    record(move);
}

void GardenSession::moveWithHands(const HandState& h) {
    if (!h.tracked || h.trigger <= 0.5f) {
        // The drag's live move ends with it; another (the headset's tool
        // stick scaling) is its owner's to end.
        if (moveDrag_) {
            moveDrag_.reset();
            endLiveMove();
        }
        toolArmed_ = true;
        return;
    }
    // Where the drag's point is now: on its plane, or as far along the ray
    // as it was grabbed.
    const auto dragPoint = [&h](const MoveDrag& d) -> std::optional<glm::vec3> {
        if (d.depth > 0.0f) return h.aim.position + h.aim.forward() * d.depth;
        return planeHit(h.aim, d.planeY);
    };
    if (moveDrag_) {
        const MoveDrag& d = *moveDrag_;
        const auto p = dragPoint(d);
        if (!p) return;  // pointing at the horizon: it stays where it was
        Placement to = d.start;
        if (d.turning) {
            const auto a = angleAbout(toGlm(d.start.position), *p);
            if (!a) return;
            to.yawDegrees = d.start.yawDegrees + (*a - d.startAngle) * 180.0 / kPi;
        } else {
            to.position[0] = d.start.position[0] + static_cast<double>(p->x - d.startPoint.x);
            to.position[2] = d.start.position[2] + static_cast<double>(p->z - d.startPoint.z);
        }
        moveSculptureLive(d.sculpture, to);
        return;
    }
    if (!toolArmed_) return;  // one grab per trigger pull
    toolArmed_ = false;
    MoveDrag d;
    if (const auto hit = toolHit(h.aim)) {
        // On a sculpture: select it, and drag it at the height it was held.
        select(hit->first);
        d.sculpture = hit->first;
        d.turning = h.pressed(kButtonSecondary);
        d.planeY = hit->second.y;
        if (std::fabs(h.aim.forward().y) < kMinPlaneSlope) d.depth = glm::length(hit->second - h.aim.position);
    } else if (selected_ >= 0 && !sculptures_[static_cast<std::size_t>(selected_)].missing()) {
        // Beside the selection: on its ring it turns; elsewhere, nothing is selected.
        const MoveRing ring = moveRing(sculptures_[static_cast<std::size_t>(selected_)]);
        const auto p = planeHit(h.aim, ring.centre.y);
        if (!p || !grabsMoveRing(ring, *p)) {
            select(-1);
            return;
        }
        d.sculpture = selected_;
        d.turning = true;
        d.planeY = ring.centre.y;
    } else {
        select(-1);
        return;
    }
    const auto p = dragPoint(d);
    if (!p) return;
    d.start = sculptures_[static_cast<std::size_t>(d.sculpture)].placement;
    d.startPoint = *p;
    if (d.turning) {
        const auto a = angleAbout(toGlm(d.start.position), *p);
        if (!a) return;
        d.startAngle = *a;
    }
    moveDrag_ = d;
}

}  // namespace hg::garden
