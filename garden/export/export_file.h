// One sculpture of a running garden written to a file in any export format
// (docs/design.md §7, docs/export.md): exact HyperFun (.hf), or a mesh meshed from
// that exported FRep (.stl, .obj, .glb, .vdb: polygonizer/export/mesh_export.h), so
// every format shows the same solid. A scanned volume's sculpture has no
// FRep to write: its meshes come from its grid as it stands, at the grid's
// resolution, and .hf is refused (docs/volumes.md, "Scanned volumes"). The command line (`hypergarden
// export`) and the desktop panel's Export button both call this.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "frep/kernels/box.h"
#include "io/progress.h"

namespace hg::voxel { class Volume; }

namespace hg::garden {

class GardenSession;

struct ExportFileOptions {
    int resolution = 0;          // mesh formats: voxels along the longest side (0: the sculpture's grid)
    std::optional<double> mmPerUnit;  // STL: millimetres per model unit (none: the placement's, 1000 x metres per unit)
    bool ascii = false;          // STL: ASCII instead of binary
    std::optional<frep::Box3> box;  // mesh formats: a model box instead of the sculpture's
    double simplifyError = 0.0;  // mesh formats but .vdb: meshoptimizer's error bound, model units (0: none)
    double memoryLimitMiB = 0.0; // mesh formats: 0: what the machine has free
};

// What was written, in words for a terminal or the panel.
struct ExportFileReport {
    std::string summary;  // "wrote PATH: ...", one line
    std::string warning;  // set when something is worth saying beside it
    bool cancelled = false;  // the progress was cancelled: nothing was written (the error is io::kCancelled)
};

// An export taken from the session (on the thread that owns it) and
// written later, on any thread: the desktop meshes in the background while
// the garden goes on.
struct ExportJob {
    std::string path;
    std::string sculpture;    // its name
    std::string hyperFun;     // the exported program (exportHyperFun)
    std::size_t edits = 0, pieces = 0, statements = 0;
    frep::Box3 box;           // model box to mesh over
    int gridResolution = 0;   // the sculpture's grid
    double metresPerUnit = 1.0;
    ExportFileOptions options;
    double prepareSeconds = 0.0;  // taking the HyperFun text from the session
    // A scanned volume's sculpture: a copy of its grid, meshed instead of
    // the HyperFun text (there is none).
    std::shared_ptr<const voxel::Volume> grid;
};
// "" and the job, or why not (nothing is written yet).
std::string prepareExport(const GardenSession& session, int index, const std::string& path,
                          const ExportFileOptions& options, ExportJob& job, ExportFileReport& report);
// Writes a prepared job. "" on success, else why not (no file is left).
// `progress` (may be null) is told the fraction done while a mesh is made
// and may cancel it before the write (poly::exportMesh).
std::string writeExport(const ExportJob& job, ExportFileReport& report, io::Progress* progress = nullptr);

// Writes sculpture `index` of `session` to `path`, the format by its
// extension (prepareExport then writeExport). "" on success, else why not (nothing is left at `path`).
// `progress` as writeExport's.
std::string exportSculptureFile(const GardenSession& session, int index, const std::string& path,
                                const ExportFileOptions& options, ExportFileReport& report,
                                io::Progress* progress = nullptr);

// The formats by extension, for error messages and the panel.
constexpr const char* kExportExtensions = ".hf, .stl, .obj, .glb or .vdb";
bool isExportExtension(const std::string& path);

}  // namespace hg::garden
