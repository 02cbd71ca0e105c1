// Gestures (seed 003's mode switching, issue 22; docs/gestures.md "In the
// garden"): while the gesture button is held (the desktop's middle button,
// the headset's navigation-hand trigger) the tool hand's ray draws a
// stroke instead of working the tool. On release the recognizer names it
// and the sketch tool takes the mode: V a new sculpture, U join, an arch
// cut, Z a deformable model (a selection). With a model made, circling
// deforms it live: clockwise shrinks it onto its sculpture, counter-
// clockwise grows it, for as long as the circling goes on.
//
// The stroke's points are the ray's directions seen from where the stroke
// began (a gnomonic projection on the plane facing the first direction,
// kGesturePixels to a unit of it, y down), the same for a mouse ray (where
// it is the screen, scaled) and a controller: the recognizer is blind to
// size, place and rotation, and the turning sense is kept.
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "garden/app/garden_session.h"
#include "garden/gesture/gesture_recognizer.h"
#include "garden/gesture/gesture_weights.h"

namespace hg::garden {

namespace {

constexpr double kGesturePixels = 1000.0;  // "pixels" per unit of the projection plane (~17 per degree)
constexpr double kGestureStep = 1.5;       // pixels: closer points add nothing
constexpr double kTwoPi = 6.283185307179586;

// The signed turn from direction a->b to b->c, radians: positive turns
// clockwise on the screen (y down), the recognizer's `shrink` sense.
double turnAt(const StrokePoint& a, const StrokePoint& b, const StrokePoint& c) {
    const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - b[0], vy = c[1] - b[1];
    return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

// The whole stroke's signed turning, radians.
double totalTurn(const StrokePoints& p) {
    double t = 0.0;
    for (std::size_t i = 2; i < p.size(); ++i) t += turnAt(p[i - 2], p[i - 1], p[i]);
    return t;
}

std::string percent(double p) {
    char b[16];
    std::snprintf(b, sizeof b, "%.0f%%", 100.0 * p);
    return b;
}

}  // namespace

const GestureRecognizer* GardenSession::recognizer() {
    if (gestureRecognizer_) return gestureRecognizer_.get();
    const std::string path = settings_.gestureWeights.empty() ? std::string(HG_GESTURE_WEIGHTS) : settings_.gestureWeights;
    try {
        gestureRecognizer_ = std::make_unique<GestureRecognizer>(loadGestureWeights(path));
    } catch (const std::exception& e) {
        gestureMessage_ = std::string("gestures are off: ") + e.what();
        return nullptr;
    }
    return gestureRecognizer_.get();
}

std::string GardenSession::applyGesture(const StrokePoints& points) {
    const GestureRecognizer* r = recognizer();
    if (!r) return gestureMessage_;
    const GestureResult g = r->classify(points);
    const auto sketchTool = [&](ToolSettings::SketchUse use) {
        if (tool_.kind != ToolSettings::Kind::Sketch) selectTool(tool_, ToolSettings::Kind::Sketch);
        tool_.sketchUse = use;
        tool_.reverse = false;
    };
    switch (g.label) {
        case GestureLabel::None:
            gestureMessage_ = g.tooShort ? "gesture too short: draw it larger"
                                         : std::string("not a gesture (closest: ") + labelName(g.best) + ", " +
                                               percent(g.confidence) + ")";
            break;
        case GestureLabel::Sketch:
            sketchTool(ToolSettings::SketchUse::New);
            gestureMessage_ = "sketch: the next outline becomes a new sculpture";
            break;
        case GestureLabel::Union:
            sketchTool(ToolSettings::SketchUse::Join);
            gestureMessage_ = "union: the next outline is joined to the sculpture it starts on";
            break;
        case GestureLabel::Intersect:
            sketchTool(ToolSettings::SketchUse::Cut);
            gestureMessage_ = "intersect: the next outline is cut from the sculpture it starts on";
            break;
        case GestureLabel::Deform:
            sketchTool(ToolSettings::SketchUse::Model);
            gestureMessage_ =
                "deform: draw around a part of a sculpture; then circle clockwise to shrink the model onto it, "
                "counter-clockwise to grow it";
            break;
        case GestureLabel::Shrink:
        case GestureLabel::Grow: {
            const bool shrink = g.label == GestureLabel::Shrink;
            if (activeModel_.empty()) {
                gestureMessage_ = std::string(labelName(g.label)) +
                                  ": no model to deform (draw Z, then sketch around a part of a sculpture)";
                break;
            }
            const int iterations = std::max(1, static_cast<int>(std::lround(std::fabs(totalTurn(points)) / kTwoPi *
                                                                             kDeformIterationsPerTurn)));
            const std::string why = deformModel(activeModel_, shrink, iterations);
            gestureMessage_ = why.empty() ? std::string(labelName(g.label)) + ": " + std::to_string(iterations) +
                                                " iterations on '" + activeModel_ + "'"
                                          : why;
            break;
        }
    }
    return g.label == GestureLabel::None ? gestureMessage_ : "";
}

void GardenSession::gestureWithHands(const HandState& h) {
    const bool held = h.tracked && h.pressed(kButtonGesture);
    if (!gesture_.drawing) {
        if (!held) return;
        gesture_ = GestureDraw{};
        gesture_.drawing = true;
        gesture_.forward = h.aim.forward();
        glm::vec3 right = glm::cross(gesture_.forward, glm::vec3(0.0f, 1.0f, 0.0f));
        right = glm::length(right) > 1e-3f ? glm::normalize(right) : h.aim.right();
        gesture_.right = right;
        gesture_.up = glm::cross(right, gesture_.forward);
    }
    if (held) {
        const glm::vec3 d = h.aim.forward();
        const float along = glm::dot(d, gesture_.forward);
        if (along > 0.05f) {
            const double a = static_cast<double>(along);
            const StrokePoint p{kGesturePixels * static_cast<double>(glm::dot(d, gesture_.right)) / a,
                                -kGesturePixels * static_cast<double>(glm::dot(d, gesture_.up)) / a};
            StrokePoints& pts = gesture_.points;
            if (pts.empty() || std::hypot(p[0] - pts.back()[0], p[1] - pts.back()[1]) >= kGestureStep) {
                pts.push_back(p);
                gesture_.trail.push_back(h.aim.position + d);
                circleLive();
            }
        }
        return;
    }
    GestureDraw done = std::move(gesture_);
    gesture_ = GestureDraw{};
    if (done.circling) {
        // Journalled as one action of all the iterations run: the same
        // model, bit for bit, as running them frame by frame.
        commitLiveDeform();
        return;
    }
    applyGesture(done.points);
}

// Circling with a model in hand deforms it while the circling goes on:
// once a loop's worth of path is recognized as shrink or grow, every turn
// of the path in that sense runs kDeformIterationsPerTurn iterations (a
// frame runs at most kLiveDeformIterations of what is owed; the rest
// waits), and a turn the other way, or none, runs nothing.
void GardenSession::circleLive() {
    if (activeModel_.empty() || tool_.kind != ToolSettings::Kind::Sketch ||
        tool_.sketchUse != ToolSettings::SketchUse::Model)
        return;
    const StrokePoints& p = gesture_.points;
    if (p.size() < 3) return;
    const double turn = turnAt(p[p.size() - 3], p[p.size() - 2], p.back());
    if (!gesture_.circling) {
        if (std::fabs(totalTurn(p)) < 0.75 * kTwoPi) return;
        const GestureRecognizer* r = recognizer();
        if (!r) return;
        const GestureResult g = r->classify(p);
        if (g.label != GestureLabel::Shrink && g.label != GestureLabel::Grow) return;
        gesture_.circling = true;
        gesture_.shrink = g.label == GestureLabel::Shrink;
        gesture_.owed = kDeformIterationsPerTurn * 0.75;  // the loop that told us
        return;
    }
    const double sense = gesture_.shrink ? 1.0 : -1.0;
    if (turn * sense > 0.0) gesture_.owed += turn * sense / kTwoPi * kDeformIterationsPerTurn;
}

void GardenSession::deformLiveStep() {
    if (!gesture_.circling || gesture_.owed < 1.0) return;
    const int n = std::min(kLiveDeformIterations, static_cast<int>(gesture_.owed));
    gesture_.owed -= n;
    // Less than a frame's worth owed is all a stopped hand leaves: the
    // deformation stops with the circling.
    gesture_.owed = std::min(gesture_.owed, static_cast<double>(kLiveDeformIterations));
    deformModelLive(activeModel_, gesture_.shrink, n);
}

}  // namespace hg::garden
