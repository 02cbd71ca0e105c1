// A sculpture's FRep out of the garden as a file for printing or for other
// programs: the one call `hypergarden export` makes for every format but
// HyperFun (.hf). See docs/mesh-export.md.
//
//   .stl  binary (or ASCII) STL, millimetres: model units times mmPerUnit
//   .obj  Wavefront OBJ with vertex normals, metres: times metresPerUnit
//   .glb  glTF 2.0 binary with normals, metres: times metresPerUnit
//   .vdb  the narrow-band level set in OpenVDB's convention (negative inside,
//         signed distance in metres: times metresPerUnit, class level set) with our
//         metadata (voxel/vdb_io.h's writeLevelSet)
//
// Meshes come from the tiled export mesher (tiled_mesher.h) at any
// resolution, in memory bounded by the memory guard, are validated closed,
// manifold and outward before anything is written, optionally simplified
// (and validated again), and are written atomically: on any failure no
// file (and no partial file) is left at the path.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "frep/eval/model.h"
#include "frep/kernels/box.h"
#include "io/progress.h"
#include "polygonizer/export/mesh_validation.h"
#include "voxel/volume.h"

namespace hg::poly {

enum class MeshFormat { Stl, Obj, Glb, Vdb };

// "" and the format named by `path`'s extension (case-insensitive: .stl,
// .obj, .glb, .vdb), or why there is none.
std::string meshFormatOf(const std::string& path, MeshFormat& format);
const char* meshFormatName(MeshFormat format);  // "STL", "OBJ", "glTF binary", "VDB level set"

struct MeshExportOptions {
    int resolution = 256;           // voxels along the model box's longest side (4 .. 16384)
    bool ascii = false;             // STL only: ASCII instead of binary
    double mmPerUnit = 1.0;         // STL: millimetres per model unit
    double metresPerUnit = 1.0;     // OBJ, glTF: metres per model unit (the sculpture's placement scale)
    double simplifyError = 0.0;     // model units; > 0: simplify (meshes only)
    std::uint64_t memoryLimitMiB = 0;  // 0: 80% of the memory available now
    int tileSize = 0;               // cells per tile side (a multiple of 8); 0: chosen by the guard
};

struct MeshExportReport {
    MeshFormat format = MeshFormat::Stl;
    std::size_t triangles = 0;       // written (0 for VDB)
    std::size_t vertices = 0;
    double volume = 0.0;             // model units^3, of the written mesh (VDB: of the grid's mesh)
    double boxMin[3] = {0, 0, 0};    // model units, the written mesh's bounding box
    double boxMax[3] = {0, 0, 0};
    double size[3] = {0, 0, 0};      // boxMax - boxMin, model units
    double seconds = 0.0;            // the whole export
    double meshSeconds = 0.0;        // of which planning, sampling, meshing and welding the tiles
    double planSeconds = 0.0;        // of which the plan (coarse sampling, normalization)
    double sampleSeconds = 0.0;      // of which sampling the tiles
    double leafTapeMean = 0.0;       // the tape each evaluated leaf ran (voxel::SampleStats)
    std::uint64_t leafTapeMax = 0;
    std::size_t tiles = 0;           // tiles sampled (meshes)
    int tileSize = 0;
    std::uint64_t peakTileBytes = 0; // the largest tile's grid (VDB: the whole grid)
    std::uint64_t estimatedBytes = 0;  // the memory guard's estimate
    std::uint64_t limitBytes = 0;
    // --simplify: what it did (mesh_simplify.h). Every pass is validated;
    // where a further collapse would break the surface, simplification
    // stops there and simplifyNote says so.
    bool simplified = false;
    std::size_t trianglesBeforeSimplify = 0;
    double simplifyAchievedError = 0.0;  // model units, the sum of the passes' deviations
    std::string simplifyNote;
    bool cancelled = false;          // the progress was cancelled before the write: nothing written
};

// Exports `model` over `box` (its model box, in model units) to `path`.
// Returns "" on success (and fills `report`), otherwise a message for a
// person: an unknown extension, a bad option, an unwritable path, a
// resolution of 0 or past what fits in the memory limit (with the largest
// that would fit), a model with no surface in the box, a mesh that fails
// validation, or a failed write. Nothing is left at `path` on failure.
// `progress` (may be null; io/progress.h) is told the fraction done, from
// the sampler's workers too, reaching 1 once the file is written; cancelled
// before the write starts, the export stops with io::kCancelled and
// report.cancelled, and whatever was at `path` is left as it was. A write
// under way is let finish.
std::string exportMesh(const frep::Model& model, const frep::Box3& box, const MeshExportOptions& options,
                       const std::string& path, MeshExportReport& report, io::Progress* progress = nullptr);

// Exports a finished grid as it stands (a scanned volume's sculpture, which
// has no FRep to sample at another resolution: docs/volumes.md, "Scanned
// volumes"): its mesh at the grid's own resolution (export_mesher.h),
// validated, optionally simplified and written like exportMesh's; .vdb
// writes the grid's level set. The same messages and guarantees.
std::string exportVolumeMesh(const voxel::Volume& volume, const MeshExportOptions& options, const std::string& path,
                             MeshExportReport& report, io::Progress* progress = nullptr);

// A few lines for a person: format, triangles, volume and size in the
// file's units, time, tiles and memory.
std::string describe(const MeshExportReport& report, const MeshExportOptions& options);

// The length unit of `format`'s files, and how many of it make one model
// unit: STL millimetres (options.mmPerUnit), OBJ, glTF and VDB metres
// (options.metresPerUnit). Every size a report gives is in it.
struct FileUnit {
    double perModelUnit = 1.0;
    const char* name = "mm";
};
FileUnit fileUnitOf(MeshFormat format, const MeshExportOptions& options);

// Why a mesh is not written, with its validation report in the file's
// units: what exportMesh says when validation fails.
std::string describeUnfitMesh(const MeshReport& report, MeshFormat format, const MeshExportOptions& options);

}  // namespace hg::poly
