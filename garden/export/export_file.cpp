#include "garden/export/export_file.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <sstream>

#include "frep/language/diagnostics.h"
#include "frep/language/parser.h"
#include "garden/app/garden_session.h"
#include "garden/export/hyperfun_export.h"
#include "garden/scene/model_file.h"
#include "garden/sculpt/sculpture_edits.h"
#include "polygonizer/export/mesh_export.h"
#include "voxel/volume.h"

namespace hg::garden {

namespace {

std::string lowerExtension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

// A scanned volume's or a mesh's sculpture: no FRep, so a mesh of its grid as it stands
// (a copy, for the worker), at the grid's resolution and over its box.
std::string prepareGridExport(const GardenSession& session, const Sculpture& s, const std::string& path, const ExportFileOptions& options,
                              ExportJob& job, std::chrono::steady_clock::time_point start) {
    if (lowerExtension(path) == ".hf") return scanRefusal(session, s);
    const int grid = s.volume->frame.resolution;
    if (options.resolution != 0 && options.resolution != grid)
        return "sculpture '" + s.name + "' is " + (s.meshed() ? "a mesh" : "a scanned volume") + ": it is meshed from its grid, at the grid's " +
               std::to_string(grid) + " voxels along its longest side (give no resolution, or " + std::to_string(grid) +
               "; a finer grid comes from a finer \"resolution\" in the garden file)";
    if (options.box) return "sculpture '" + s.name + "' is a scanned volume: it is meshed from its whole grid, not over a box";
    job.path = path;
    job.sculpture = s.name;
    job.edits = s.edits ? s.edits->list().size() : 0;
    job.box = s.volume->frame.modelBox;
    job.gridResolution = grid;
    job.metresPerUnit = s.scale();
    job.options = options;
    // An edit whose grid update is still spread over frames is in the copy.
    job.grid = std::make_shared<const voxel::Volume>(s.edits ? s.edits->settledGrid() : s.volume->clone());
    job.prepareSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return "";
}

poly::MeshExportOptions meshOptionsOf(const ExportJob& job) {
    const ExportFileOptions& o = job.options;
    poly::MeshExportOptions mo;
    mo.resolution = o.resolution > 0 ? o.resolution : job.gridResolution;
    mo.ascii = o.ascii;
    mo.metresPerUnit = job.metresPerUnit;
    // A sculpture's true size unless the user asks for another scale.
    mo.mmPerUnit = o.mmPerUnit ? *o.mmPerUnit : 1000.0 * job.metresPerUnit;
    mo.simplifyError = o.simplifyError;
    mo.memoryLimitMiB = static_cast<std::uint64_t>(std::max(0.0, o.memoryLimitMiB));
    return mo;
}

std::string meshSummary(const ExportJob& job, const poly::MeshExportReport& mr, const poly::MeshExportOptions& mo) {
    std::ostringstream out;
    out << "wrote " << job.path << ": sculpture '" << job.sculpture << "', " << job.edits << " edits"
        << (job.grid ? " (meshed from its grid)" : "") << "\n"
        << poly::describe(mr, mo);
    std::string summary = out.str();
    while (!summary.empty() && summary.back() == '\n') summary.pop_back();
    return summary;
}

std::string writeGridExport(const ExportJob& job, ExportFileReport& report, io::Progress* progress) {
    const poly::MeshExportOptions mo = meshOptionsOf(job);
    poly::MeshExportReport mr;
    std::string e = poly::exportVolumeMesh(*job.grid, mo, job.path, mr, progress);
    report.cancelled = mr.cancelled;
    if (!e.empty()) return e;
    report.summary = meshSummary(job, mr, mo);
    return "";
}

}  // namespace

bool isExportExtension(const std::string& path) {
    const std::string e = lowerExtension(path);
    return e == ".hf" || e == ".stl" || e == ".obj" || e == ".glb" || e == ".vdb";
}

std::string prepareExport(const GardenSession& session, int index, const std::string& path,
                          const ExportFileOptions& options, ExportJob& job, ExportFileReport& report) {
    report = {};
    if (!isExportExtension(path))
        return path + ": unknown format '" + lowerExtension(path) + "': the export writes " + kExportExtensions;
    if (index < 0 || static_cast<std::size_t>(index) >= session.sculptures().size())
        return "no sculpture with index " + std::to_string(index);
    const Sculpture& s = session.sculptures()[static_cast<std::size_t>(index)];
    if (s.removed) return "sculpture '" + s.name + "' was removed";
    if (s.missing()) return "sculpture '" + s.name + "' is missing: " + s.error;
    if (options.resolution < 0) return "the resolution must be positive";
    if (!s.volume) return "sculpture '" + s.name + "' has no grid to take its model box from";
    const auto start = std::chrono::steady_clock::now();
    if (s.gridOnly()) return prepareGridExport(session, s, path, options, job, start);
    HyperFunExport hf = exportHyperFun(session, index);
    if (!hf.error.empty()) return "cannot export sculpture '" + s.name + "': " + hf.error;
    report.warning = hf.warning;
    job.path = path;
    job.sculpture = s.name;
    job.hyperFun = std::move(hf.text);
    job.edits = hf.edits;
    job.pieces = hf.pieces;
    job.statements = hf.statements;
    job.box = options.box ? *options.box : s.volume->frame.modelBox;
    job.gridResolution = s.volume->frame.resolution;
    job.metresPerUnit = s.scale();
    job.options = options;
    job.prepareSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return "";
}

std::string writeExport(const ExportJob& job, ExportFileReport& report, io::Progress* progress) {
    const auto start = std::chrono::steady_clock::now();
    std::ostringstream out;
    if (lowerExtension(job.path) == ".hf") {
        HyperFunExport hf;
        hf.text = job.hyperFun;
        report.cancelled = progress && progress->interrupted();
        if (report.cancelled) return io::kCancelled;
        if (std::string why = writeHyperFunExport(hf, job.path); !why.empty()) return why;
        if (progress) progress->interrupted(1.0);
        const double seconds =
            job.prepareSeconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        out << "wrote " << job.path << ": sculpture '" << job.sculpture << "', " << job.edits << " edits ("
            << job.pieces << " pieces), " << job.statements << " statements in my_model, " << job.hyperFun.size()
            << " bytes, " << seconds << " s";
        report.summary = out.str();
        return "";
    }
    if (job.grid) return writeGridExport(job, report, progress);
    // A mesh is made from the exported FRep itself, not from the grid, so it
    // can be finer than the grid the sculpture was edited at and is the very
    // solid the .hf file describes.
    frep::ParseResult parsed = frep::parseProgram(job.hyperFun, job.sculpture + ".hf");
    if (!parsed.ok()) {
        std::string why = "the exported HyperFun of '" + job.sculpture + "' does not parse (a bug):\n";
        for (const auto& d : parsed.errors) why += frep::formatDiagnostic(d);
        return why;
    }
    auto program = std::make_shared<const frep::Program>(std::move(*parsed.program));
    std::string why;
    const int body = findBodyOrExplain(*program, "my_model", job.sculpture + ".hf", why);
    if (body < 0) return why;
    const frep::Model model(program, body, {});
    const poly::MeshExportOptions mo = meshOptionsOf(job);
    poly::MeshExportReport mr;
    std::string e = poly::exportMesh(model, job.box, mo, job.path, mr, progress);
    report.cancelled = mr.cancelled;
    if (!e.empty()) return e;
    report.summary = meshSummary(job, mr, mo);
    return "";
}

std::string exportSculptureFile(const GardenSession& session, int index, const std::string& path,
                                const ExportFileOptions& options, ExportFileReport& report,
                                io::Progress* progress) {
    ExportJob job;
    if (std::string why = prepareExport(session, index, path, options, job, report); !why.empty()) return why;
    const std::string warning = report.warning;
    std::string why = writeExport(job, report, progress);
    report.warning = warning;
    return why;
}

}  // namespace hg::garden
