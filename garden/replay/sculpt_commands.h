// Replay commands that sculpt (docs/replay-format.md): one small struct per
// command, each field named for what it is. Positions in world metres.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "garden/action/action.h"
#include "garden/gesture/stroke.h"
#include "garden/sculpt/edit.h"
#include "garden/sculpt/impacts.h"
#include "garden/sculpt/tool_settings.h"

namespace hg::garden {

// A whole stroke along a path, as if drawn in one frame.
struct StrokeCommand {
    std::string sculpture;
    StrokeTool tool = StrokeTool::Carve;
    double radius = 0.05;
    double softness = 2.0;
    // Smooth: the blend's weight in (0, 1]; inflate: voxels (< 0 deflates).
    double strength = 1.0;
    Falloff falloff = Falloff::Smooth;
    std::vector<std::array<double, 3>> path;
};

struct PerturbCommand {
    std::string sculpture;
    QuadricShape shape = QuadricShape::Ellipsoid;
    std::array<double, 3> center{};
    std::array<double, 3> radii{0.05, 0.05, 0.05};
    double strength = 2.0;
};

// Impacts fired along a world ray (sizes in metres, the volume in cubic
// centimetres, a cone's half-angle in degrees).
struct ImpactsCommand {
    std::string sculpture;
    std::array<double, 3> origin{};
    std::array<double, 3> direction{0, 0, -1};
    ImpactTool tool;  // as read: metres, cm^3 (converted when run)
};

// A sketch drawn on a plane (world points on or near it, its normal)
// joined to the sculpture or cut from it, or (`newSculpture`, mode "new")
// made a new sculpture of that name.
struct SketchCommand {
    std::string sculpture;
    SketchMode mode = SketchMode::Add;
    bool newSculpture = false;
    // Mode "model": a deformable model named `model` around the sculpture.
    bool model = false;
    std::string modelName;
    std::vector<std::array<double, 3>> points;
    std::array<double, 3> normal{0, 0, 1};
    double thickness = 1.0;
};

// A HyperFun file brought into the garden as a new sculpture (the
// window's "add a sculpture"); `file` is resolved against the script's
// folder; no position: on the ground 3 m ahead of the viewer.
struct AddCommand {
    std::string file;
    std::string name;                               // "": the file's stem
    std::optional<std::array<double, 3>> position;  // metres
    double yaw = 0.0;                               // degrees
    double scale = 1.0;                             // metres per model unit
    int resolution = 128;
    std::string body;
};

// Iterations of a model's snake against its sculpture: shrink-wrap or blow-up.
struct DeformCommand {
    std::string sculpture;
    std::string model;
    bool shrink = true;
    int iterations = 1;
};

// The part of a sculpture inside a model's selection made a new sculpture
// (run by the program: garden/export writes the part, ReplayOptions::extractor).
struct ExtractCommand {
    std::string from, by, name;
};

// A stroke fed to the gesture recognizer as the gesture button would
// (screen pixels, y down).
struct GestureCommand {
    StrokePoints points;
};

// The last impact series made on one sculpture fired again at another.
struct ReapplyImpactsCommand {
    std::string from, to;
};

// The perturbation under a world point given a new strength and radii.
struct EditPerturbationCommand {
    std::string sculpture;
    std::array<double, 3> at{};
    double strength = 2.0;
    std::array<double, 3> radii{0.05, 0.05, 0.05};
};

struct UndoCommand { int times = 1; };
struct RedoCommand { int times = 1; };

// The tool the tool hand works from now on (hand-driven sculpting).
struct ToolCommand { ToolSettings settings; };

// An action in the model frame, exactly as a session's journal holds it
// (garden/action/action.h, docs/session-format.md): the commands above are
// the world-frame forms that become these.
struct ActionCommand { Action action; };

using SculptCommand = std::variant<StrokeCommand, PerturbCommand, UndoCommand, RedoCommand, ToolCommand, ImpactsCommand,
                                   ReapplyImpactsCommand, EditPerturbationCommand, ActionCommand, SketchCommand, AddCommand,
                                   DeformCommand, ExtractCommand, GestureCommand>;

// Reads the command under `key` (stroke, perturb, edit_perturbation,
// impacts, reapply_impacts, undo, redo, sculpt_tool, action, sketch);
// throws JsonError with the JSON path of a bad value.
SculptCommand readSculptCommand(const std::string& key, const nlohmann::json& v, const std::string& path);
class GardenSession;
// "" or why the session refused it (replay_runner.cpp).
std::string runSculptCommand(const SculptCommand& c, GardenSession& session);

}  // namespace hg::garden
