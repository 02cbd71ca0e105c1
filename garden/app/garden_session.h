// The garden while it runs, without a window (docs/design.md §6): every sculpture
// as a volume with its LOD pyramid and remesh queue, the metamorphoses (each
// result a sculpture holding its source caches, weights and budgeted
// blend: garden/morph/morph_state.h), the navigator and the
// frame scheduler. One frame is one call, frame(input, views), that runs
// the stages in their one order:
//
//   begin, the caller's commands, input (navigation and the tools: a
//   stroke's box is applied here, first), level selection, the morph's
//   budgeted blend, remeshing, upload and render (through the ViewSink),
//   end (the frame's stats closed and kept in the history).
//
// The desktop window, the headset, `replay` (headless or offscreen), the
// benches and the tests all drive this same object through frame(), so what
// a script does is what a user sees, and each stage is timed in one place.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "garden/app/frame_scheduler.h"
#include "garden/app/navigator.h"
#include "garden/app/sculpture_meshing.h"
#include "garden/app/sculpture.h"
#include "garden/app/view_sink.h"
#include "garden/gesture/stroke.h"
#include "garden/morph/morph_weights.h"
#include "garden/scene/garden_file.h"
#include "garden/sculpt/edit.h"
#include "garden/sculpt/tool_settings.h"
#include "garden/action/action_sink.h"
#include "polygonizer/realtime/lod_selection.h"
#include "polygonizer/realtime/remesh_queue.h"

namespace hg::garden {

struct MorphState;
class SculptureLoader;
class GridPager;
struct GridNeed;
struct MorphSources;
struct GestureRecognizer;
namespace deform { class DeformableModel; }
}  // namespace hg::garden
namespace hg::jobs {
class JobThread;
}
namespace hg::voxel {
struct VolumeRequest;
}
namespace hg::garden {

// The scales a sculpture may be given, metres per model unit.
constexpr double kMinSculptureScale = 1e-3;
constexpr double kMaxSculptureScale = 1e3;
// The longest side, in metres, of a sculpture added without a scale.
constexpr double kAddedSize = 1.5;
// "" when the placement is finite and its scale within those bounds, else why not.
std::string checkPlacementValues(const Placement& placement);

struct SessionSettings {
    SchedulerSettings scheduler;
    // The morph's per-frame budget in samples (0: its share of the frame's
    // time instead, from the scheduler).
    std::uint64_t morphSamplesPerFrame = 0;
    // Chunks remeshed per frame (0: the scheduler's remesh allowance). With
    // both counts fixed a frame does the same work whatever the clock says:
    // what replays use, so that they are deterministic. A count meshes in
    // the frame; the allowance meshes off the frame thread (the frame only
    // gathers the chunks' samples and shows the meshes finished since the
    // last frame: it never waits for a mesh).
    std::size_t remeshChunksPerFrame = 0;
    // With the allowances: mesh and blend morphs off the frame thread
    // (false: within the frame, in batches while the allowance lasts). The
    // window and the headset set it: their frames are paced by the display,
    // so the workers run while a frame waits. A caller that runs frames back
    // to back until idle (tests, headless replays) would only spin while the
    // workers run, so it stays off by default; bench_garden's stages rows
    // measure both.
    bool workOffFrameThread = false;
    int chunkSize = 32;
    int maxLevel = 3;
    double pixelError = 1.0;
    // Levels by measured error (polygonizer/realtime/chunk_errors.h): a
    // coarser level is also taken where its surface strays from level 0's
    // by at most this many pixels on screen (0: the voxel-size rule alone).
    double levelErrorPixels = 0.5;
    // Milliseconds a frame for measuring again the errors of chunks an edit
    // or a blend changed (a frame measures at least one small batch while
    // any wait); until then they take the voxel-size rule's levels. Tests
    // make it tiny to play a slow machine.
    double errorRefreshMs = 0.5;
    double fovY = 1.0471975511965976;  // 60 degrees
    int viewportHeight = 720;
    bool lod = true;                   // false: every chunk at level 0
    // Resolutions instead of the garden file's (0: the file's): tests and
    // benchmarks run the same garden smaller or larger.
    int sculptureResolution = 0;
    int morphResolution = 0;
    // The garden opens at once and sculptures are sampled in the background,
    // nearest to the viewer first, each shown coarse as soon as its grid is
    // in (garden/app/sculpture_loader.h); the morph's sources are sampled
    // before the session opens. Until then a sculpture is loading(): no
    // grid, not editable. Off: every sculpture is sampled in the constructor.
    bool progressiveLoading = false;
    // New meshes shown per frame, in bytes (0: no limit): what the upload
    // stage then moves to the GPU, spread over frames instead of a burst.
    // Groups of touching chunks are shown whole (a split would show a
    // crack), so a group larger than this is shown alone in its frame.
    std::size_t uploadBytesPerFrame = 0;
    // With the allowance (remeshChunksPerFrame 0): a new edit's grid update
    // is spread over frames, computed at the start of each input stage
    // within its share of the frame (SchedulerSettings::editShare), so a
    // big perturbation or a whole stroke does not hold one frame
    // (SculptureEdits::appendSpread). The window and the headset set it;
    // with it off (tests, deterministic replays) an edit is whole in the
    // grid when its call returns.
    bool spreadEdits = false;
    // The gesture recognizer's weights ("": content/gestures/weights.json).
    std::string gestureWeights;
    // What the sculptures may hold in memory (grids, coarse levels, meshes,
    // edits' bases, morph caches; garden/app/memory_report.h): over it, the
    // farthest grids are kept on disk until a visitor or a tool comes near
    // (garden/app/grid_pager.h). 0: no budget. The folder "" is one of the
    // process's own under the user's cache folder, removed at the end.
    std::size_t memoryBudgetBytes = std::size_t{1024} << 20;
    std::string pageFolder;
};

// What one frame is given: the hands (world frame), the time since the
// last frame, and the caller's commands.
// One action in the undo history, for a panel.
struct HistoryItem {
    int sculpture = -1;
    std::string name;    // the sculpture's
    std::string action;  // actionKind: "stroke", "perturb", "move", ...
    bool undone = false; // waiting in the redo list
};

struct FrameInput {
    FrameInput() = default;
    FrameInput(const Hands& h, double seconds) : hands(h), dt(seconds) {}

    Hands hands;
    double dt = 1.0 / 90.0;
    // Run once the frame has begun and before its input stage reads the
    // hands (timed as input): a replay step's commands, the desktop's keys,
    // the headset's panel. They may change the hands (the panel takes the
    // trigger it owns). False ends the frame there: no stage runs, and the
    // frame is closed as it stands (a replay command that failed).
    std::function<bool(GardenSession&, Hands&)> commands;
};

class GardenSession {
public:
    // Samples every sculpture (those that fail become missing) and the
    // morph's sources, or with progressiveLoading starts sampling them;
    // throws nothing for a broken sculpture.
    GardenSession(GardenLoad load, SessionSettings settings = {});
    ~GardenSession();
    GardenSession(const GardenSession&) = delete;
    GardenSession& operator=(const GardenSession&) = delete;

    const Garden& garden() const { return *load_.garden; }
    const GardenLoad& load() const { return load_; }
    std::vector<Sculpture>& sculptures() { return sculptures_; }
    const std::vector<Sculpture>& sculptures() const { return sculptures_; }
    Navigator& navigator() { return navigator_; }
    // Back where the garden file starts the visitor, walking.
    void resetView();
    const Navigator& navigator() const { return navigator_; }
    FrameScheduler& scheduler() { return scheduler_; }
    SessionSettings& settings() { return settings_; }

    // --- what the user changes ---------------------------------------
    // A garden may hold several morphs; each result is a sculpture with its
    // own sources, weights and blend. The selector's setters, the panels and
    // the replay's morph commands act on the active one: the garden's first
    // that could be made, or the morph result last selected (select(), or
    // its triangle picked on the ground). The readers below take a morph
    // result's index, or -1 for the active one.
    std::vector<int> morphResults() const;  // every morph result's index, in the file's order
    int activeMorph() const { return activeMorph_; }  // -1: none can run
    void setActiveMorph(int sculpture);  // ignored unless a morph result that runs
    // The selector on the ground (x, z), clamped to the triangle.
    void setMorphPoint(double x, double z);
    void setMorphWeights(const std::array<double, 3>& w);  // normalized here
    // A point of the on-screen triangle widget, as barycentric coordinates:
    // balanced like a point on the ground.
    void setMorphBarycentric(const std::array<double, 3>& b);
    const std::optional<MorphWeights>& morphWeights(int sculpture = -1) const;
    // The triangle on the ground (a morph result's even when its sources are missing).
    std::optional<MorphTriangle> morphTriangle(int sculpture = -1) const;
    const MorphSpec* morphSpec(int sculpture = -1) const;
    bool hasMorph() const { return activeMorph_ >= 0; }
    // The detail sphere (world), where chunks go to level 0.
    void setDetail(std::optional<poly::Sphere> world) { detail_ = world; }
    const std::optional<poly::Sphere>& detail() const { return detail_; }
    void select(int sculpture);  // -1: none
    int selected() const { return selected_; }
    int findSculpture(const std::string& name) const;

    // --- actions (garden/action/action.h, garden/app/session_actions.cpp) ---
    // The one entry for an action, in the model frame: what a journal
    // plays, what the tools and the replays' world commands become (below),
    // what undo and redo step over. The grid changes in the action's box
    // within the call (its chunks remeshed first) and the action is
    // journalled. "" on success, else why it was refused (nothing changed).
    std::string apply(const Action& action);

    // World-frame requests (metres, the world's axes) taken into a
    // sculpture's model frame: the edge where world coordinates end. Each
    // gives the action, or why there is none.
    struct ActionOrWhy {
        std::optional<Action> action;
        std::string why;
    };
    // A stroke's path and radius; the sculpture's mirror plane goes with it.
    // Smooth and inflate take a strength (inflate: voxels) and a falloff.
    ActionOrWhy strokeFromWorld(int sculpture, StrokeTool tool, const std::vector<std::array<double, 3>>& worldPath,
                                double radius, double softness = 2.0, double strength = 1.0,
                                Falloff falloff = Falloff::Smooth) const;
    // A perturbation's centre and radii (its axes the world's).
    ActionOrWhy perturbationFromWorld(int sculpture, QuadricShape shape, const std::array<double, 3>& worldCenter,
                                      const std::array<double, 3>& radii, double strength) const;
    // An impact tool fired along the world ray (origin, direction); sizes
    // in metres, the compaction volume in cubic metres. The impacts that
    // meet the sculpture are one action.
    ActionOrWhy impactsFromWorld(int sculpture, const std::array<double, 3>& worldOrigin,
                                 const std::array<double, 3>& worldDirection, ImpactTool tool) const;
    // The last impact series made on `from` fired again at `to`, its rays
    // placed the same way in `to`'s model box.
    ActionOrWhy impactsAgain(int from, int to) const;
    // A sketch drawn on a plane (world points on or near it, the plane's
    // normal), joined to the sculpture or cut from it; the mirror plane
    // goes with it.
    ActionOrWhy sketchFromWorld(int sculpture, SketchMode mode, const std::vector<std::array<double, 3>>& worldPoints,
                                const std::array<double, 3>& worldNormal, double thickness = 1.0) const;
    // A sculpture from a HyperFun file, added to the garden (an AddAction
    // holding the file's text), or from a mesh (.stl, .obj, .ply) or an
    // OpenVDB volume (.vdb; a level set's zero or a fog volume's middle
    // value), whose AddAction names the file (addSculptureFile copies it
    // into the session first): `name` "" takes the file's stem (made
    // unique); refused with the reader's messages (file, line) when the
    // file is broken. A placement with scale 0 sizes the model to
    // kAddedSize metres and stands it on the ground at the placement's x and z.
    ActionOrWhy addFromFile(const std::string& path, const std::string& name, const Placement& placement,
                            int resolution = 128, const std::string& body = "") const;
    // A sketch in mode `new`: its inflated solid as a new sculpture named
    // `name` ("" : "sketch", made unique) standing where it was drawn.
    ActionOrWhy sketchNewFromWorld(const std::string& name, const std::vector<std::array<double, 3>>& worldPoints,
                                   const std::array<double, 3>& worldNormal, double thickness = 1.0) const;
    // A deformable model sketched around a sculpture (issue 22): the
    // outline on its plane (world points, the normal) inflated and meshed,
    // named `name` ("": "model", made unique among the models).
    ActionOrWhy modelFromWorld(int sculpture, const std::string& name, const std::vector<std::array<double, 3>>& worldPoints,
                               const std::array<double, 3>& worldNormal, double thickness = 1.0) const;
    // `wanted` if no sculpture has that name, else the first free `wanted-N`.
    std::string uniqueName(const std::string& wanted) const;
    // A point on the ground `distance` metres ahead of the viewer: where
    // the window puts a sculpture it adds.
    std::array<double, 3> placeInView(double distance) const;
    // Edit `edit` of the sculpture (a perturbation) with a new factor and
    // extent (radii in metres): its replacement.
    ActionOrWhy perturbationChange(int sculpture, std::size_t edit, double strength,
                                   const std::array<double, 3>& radii) const;

    // --- sculpting (garden/app/session_sculpting.cpp) ------------------
    // The world-frame requests above, applied.
    std::string applyStroke(int sculpture, StrokeTool tool, const std::vector<std::array<double, 3>>& worldPath,
                            double radius, double softness = 2.0, double strength = 1.0,
                            Falloff falloff = Falloff::Smooth);
    std::string applySketch(int sculpture, SketchMode mode, const std::vector<std::array<double, 3>>& worldPoints,
                            const std::array<double, 3>& worldNormal, double thickness = 1.0);
    std::string applyPerturbation(int sculpture, QuadricShape shape, const std::array<double, 3>& worldCenter,
                                  const std::array<double, 3>& radii, double strength);
    std::string applyImpacts(int sculpture, const std::array<double, 3>& worldOrigin,
                             const std::array<double, 3>& worldDirection, ImpactTool tool);
    std::string reapplyImpacts(int from, int to);
    std::string editPerturbation(int sculpture, std::size_t edit, double strength, const std::array<double, 3>& radii);
    // addFromFile applied; a mesh or a volume is first copied into the
    // session folder's imports/ (sessionFolder()), and the record names the
    // copy, so the session reopens whatever becomes of the original.
    std::string addSculptureFile(const std::string& path, const std::string& name, const Placement& placement,
                                 int resolution = 128, const std::string& body = "");
    // The session folder the journal is kept in ("" : none): where added
    // meshes and volumes are copied to and their records' files are found
    // (docs/session-format.md, "Imported files"). Set before a journal is played.
    void setSessionFolder(const std::string& dir) { sessionFolder_ = dir; }
    const std::string& sessionFolder() const { return sessionFolder_; }
    // A live stroke: begun at a point, extended as the hand moves, ended on
    // release (the stroke is in the edit list from its first point, and
    // journalled as one StrokeAction when it ends).
    // Smooth and inflate take a strength (already scaled by the pen's
    // pressure) and a falloff.
    std::string beginStroke(int sculpture, StrokeTool tool, const std::array<double, 3>& worldPoint, double radius,
                            double softness = 2.0, double strength = 1.0, Falloff falloff = Falloff::Smooth);
    std::string extendStroke(const std::array<double, 3>& worldPoint);
    void endStroke();
    bool stroking() const { return strokeSculpture_ >= 0; }
    // Undo and redo over every sculpture, in the order actions were made;
    // false when there is nothing to undo or redo.
    bool undo();
    bool redo();
    // The last action on one sculpture undone, the others' left as they are
    // (journalled as an UndoAction naming it); redo brings it back. False
    // when that sculpture has nothing to undo.
    bool undoSculpture(int sculpture);
    // The undo history, oldest first, then what redo would bring back
    // (garden/render/history_panel.cpp lists it).
    std::vector<HistoryItem> history() const;
    // The perturbation of a sculpture under a world point (the latest whose
    // quadric holds it), by its index in the edit list; none when none does.
    std::optional<std::size_t> pickPerturbation(int sculpture, const std::array<double, 3>& worldPoint) const;
    // Moves, turns or scales a sculpture (a MoveAction: undoable,
    // journalled): its grid stays, in its model frame. "" or why not (a
    // scale out of range, say).
    std::string moveSculpture(int sculpture, const Placement& placement);
    // Gives a sculpture another material (a MaterialAction: undoable,
    // journalled); a missing sculpture keeps its place and takes it too.
    // "" or why not; nothing is recorded when it already has that material.
    std::string setMaterial(int sculpture, const Material& material);
    // A move while a hand drags (garden/app/session_moving.cpp): shown at
    // once, not journalled; endLiveMove makes the drag one undoable,
    // journalled move from the placement before its first live move to the
    // last (nothing when it ends where it began). Undo, redo, another move
    // or a live move of another sculpture end it first.
    std::string moveSculptureLive(int sculpture, const Placement& placement);
    void endLiveMove();
    bool movingLive() const { return liveMove_ >= 0; }
    // --- gestures and selections (garden/app/session_gestures.cpp,
    // session_selection.cpp; docs/sketching.md "Selections") ----------
    // A stroke in screen pixels (y down) recognized as the gesture button
    // would: the sketch tool takes the gesture's mode, or a loop deforms
    // the model in hand (kDeformIterationsPerTurn a turn). "" when it was
    // a gesture, else why not (also gestureMessage()).
    std::string applyGesture(const StrokePoints& points);
    const std::string& gestureMessage() const { return gestureMessage_; }
    const StrokePoints& gesturePath() const { return gesture_.points; }
    // The gesture as drawn, a metre along the ray from its hand (for the gizmo).
    const std::vector<glm::vec3>& gestureTrail() const { return gesture_.trail; }
    bool gestureDrawing() const { return gesture_.drawing; }
    // Deformable models: `iterations` of the snake against the model's
    // sculpture (a DeformAction); the model's selection then becomes the
    // sculpture's. "" or why not.
    std::string deformModel(const std::string& model, bool shrink, int iterations);
    // The selection a model makes now (its balls fitted to its mesh, in
    // its sculpture's model frame), or why there is none.
    std::optional<SelectionMask> modelMask(const std::string& model, std::string& why) const;
    // An extracted part as a new sculpture (garden/export/part_export.h
    // writes `text`, the part of `from` inside `mask` as HyperFun): named
    // `name` ("": FROM-part, made unique), in `from`'s model frame and
    // voxel size, its box the mask's within `from`'s, standing beside it.
    ActionOrWhy partFromText(int from, const std::string& name, std::string text, const SelectionMask& mask,
                             const std::string& origin) const;
    // The sculpture's selection: edits made while it is set act only
    // inside it. `model` "" clears it (a SelectAction).
    std::string selectWithModel(const std::string& sculpture, const std::string& model);
    const std::optional<SelectionMask>& selectionOf(int sculpture) const;
    // The models: name, the sculpture each surrounds, its mesh (model frame
    // of that sculpture) for drawing.
    struct ModelView {
        std::string name;
        int sculpture = -1;
        const std::vector<glm::dvec3>* vertices = nullptr;
        const std::vector<std::array<std::uint32_t, 3>>* triangles = nullptr;
        int iterations = 0;
        bool settled = false;
    };
    std::vector<ModelView> models() const;
    const std::string& activeModel() const { return activeModel_; }
    static constexpr double kDeformIterationsPerTurn = 20.0;
    static constexpr int kLiveDeformIterations = 6;

    // The sketch tool's outline while the button is held (world points on
    // its plane, garden/app/session_sketching.cpp), for the gizmo; empty
    // otherwise. The last sketch's refusal ("" after one that was made).
    const std::vector<glm::vec3>& sketchPath() const { return sketch_.points; }
    const std::string& sketchMessage() const { return sketchMessage_; }
    // Why the last press of a sculpting tool did nothing ("" after one that
    // acted): it met no sculpture. A stroke edits the sculpture its press
    // met, and only that one, which becomes the selection.
    const std::string& toolMessage() const { return toolMessage_; }
    // The sculpture's mirror plane (model frame; none: off): strokes and
    // perturbations made while it is set act on both sides of it.
    void setMirror(int sculpture, std::optional<MirrorPlane> plane);
    // Takes every edit of a sculpture out (the morph result's strokes, say):
    // one action (a DiscardAction), so undo puts them all back and redo
    // takes them out again.
    void discardEdits(int sculpture);
    std::size_t editCount(int sculpture) const;

    // --- sources edited on disk (garden/app/session_reloading.cpp) -------
    // Each sculpture of the garden file (and each added from a HyperFun
    // file, by a journalled ReloadAction) whose HyperFun file changed on disk
    // (its modification time) since it was read is read again: a good file
    // is sampled and replaces the unedited grid, the sculpture's edits
    // applied again on it (nothing the user made is lost); a broken one
    // keeps the last good grid and the parser's message in the sculpture's
    // sourceProblem. What happened, a line each ("" : nothing changed).
    struct SourceReload {
        std::string sculpture;
        std::string problem;  // "": read again and shown; else why the last good one stays
    };
    std::vector<SourceReload> reloadChangedSources();

    // --- the journal (garden/session) ------------------------------------
    // Called with every finished action (a stroke at its end, a
    // perturbation, undo, redo, discard, a morph weight change once the
    // hand lets go); the session folder appends it to its journal and says
    // whether it is saved (garden/action/action_sink.h). Not owned.
    void setJournal(JournalSink* journal) { journal_ = journal; }
    JournalSink* journal() const { return journal_; }
    // Finished actions made in this run (not those a journal played): with
    // no journal, what closing would lose.
    std::size_t actionsRecorded() const { return recorded_; }
    // Plays journalled actions without journalling them again, the grids
    // recomputed once at the end (each voxel once). "" or why a record
    // cannot be played (its number, from 1, and the reason).
    std::string restore(const std::vector<Action>& records);
    // The same, with the record that could not be played taken apart.
    JournalPlayed restoreRecords(const std::vector<Action>& records);
    ToolSettings& tool() { return tool_; }
    const ToolSettings& tool() const { return tool_; }
    // Where the tool hand's ray first meets a sculpture's surface (world):
    // the sculpture's index and the point, or none.
    std::optional<std::pair<int, glm::vec3>> toolHit(const Pose& aim) const;

    // --- one frame -----------------------------------------------------
    // Runs a whole frame (see the top of this file) and returns its stats.
    const FrameStats& frame(const FrameInput& input, ViewSink& views);
    // The same with nothing to upload to or draw: headless replays, tests, benches.
    const FrameStats& frame(const FrameInput& input);
    // The frame under way (a sink adds what it measured itself).
    FrameStats& stats() { return scheduler_.stats(); }

    // The morph has nothing left to blend, no edit's grid update waits
    // (spreadEdits), no chunk waits for a mesh, no sculpture is loading, and
    // every sculpture's levels were chosen in the last frame from errors all
    // measured: what a settled garden shows then depends on where the viewer
    // stands and what the grids hold, not on how fast the frames ran.
    bool idle() const;
    // Every edit's grid update that waits (spreadEdits) computed now and
    // shown: what a snapshot of the grids needs.
    void settleEdits();
    // Sculptures still being sampled (progressive loading), and a wait until
    // every one is in (what needs the whole garden: a journal to play).
    std::size_t sculpturesLoading() const;
    void finishLoading();
    // Far grids on disk (garden/app/grid_pager.h): the pager, and a wait
    // until every grid it is writing or reading back is done and taken.
    const GridPager* pager() const { return pager_.get(); }
    GridPager* pager() { return pager_.get(); }
    void settlePaging();
    std::size_t remeshPending() const;
    // Triangles of the meshes on show, over every sculpture.
    std::size_t trianglesShown() const;
    // Samples left to blend, over every morph.
    std::uint64_t morphRemaining() const;
    // A morph result's grid, and a from-scratch blend at its current
    // weights (what the result must equal once idle); -1: the active morph's.
    const voxel::Volume* morphResult(int sculpture = -1) const;
    std::unique_ptr<voxel::Volume> blendFromScratch(int sculpture = -1) const;
    // A morph's source caches (none: it cannot run); the export reads their
    // normalizations.
    const MorphSources* morphSources(int sculpture = -1) const;

    glm::mat4 view() const { return navigator_.view(); }

private:
    // The frame's stages, in order (frame() is their one caller).
    void beginFrame();
    void input(const Hands& hands, double dt);
    // The waiting edits' grid updates computed within `milliseconds`, and
    // shown (0: only those a later change settled).
    void advanceEdits(double milliseconds);
    // A new edit's grid update is spread over frames (SessionSettings::spreadEdits).
    bool spreading() const { return settings_.spreadEdits && settings_.remeshChunksPerFrame == 0 && !restoring_; }
    void selectLevels();
    // What level selection says of each sculpture's grid (garden/app/grid_pager.h).
    GridNeed gridNeed(std::size_t index, const poly::Camera& camera, const poly::LodSettings& lod) const;
    void morph();
    void remesh();
    void remeshInBackground(const std::vector<std::pair<float, std::size_t>>& order);
    void uploadAndRender(ViewSink& views);
    const FrameStats& endFrame();

    // The actions to undo, oldest first: each as it was made (an edit, a
    // move, a replacement), with what undoing it needs beyond the edit
    // list's own history (the placement or the perturbation before it).
    struct UndoEntry {
        UndoEntry(int s, Action a, std::optional<Placement> before = std::nullopt,
                  std::optional<Perturbation> replaced = std::nullopt, std::optional<Material> material = std::nullopt)
            : sculpture(s),
              action(std::move(a)),
              placementBefore(std::move(before)),
              replacedBefore(std::move(replaced)),
              materialBefore(std::move(material)) {}
        int sculpture = -1;
        Action action;
        std::optional<Placement> placementBefore;     // a MoveAction's
        std::optional<Perturbation> replacedBefore;   // a ReplaceAction's
        std::optional<Material> materialBefore;       // a MaterialAction's
        // A DiscardAction's while it stands: the edits it took out, in list
        // order, and their entries (undoing it puts both back).
        std::vector<Edit> discardedEdits;
        std::vector<UndoEntry> discardedEntries;
    };
    // A sculpture from the garden file (name, placement, source; missing
    // when its file is), then sampled and given its meshing caches.
    void describeSculpture(std::size_t index);
    void sampleSculpture(std::size_t index);
    // `prepared` (when built, on `volume`) saves attachMeshing building it.
    void attachGrid(std::size_t index, std::unique_ptr<voxel::Volume> volume, const std::string& error,
                    PreparedMeshing prepared = {});
    // Progressive loading: grids the loader finished, attached within the frame.
    void attachLoaded();
    // The pyramid, layout and queue of a sampled sculpture, its coarsest level meshed.
    void attachMeshing(Sculpture& s, PreparedMeshing prepared = {}) const;
    MeshingShape meshingShape() const;
    static voxel::VolumeRequest volumeRequest(const SculptureSpec& spec);
    // A file's modification time as a number (0: none); reloading compares them.
    static std::int64_t sourceStamp(const std::string& path);
    // Sculpture `index`'s grid replaced by `fresh`, its edits applied
    // again: "" or why not (nothing changed then).
    // When the frame differs the sculpture is rebuilt in the new one (reframeSculpture).
    std::string replaceSource(std::size_t index, SculptureLoad loaded, voxel::Volume fresh);
    // Sculpture `index`'s grid is in a new frame: its edits derived again in
    // the new units and applied, its meshing caches made anew.
    void reframeSculpture(std::size_t index);
    // Sources of the metamorphosis read again (`changed`, with their loads
    // and grids): replaced like any sculpture, then the morph's caches
    // sampled again once and the result blended again (budgeted, frame by
    // frame), its own edits applied after the blend.
    std::string replaceMorphSources(const std::vector<std::size_t>& changed, std::vector<SculptureLoad> loads,
                                    std::vector<voxel::Volume> grids);
    std::string applyAddModel(const AddAction& a);
    // addFromFile for a mesh or a volume: the AddAction names the original
    // (absolute); importIntoSession then copies it into the session folder
    // and names the copy ("" or why not: nothing is added then).
    ActionOrWhy importFromFile(const std::string& path, const std::string& name, const Placement& placement,
                               int resolution, const std::string& body) const;
    std::string importIntoSession(AddAction& a) const;
    // An imported file's path as read now: a record's relative file in the session folder.
    std::string importedPath(const AddAction::Imported& m) const;
    std::string applyReloadModel(const ReloadAction& a);
    // An added sculpture's file, watched for changes (its text as last
    // applied compared with the file's; none for a file that is not there).
    void watchAddedSource(std::size_t index, const std::string& text);
    // A reload of each added HyperFun sculpture whose file changed (reloadChangedSources).
    void reloadAddedSources(std::vector<std::size_t>& reported);
    // Morph `spec` of the garden file as a sculpture appended to sculptures_.
    void buildMorph(std::size_t spec);
    // The morph a reader means (-1: the active one): its state, or null.
    const MorphState* morphState(int sculpture) const;
    MorphState* morphState(int sculpture);
    // The blend started again at the result's current weights.
    void restartMorph(int sculpture);
    void setActiveWeights(const MorphWeights& w);
    std::array<double, 3> toModel(const Sculpture& s, const glm::vec3& world) const;
    // A world direction (a sketch plane's normal) in the sculpture's model frame.
    static std::array<double, 3> toModelDirection(const Sculpture& s, const std::array<double, 3>& world);
    std::string checkEditable(int sculpture) const;
    std::string startStroke(int sculpture, Stroke stroke);
    // apply()'s cases, each on a sculpture found by the action's name.
    std::string applyStrokeModel(int sculpture, const Stroke& stroke);
    std::string applyPerturbationModel(int sculpture, const Perturbation& p);
    std::string applyImpactsModel(int sculpture, const ImpactSeries& series);
    std::string replacePerturbationModel(int sculpture, std::size_t edit, const Perturbation& p);
    std::string applySketchModel(int sculpture, const SketchAction& a);
    // A whole edit appended to a sculpture's list (shown, undoable as
    // `done`, redo cleared, journalled): what every finished edit but a
    // live stroke goes through.
    void appendEdit(int sculpture, Edit e, const Action& done);
    // discardEdits, or a journal's discard (`undoable` false: one written
    // before discards could be undone, played as it was made, for good).
    void discard(int sculpture, bool undoable);
    // The sculpture's edits and their undo entries moved into `entry`, a
    // discard's; putBackEdits moves them back, the entries where it stood.
    void takeEdits(UndoEntry& entry);
    void putBackEdits(UndoEntry& entry, std::vector<UndoEntry>& undoOrder, std::size_t at);
    // The sculpture an action names: its index, or why it cannot take the
    // action (none by that name, missing).
    int actionSculpture(const std::string& name, std::string& why) const;
    static bool finite3(const std::array<double, 3>& p);
    SculptureEdits& editsOf(int sculpture);
    void showChanged(int sculpture, const voxel::IndexBox& box);
    // The hands' tool intents applied (garden/app/tool_intents.cpp), before
    // the tools read the hands.
    void applyToolIntents(const Hands& hands);
    void sculptWithHands(const Hands& hands);
    void record(const Action& r);
    // `only` >= 0: that sculpture's last entry, not the last of all.
    bool stepHistory(std::vector<UndoEntry>& from, std::vector<UndoEntry>& to, bool undoing, int only = -1);
    // `followOrbit`: an orbit of the sculpture follows it (not during a live
    // move: the camera would carry the hand's ray, and the sculpture, along).
    void placeSculpture(int sculpture, const Placement& placement, bool followOrbit = true);
    std::string checkPlacement(int sculpture, const Placement& placement) const;
    void moveWithHands(const HandState& h);
    void sketchWithHands(const HandState& h);
    void recordMorph(int sculpture);
    // Gestures (session_gestures.cpp) and models (session_selection.cpp).
    const GestureRecognizer* recognizer();
    void gestureWithHands(const HandState& h);
    void circleLive();
    void deformLiveStep();
    bool deformModelLive(const std::string& model, bool shrink, int iterations);
    void commitLiveDeform();
    std::string applyModelAction(const ModelAction& a);
    std::string applyDeformAction(const DeformAction& a);
    std::string applySelectAction(const SelectAction& a);
    // The selection edit `e` of `sculpture` is made with now (none: off),
    // its box grown by the edit's reach beyond the balls (its floor).
    std::optional<SelectionMask> maskFor(int sculpture, const Edit& e) const;

    GardenLoad load_;
    SessionSettings settings_;
    // Mesh chunks and blend morphs off the frame thread (made at the first
    // use); declared before the sculptures, whose queues and blenders let
    // go of their jobs as they go.
    std::unique_ptr<poly::MeshingWorker> meshing_;
    std::unique_ptr<jobs::JobThread> blending_;
    // Far grids kept on disk within the memory budget; declared before the
    // sculptures, whose volumes may read back from its folder until they go.
    std::unique_ptr<GridPager> pager_;
    std::vector<GridNeed> gridNeeds_;  // this frame's, by sculpture
    std::vector<Sculpture> sculptures_;
    Navigator navigator_;
    FrameScheduler scheduler_;
    std::optional<poly::Sphere> detail_;
    int selected_ = -1;
    int activeMorph_ = -1;             // the morph result the selector acts on, or -1
    // Sculpting.
    ToolSettings tool_;
    int strokeSculpture_ = -1;         // the live stroke's sculpture, or -1
    std::vector<UndoEntry> undoOrder_;
    std::vector<UndoEntry> redoOrder_;
    std::uint32_t lastButtons_ = 0;    // the tool hand's buttons last frame (undo, redo edges)
    bool toolArmed_ = true;            // the trigger was released since the last action
    float lastToolTrigger_ = 0.0f;     // the tool hand's trigger the frame before
    int settleFrames_ = 0;             // frames a press waited for the trigger to settle
    JournalSink* journal_ = nullptr;
    std::size_t recorded_ = 0;         // actionsRecorded()
    bool restoring_ = false;           // playing a journal: nothing is journalled again
    bool morphDragging_ = false;       // the tool hand holds the selector on the ground
    bool morphDragged_ = false;        // ... and moved it: journalled on release
    int morphDragTarget_ = -1;         // ... of this morph result (-1: none picked yet)
    float strokeDepth_ = 0.0f;         // metres along the ray where the live stroke began
    // The move tool's drag: which sculpture, moving or turning it, and
    // where it began. The aim ray is followed on a horizontal plane, or,
    // when it began near level, at the distance along it where it grabbed.
    struct MoveDrag {
        int sculpture = -1;
        bool turning = false;
        Placement start;
        float planeY = 0.0f;
        float depth = 0.0f;       // > 0: the near-level mode's distance along the ray
        glm::vec3 startPoint{0.0f};
        double startAngle = 0.0;  // radians about +y, turning only
    };
    std::optional<MoveDrag> moveDrag_;
    // The sketch tool's outline under way: its sculpture, its plane (a
    // point and the normal facing the hand where it began) and the points.
    struct SketchDraw {
        bool drawing = false;
        int sculpture = -1;  // -1: begun in the air, a new sculpture
        glm::vec3 origin{0.0f}, normal{0.0f, 0.0f, 1.0f};
        std::vector<glm::vec3> points;
    };
    SketchDraw sketch_;
    std::string sketchMessage_;
    // The gesture under way: its projection frame and points; circling: a
    // loop recognized in deform mode, deforming the active model as it goes.
    struct GestureDraw {
        bool drawing = false;
        glm::vec3 forward{0.0f, 0.0f, -1.0f}, right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f};
        StrokePoints points;
        std::vector<glm::vec3> trail;
        bool circling = false;
        bool shrink = true;
        double owed = 0.0;  // iterations the circling has earned and not run
    };
    GestureDraw gesture_;
    std::string gestureMessage_;
    std::unique_ptr<GestureRecognizer> gestureRecognizer_;
    // Deformable models, in the order made.
    struct ModelEntry {
        std::string name;
        std::string sculpture;
        std::unique_ptr<deform::DeformableModel> model;
        ModelEntry();
        ~ModelEntry();
        ModelEntry(ModelEntry&&) noexcept;
        ModelEntry& operator=(ModelEntry&&) noexcept;
    };
    std::vector<ModelEntry> models_;
    std::string activeModel_;  // the model circling deforms: the last made
    // Iterations run live on the active model, not yet journalled.
    struct LiveDeform {
        std::string model;
        bool shrink = true;
        int iterations = 0;
    };
    LiveDeform liveDeform_;
    ModelEntry* findModel(const std::string& name);
    const ModelEntry* findModel(const std::string& name) const;
    // The model's sculpture (its index), or why it cannot be deformed against.
    int modelSculpture(const ModelEntry& m, std::string& why) const;
    // The model's selection made its sculpture's.
    void selectModel(const ModelEntry& m);
    std::string toolMessage_;  // toolMessage()
    int liveMove_ = -1;                // the sculpture moved live, or -1
    Placement liveMoveFrom_;           // its placement before the drag
    bool intentScaling_ = false;       // the live move is the tool intents' selection scaling
    // Progressive loading (null when nothing is left to sample). Last: it
    // reads load_'s models and stops before they go.
    std::unique_ptr<SculptureLoader> loader_;
    // Sculptures from the garden file (those added later hold their text in
    // their AddAction; those added from a HyperFun file are watched through
    // addedSources_).
    std::size_t fileSculptures_ = 0;
    // Added HyperFun sculptures by index: the text last applied (their
    // watched file is their spec's `file`).
    std::map<std::size_t, std::string> addedSources_;
    std::string sessionFolder_;  // setSessionFolder()
};

}  // namespace hg::garden
