// One sculpture of the running garden (docs/design.md §4): what the user made (its
// source, its edit list, its placement) and the caches rebuilt from them
// (the grid, its LOD pyramid, chunk layout and remesh queue). The morph
// result is a sculpture like the others: its source is the blend of three
// sculptures instead of a HyperFun body, and it holds its morph's state.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "garden/scene/garden.h"
#include "garden/sculpt/edit.h"
#include "polygonizer/realtime/chunk_errors.h"
#include "polygonizer/realtime/chunk_layout.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "polygonizer/realtime/remesh_queue.h"
#include "voxel/volume.h"

namespace hg::frep { struct Program; class Model; }

namespace hg::garden {

class SculptureEdits;
struct MorphState;

// What a sculpture's field is made from.
struct SculptureSource {
    enum class Kind { HyperFun, Morph, Scan, Mesh };
    Kind kind = Kind::HyperFun;
    // HyperFun: the garden's entry (file, body, a[], box, resolution) by its
    // index in Garden::sculptures and GardenLoad::sculptures (an index: a
    // sculpture added while the garden runs appends to both), and the
    // program read from it (null when the file is missing or broken).
    // Scan: the same index; its entry's `scan` names the volume and the
    // iso-value (docs/volumes.md, "Scanned volumes"), and its base grid is
    // the iso-surface rebuilt as a level set. It has no program: it cannot
    // be written as HyperFun, only meshed from its grid.
    // Mesh: the same index; its entry's `mesh` names an STL, OBJ or PLY
    // file whose triangles became the base grid (voxel/mesh_volume.h), and
    // like a scan it has no program.
    // Morph: the index in Garden::morphs (its triangle of sources); the
    // sources' caches, weights and blender are the Sculpture's `morph`.
    int spec = -1;
    std::shared_ptr<const frep::Program> program;
};

// What a sculpture's last chunk-by-chunk level selection was made from
// (GardenSession::selectLevels makes it again only when these change or the
// eye has moved far enough).
struct LevelsChosen {
    bool valid = false;
    std::array<double, 3> eye{};   // model frame
    std::uint64_t errors = 0;      // ChunkErrors::version()
    std::array<double, 4> detail{};  // the detail sphere's centre (model frame) and radius; radius < 0: none
    int finest = 0;                // its grid on disk keeps level 1 or coarser
    bool anyFull = false;          // some chunk took level 0
    // The camera's viewport height and field of view, and the LOD's pixel
    // error, measured-error pixels and coarsest level: the automatic
    // quality changes the viewport (the render and detail scales) while
    // the visitor may stand still.
    std::array<double, 5> view{};
    bool sameInputs(const LevelsChosen& o) const {
        return valid && o.valid && errors == o.errors && finest == o.finest && detail == o.detail && view == o.view;
    }
};

struct Sculpture {
    std::string name;
    SculptureSource source;
    std::string error;                 // non-empty: missing (shown as such), no caches
    Placement placement;               // where it stands in the garden
    std::optional<MirrorPlane> mirror; // strokes act on both sides of it (model frame)
    // The selection edits act inside (a deformable model's, by name): none, everywhere.
    std::optional<SelectionMask> selection;
    std::string selectionModel;
    Material material;
    // The placement as a matrix, and metres per model unit: both read from
    // `placement`, the one place a sculpture's position is kept.
    glm::mat4 modelToWorld() const;
    double scale() const { return placement.scale; }
    // The edit list and the unedited grid (made at the first edit).
    std::unique_ptr<SculptureEdits> edits;
    // Caches, rebuilt from the above.
    std::unique_ptr<voxel::Volume> volume;
    std::unique_ptr<poly::LodPyramid> pyramid;
    std::unique_ptr<poly::ChunkLayout> layout;
    // How far each chunk's coarser levels stray (none: levels by voxel size alone).
    std::unique_ptr<poly::ChunkErrors> errors;
    std::unique_ptr<poly::RemeshQueue> queue;
    // A morph result's caches, weights and blender (garden/morph/morph_state.h);
    // none for other sculptures, and for a result whose sources are missing.
    // Declared after the grid it writes, so it goes first.
    std::unique_ptr<MorphState> morph;
    int framesSinceLevels = 0;         // frames since the queue last took new levels
    int uniformLevel = -1;             // the one level the queue's chunks last took, or -1 when they differ
    LevelsChosen levelsChosen;         // when they differ: what they were chosen from

    Sculpture();
    ~Sculpture();
    Sculpture(Sculpture&&) noexcept;
    Sculpture& operator=(Sculpture&&) noexcept;

    bool loading = false;              // sampled in the background (progressive loading): no caches yet
    // Its HyperFun file on disk (GardenSession::reloadChangedSources): the
    // modification time it was last read at, and why the file as it is now
    // is not shown ("": it is; else the parser's message, the last good one kept).
    std::int64_t sourceStamp = 0;
    std::string sourceProblem;
    // Counts the times the grid was replaced by one of another frame (its
    // chunks are others then): a view drops the meshes it uploaded before.
    std::uint64_t frameGeneration = 0;

    bool missing() const { return !error.empty(); }
    // Its adding was undone (AddAction): not shown, picked, edited or found
    // by name; its caches stay so that redo shows it at once.
    bool removed = false;
    // In the garden with a grid: what is drawn, picked and meshed.
    bool onShow() const { return !removed && hasGrid(); }
    // The grid and its meshing caches are there: neither missing nor loading.
    bool hasGrid() const { return !missing() && !loading; }
    bool morphResult() const { return source.kind == SculptureSource::Kind::Morph; }
    bool scanned() const { return source.kind == SculptureSource::Kind::Scan; }
    bool meshed() const { return source.kind == SculptureSource::Kind::Mesh; }
    // Made from a grid with no HyperFun behind it (a scan, a mesh): meshed
    // from its grid for export, never written as HyperFun.
    bool gridOnly() const { return scanned() || meshed(); }
    glm::vec3 worldCentre() const;
};

// Where a placement puts model points: translate, turn about +y, scale.
glm::mat4 placementMatrix(const Placement& p);

}  // namespace hg::garden
