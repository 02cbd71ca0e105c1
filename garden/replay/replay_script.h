// A scripted session (docs/replay-format.md): a garden, a fixed timestep,
// and steps that hold hand states and commands for a number of frames.
// `hypergarden replay` plays it frame by frame, deterministically: the same
// script gives the same frames, the same morph and the same meshes.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "garden/hands/hand_state.h"
#include "garden/replay/sculpt_commands.h"

namespace hg::garden {

struct ReplayCommand {
    enum class Kind {
        Morph,         // the selector point on the ground (x, z): weights from the triangle
        MorphWeights,  // the three weights directly (they are normalized)
        Screenshot,    // a PNG of this frame (offscreen only), `text` is its file name
        Detail,        // move the detail sphere (`vec`, `number` = radius); radius 0 removes it
        Pose,          // put the viewer at `vec` with yaw, pitch (degrees) in `pair`
        Select,        // select the sculpture named `text` ("" selects none)
        Orbit,         // orbit the selection (`flag`), or stop
        Budget,        // the frame budget, milliseconds (`number`)
        Sculpt,        // a sculpting command (`sculpt`)
        Export,        // sculpture `text` ("" : the selected one) written to `file` at resolution `number` (0: the grid's)
    };
    Kind kind = Kind::Morph;
    std::array<double, 3> vec{};
    std::array<double, 2> pair{};
    double number = 0.0;
    std::string text;
    std::string file;
    bool flag = false;
    SculptCommand sculpt;
};

struct ReplayStep {
    int frames = 1;
    // Run until the morph update and every remesh queue are drained (at
    // most `frames` frames, then the replay fails: something never settles).
    bool untilIdle = false;
    Hands hands;                          // held for every frame of the step (but its intents: stepHands)
    std::vector<ReplayCommand> commands;  // run at the step's first frame, in order
};

struct ReplayScript {
    std::string file;
    std::string garden;                // resolved against the script's folder
    double timestep = 1.0 / 90.0;      // seconds per frame
    double budgetMs = 11.1;
    std::array<int, 2> viewport = {1280, 720};
    std::vector<ReplayStep> steps;

    int totalFrames() const;  // an upper bound: until_idle steps count their maximum
};

// The hands of frame `frame` (from 0) of a step: the step's hands, with
// its tool intents spread over its frames: the tool choice, reverse and
// mirror at the first frame only, each factor (size, strength, selection
// scale) as its frames-th root every frame, so that the whole step
// multiplies by the factor; `held` on every frame. A scale over a step is
// one gesture: one undo step.
Hands stepHands(const ReplayStep& step, int frame);

// Throws JsonError (garden/scene/json_reader.h) at the first problem, with
// its JSON path.
ReplayScript parseReplayScript(const std::string& text, const std::string& file, const std::string& folder);
ReplayScript loadReplayScript(const std::string& path);

}  // namespace hg::garden
