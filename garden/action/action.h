// The actions a session is made of, in the sculpture's model frame
// (docs/design.md §10, docs/session-format.md): what the journal holds one
// per line, what a restore plays back, what the session's recorder is
// handed as each action finishes. Model frame, so that playing them again
// rebuilds the same edits (and the same grids) bit for bit.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "garden/scene/garden.h"
#include "garden/sculpt/edit.h"

namespace hg::garden {

// A finished stroke: its tool, radius (model units), softness and path
// (model frame); the segments follow from them. Smooth and inflate add
// their strength (as applied: the pen's pressure already in it) and
// falloff, smooth its segments' fits (so a replay never fits again).
struct StrokeAction {
    std::string sculpture;
    StrokeTool tool = StrokeTool::Carve;
    double radius = 0.0;
    double softness = 2.0;
    std::vector<ModelPoint> path;
    std::optional<MirrorPlane> mirror;
    double strength = 1.0;
    Falloff falloff = Falloff::Smooth;
    std::vector<std::optional<SegmentFit>> fits;
};

struct PerturbAction {
    std::string sculpture;
    Perturbation perturbation;  // model frame
};

// Impacts as they were resolved (and their rays, to fire again).
struct ImpactsAction {
    std::string sculpture;
    ImpactSeries series;
};

// A sculpture moved, turned or scaled: its new placement.
struct MoveAction {
    std::string sculpture;
    Placement placement;
};

// A perturbation's factor or extent changed: edit `edit` of the sculpture's
// list replaced.
struct ReplaceAction {
    std::string sculpture;
    std::size_t edit = 0;
    Perturbation perturbation;
};

// Undo: the last action over every sculpture, or with `sculpture` named the
// last action on that sculpture only (the history panel's "undo on the
// selection"), leaving the others' as they are.
struct UndoAction {
    std::string sculpture;  // "": the last action, whichever sculpture it was on
};
struct RedoAction {};
// Every edit of a sculpture taken out (the morph result back to its pure
// blend): undo puts them back, redo takes them out again. Journals written
// before discards could be undone hold no `undoable` and play theirs for
// good, as they were made.
struct DiscardAction {
    std::string sculpture;
    bool undoable = true;
};
// A morph's selector as barycentric coordinates and the balancing factors
// it was weighed with (the blend's weights follow from both).
struct MorphWeightsAction {
    std::array<double, 3> barycentric{};
    std::array<double, 3> balance{1.0, 1.0, 1.0};
    // The morph result it weighs ("": the garden's first morph, as in
    // journals written before a garden could hold several).
    std::string sculpture;
};

// A sketched outline joined to or cut from a sculpture: the points as
// drawn and the plane's normal (model frame); the solid is inflated from
// them when the action is applied (garden/sculpt/sketch_edit.h).
struct SketchAction {
    std::string sculpture;
    SketchMode mode = SketchMode::Add;
    std::vector<ModelPoint> points;
    ModelPoint normal{0.0, 0.0, 1.0};
    double thickness = 1.0;
    std::optional<MirrorPlane> mirror;
};

// A sculpture brought into the garden: a HyperFun file opened from the
// window or `garden add`, a replay's {"add": ...}, a sketch in mode `new`
// (its inflated solid written as HyperFun). The program's text is held
// whole, so the journal plays it back whatever becomes of the file.
struct AddAction {
    std::string sculpture;            // its name, unique among the garden's sculptures
    std::string source;               // the HyperFun program
    std::string origin;               // where it came from (the file as named, "sketch"): messages, the export's label
    std::string body;                 // "": my_model, else the first body
    std::optional<frep::Box3> box;    // the model box; none: found from the model (voxel::resolveModelBox)
    int resolution = 128;             // voxels along the model box's longest side
    Placement placement;
    // A mesh or a volume instead of a program (source ""): the file as
    // copied into the session folder, which the record names so that the
    // session plays back whatever becomes of the original
    // (docs/session-format.md, "Imported files").
    struct Imported {
        enum class Kind { Mesh, Volume };
        Kind kind = Kind::Mesh;
        std::string file;          // imports/NAME.EXT, relative to the session folder; absolute outside a session
        double iso = 0.0;          // a volume's surface value
        bool insideAbove = false;  // a volume's solid is above iso (a fog volume), else below (a level set)
    };
    std::optional<Imported> imported;
};

// An added HyperFun sculpture's file changed on disk: the new text, read
// again (GardenSession::reloadChangedSources). Journalled so that a replay
// gives the same result without the file; not undone (the file is the
// user's, outside the session).
struct ReloadAction {
    std::string sculpture;
    std::string source;
};

// A sculpture given another material (the panel's choice): the whole
// material, so the journal plays it back whatever the garden file says.
struct MaterialAction {
    std::string sculpture;
    Material material;
};

// A deformable model sketched around a sculpture (issue 22,
// docs/sketching.md "Selections"): the outline as drawn and its plane's
// normal (the sculpture's model frame), inflated and meshed when applied.
// It becomes the active model, which circling gestures deform.
struct ModelAction {
    std::string name;       // the model's, unique among the session's models
    std::string sculpture;  // the sculpture it surrounds
    std::vector<ModelPoint> points;
    ModelPoint normal{0.0, 0.0, 1.0};
    double thickness = 1.0;
};
// Iterations of a model's snake against its sculpture (shrink-wrap or
// blow-up); its selection then becomes the sculpture's.
struct DeformAction {
    std::string model;
    bool shrink = true;
    int iterations = 1;
};
// The sculpture's selection set to a model's (`model` "": cleared).
// Selections are not undone (undo takes back what was made with them).
struct SelectAction {
    std::string sculpture;
    std::string model;
};
using Action =
    std::variant<StrokeAction, PerturbAction, UndoAction, RedoAction, DiscardAction, MorphWeightsAction, MoveAction,
                 ImpactsAction, ReplaceAction, SketchAction, AddAction, MaterialAction, ModelAction, DeformAction,
                 SelectAction, ReloadAction>;

std::string actionKind(const Action& r);

// One action as JSON (a journal line's text without its CRC), and back;
// throws JsonError (garden/scene/json_reader.h) on a bad record.
std::string actionJson(const Action& r);
Action parseAction(const std::string& json, const std::string& path);
// The same from JSON already read (a replay script's "action" command).
Action readAction(const nlohmann::json& v, const std::string& path);
// "shrink" (true) or "grow" (false); throws JsonError otherwise.
bool readDeformMode(const nlohmann::json& v, const std::string& path);

}  // namespace hg::garden
