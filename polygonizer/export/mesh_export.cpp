#include "polygonizer/export/mesh_export.h"

#include "io/checked_write.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <sstream>

#include "polygonizer/export/export_mesher.h"
#include "polygonizer/export/gltf_io.h"
#include "polygonizer/export/mesh_simplify.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/obj_io.h"
#include "polygonizer/export/stl_io.h"
#include "polygonizer/export/tiled_mesher.h"
#include "voxel/memory_guard.h"
#include "voxel/sampler.h"
#include "voxel/vdb_io.h"

namespace hg::poly {

namespace {

using Clock = std::chrono::steady_clock;

bool positiveFinite(double v) { return v > 0.0 && std::isfinite(v); }

// The share of the progress that making the mesh or the grid takes; the
// rest is validating, simplifying and writing.
constexpr double kMakeShare = 0.9;

// True, and the report says so, when the export is to stop: asked just
// before the write, so a cancelled export writes nothing.
bool cancelledBeforeWrite(io::Progress* progress, MeshExportReport& report) {
    report.cancelled = progress && progress->interrupted();
    return report.cancelled;
}

void reportDone(io::Progress* progress) {
    if (progress) progress->interrupted(1.0);
}

void fillGeometry(const MeshReport& r, MeshExportReport& report) {
    report.triangles = r.triangles;
    report.vertices = r.vertices;
    report.volume = r.volume;
    for (int a = 0; a < 3; ++a) {
        report.boxMin[a] = r.boxMin[a];
        report.boxMax[a] = r.boxMax[a];
        report.size[a] = static_cast<double>(r.boxMax[a]) - static_cast<double>(r.boxMin[a]);
    }
}

// Simplifies `mesh` in place (simplifyMesh validates every pass) and says
// in the report what it did.
void simplify(Mesh& mesh, double error, MeshExportReport& report) {
    report.trianglesBeforeSimplify = mesh.triangleCount();
    SimplifyStats s;
    Mesh simpler = simplifyMesh(mesh, error, &s);
    if (!validateMesh(simpler).ok()) {  // kept as a last word: never write a broken mesh
        report.simplifyNote = "simplification left the mesh not fit to write; the unsimplified mesh was written";
        return;
    }
    mesh = std::move(simpler);
    report.simplified = s.passes > 0;
    report.simplifyAchievedError = s.error;
    if (s.stoppedByTopology)
        report.simplifyNote = "simplification stopped at " + std::to_string(mesh.triangleCount()) +
                              " triangles: a further collapse would have left the mesh not closed or not manifold";
}

// A grid's level set written as .vdb; the report's geometry from its mesh.
std::string writeVdbOf(const voxel::Volume& volume, const MeshExportOptions& options, const std::string& path,
                       MeshExportReport& report, io::Progress* progress) {
    const Mesh mesh = meshVolume(volume);
    if (mesh.empty()) return "the model has no surface inside the box";
    fillGeometry(validateMesh(mesh), report);
    report.triangles = report.vertices = 0;
    if (cancelledBeforeWrite(progress, report)) return io::kCancelled;
    return voxel::writeLevelSet(volume, path, options.metresPerUnit);
}

std::string exportVdb(const frep::Model& model, const frep::Box3& box, const MeshExportOptions& options,
                      const std::string& path, MeshExportReport& report, io::Progress* progress) {
    voxel::VolumeRequest req;
    req.box = box;
    req.resolution = options.resolution;
    req.source.body = model.body().spelling;
    voxel::SampleOptions so;
    so.memoryLimit = options.memoryLimitMiB << 20;
    io::ProgressRange sampling(progress, 0.0, kMakeShare);
    so.progress = &sampling;
    voxel::VoxelizeResult v = voxel::voxelize(model, req, so);
    report.cancelled = v.cancelled;
    if (!v.volume) return v.error;
    report.estimatedBytes = v.stats.estimatedBytes;
    report.limitBytes = voxel::memoryLimit(so.memoryLimit);
    report.peakTileBytes = v.volume->memoryBytes();
    if (std::string why = writeVdbOf(*v.volume, options, path, report, progress); !why.empty()) return why;
    reportDone(progress);
    return "";
}

}  // namespace

std::string meshFormatOf(const std::string& path, MeshFormat& format) {
    const std::size_t dot = path.find_last_of('.');
    const std::size_t slash = path.find_last_of('/');
    std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == "stl") format = MeshFormat::Stl;
    else if (ext == "obj") format = MeshFormat::Obj;
    else if (ext == "glb") format = MeshFormat::Glb;
    else if (ext == "vdb") format = MeshFormat::Vdb;
    else return path + ": unknown extension" + (ext.empty() ? "" : " ." + ext) + " (use .stl, .obj, .glb or .vdb)";
    return "";
}

const char* meshFormatName(MeshFormat format) {
    switch (format) {
        case MeshFormat::Stl: return "STL";
        case MeshFormat::Obj: return "OBJ";
        case MeshFormat::Glb: return "glTF binary";
        case MeshFormat::Vdb: return "VDB level set";
    }
    return "STL";
}

namespace {

// The checks that need no work: the format, its options, a writable path.
std::string checkRequest(const MeshExportOptions& options, const std::string& path, MeshExportReport& report) {
    if (std::string why = meshFormatOf(path, report.format); !why.empty()) return why;
    const MeshFormat format = report.format;
    if (format == MeshFormat::Stl && !positiveFinite(options.mmPerUnit))
        return "millimetres per model unit must be finite and positive";
    if ((format == MeshFormat::Obj || format == MeshFormat::Glb) && !positiveFinite(options.metresPerUnit))
        return "metres per model unit must be finite and positive";
    if (!(options.simplifyError >= 0.0) || !std::isfinite(options.simplifyError))
        return "the simplification error must be a finite number of model units, 0 or more";
    if (options.simplifyError > 0.0 && format == MeshFormat::Vdb) return "simplification applies to meshes, not to .vdb";
    if (options.ascii && format != MeshFormat::Stl) return "ASCII applies to STL only";
    return io::checkWritable(path);
}

// A finished mesh validated (never written when not closed, manifold and
// outward), optionally simplified, and written in the report's format.
std::string writeMeshFile(Mesh& mesh, const MeshExportOptions& options, const std::string& path,
                          MeshExportReport& report, io::Progress* progress) {
    const MeshFormat format = report.format;
    MeshReport checked = validateMesh(mesh);
    if (!checked.ok()) return describeUnfitMesh(checked, format, options);
    if (options.simplifyError > 0.0) {
        simplify(mesh, options.simplifyError, report);
        if (report.simplified) checked = validateMesh(mesh);
    }
    fillGeometry(checked, report);
    if (cancelledBeforeWrite(progress, report)) return io::kCancelled;
    switch (format) {
        case MeshFormat::Stl: return writeStl(mesh, path, options.ascii, options.mmPerUnit);
        case MeshFormat::Obj: return writeObj(mesh, path, options.metresPerUnit);
        case MeshFormat::Glb: return writeGlb(mesh, path, options.metresPerUnit);
        case MeshFormat::Vdb: break;
    }
    return "";
}

}  // namespace

std::string exportMesh(const frep::Model& model, const frep::Box3& box, const MeshExportOptions& options,
                       const std::string& path, MeshExportReport& report, io::Progress* progress) {
    const auto start = Clock::now();
    report = MeshExportReport{};
    if (std::string why = checkRequest(options, path, report); !why.empty()) return why;
    if (report.format == MeshFormat::Vdb) {
        std::string why = exportVdb(model, box, options, path, report, progress);
        report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return why;
    }

    TiledMeshOptions to;
    to.resolution = options.resolution;
    to.tileSize = options.tileSize;
    to.memoryLimit = options.memoryLimitMiB << 20;
    io::ProgressRange meshing(progress, 0.0, kMakeShare);
    to.progress = &meshing;
    to.bytesPerTriangle = options.simplifyError > 0.0 ? kSimplifyBytesPerTriangle : kMeshBytesPerTriangle;
    TiledMeshResult tiled = meshModelTiled(model, box, to);
    report.tiles = tiled.stats.tiles;
    report.tileSize = tiled.plan.tileSize;
    report.peakTileBytes = tiled.stats.peakTileBytes;
    report.estimatedBytes = tiled.plan.estimatedBytes;
    report.limitBytes = tiled.plan.limit;
    report.meshSeconds = tiled.stats.seconds;
    report.planSeconds = tiled.stats.planSeconds;
    report.sampleSeconds = tiled.stats.sampleSeconds;
    report.leafTapeMean = tiled.stats.leafTapeMean;
    report.leafTapeMax = tiled.stats.leafTapeMax;
    report.cancelled = tiled.cancelled;
    if (!tiled.error.empty()) return tiled.error;
    std::string why = writeMeshFile(tiled.mesh, options, path, report, progress);
    if (why.empty()) reportDone(progress);
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return why;
}

std::string exportVolumeMesh(const voxel::Volume& volume, const MeshExportOptions& options, const std::string& path,
                             MeshExportReport& report, io::Progress* progress) {
    const auto start = Clock::now();
    report = MeshExportReport{};
    if (std::string why = checkRequest(options, path, report); !why.empty()) return why;
    report.peakTileBytes = volume.memoryBytes();
    report.limitBytes = voxel::memoryLimit(options.memoryLimitMiB << 20);
    if (report.format == MeshFormat::Vdb) {
        if (progress) progress->interrupted(0.5);
        std::string why = writeVdbOf(volume, options, path, report, progress);
        if (why.empty()) reportDone(progress);
        report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return why;
    }
    ExportStats stats;
    Mesh mesh = meshVolume(volume, &stats);
    report.meshSeconds = stats.seconds;
    if (progress) progress->interrupted(0.5);
    if (mesh.empty()) return "the grid has no surface";
    const std::string why = writeMeshFile(mesh, options, path, report, progress);
    if (why.empty()) reportDone(progress);
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return why;
}

FileUnit fileUnitOf(MeshFormat format, const MeshExportOptions& options) {
    if (format == MeshFormat::Stl) return {options.mmPerUnit, "mm"};
    return {options.metresPerUnit, "m"};  // OBJ, glTF and the level set's transform and values
}

std::string describeUnfitMesh(const MeshReport& r, MeshFormat format, const MeshExportOptions& options) {
    // In the file's units: at one millimetre per model unit the report had
    // a sculpture 1.49 mm across whose STL would be 1,492 mm.
    const FileUnit u = fileUnitOf(format, options);
    return "the mesh is not fit to write (" + std::string(r.closed() ? "" : "not closed; ") +
           (r.manifold() ? "" : "not manifold; ") + (r.outwardFacing() ? "" : "not facing outward; ") +
           "see docs/mesh-export.md):\n" + describe(r, u.perModelUnit, u.name);
}

std::string describe(const MeshExportReport& r, const MeshExportOptions& o) {
    const FileUnit u = fileUnitOf(r.format, o);
    const double unit = u.perModelUnit;
    const char* name = u.name;
    std::ostringstream m;
    m.precision(6);
    m << meshFormatName(r.format);
    if (r.format != MeshFormat::Vdb) m << ", " << r.triangles << " triangles, " << r.vertices << " vertices";
    m << "\nvolume " << r.volume * unit * unit * unit << " " << name << "^3, size " << r.size[0] * unit << " x "
      << r.size[1] * unit << " x " << r.size[2] * unit << " " << name << "\n";
    if (r.simplified)
        m << "simplified from " << r.trianglesBeforeSimplify << " triangles, deviation up to "
          << r.simplifyAchievedError * unit << " " << name << "\n";
    if (!r.simplifyNote.empty()) m << "note: " << r.simplifyNote << "\n";
    if (r.tiles) m << r.tiles << " tiles of " << r.tileSize << "^3 cells, largest tile grid " << voxel::formatBytes(r.peakTileBytes) << "; ";
    m << "estimated " << voxel::formatBytes(r.estimatedBytes) << " of " << voxel::formatBytes(r.limitBytes)
      << "; " << r.seconds << " s\n";
    return m.str();
}

}  // namespace hg::poly
