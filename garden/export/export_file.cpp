#include "garden/export/export_file.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <sstream>

#include "frep/diagnostics.h"
#include "frep/parser.h"
#include "garden/app/garden_session.h"
#include "garden/export/hyperfun_export.h"
#include "garden/scene/model_file.h"
#include "polygonizer/mesh_export.h"

namespace hg::garden {

namespace {

std::string lowerExtension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
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
    job.metresPerUnit = s.scale;
    job.options = options;
    job.prepareSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return "";
}

std::string writeExport(const ExportJob& job, ExportFileReport& report, const std::function<void(double)>& progress) {
    const auto start = std::chrono::steady_clock::now();
    std::ostringstream out;
    if (lowerExtension(job.path) == ".hf") {
        HyperFunExport hf;
        hf.text = job.hyperFun;
        if (std::string why = writeHyperFunExport(hf, job.path); !why.empty()) return why;
        const double seconds =
            job.prepareSeconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        out << "wrote " << job.path << ": sculpture '" << job.sculpture << "', " << job.edits << " edits ("
            << job.pieces << " pieces), " << job.statements << " statements in my_model, " << job.hyperFun.size()
            << " bytes, " << seconds << " s";
        report.summary = out.str();
        return "";
    }
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
    const ExportFileOptions& o = job.options;
    poly::MeshExportOptions mo;
    mo.resolution = o.resolution > 0 ? o.resolution : job.gridResolution;
    mo.ascii = o.ascii;
    mo.metresPerUnit = job.metresPerUnit;
    // A sculpture's true size unless the user asks for another scale.
    mo.mmPerUnit = o.mmPerUnit ? *o.mmPerUnit : 1000.0 * job.metresPerUnit;
    mo.simplifyError = o.simplifyError;
    mo.memoryLimitMiB = static_cast<std::uint64_t>(std::max(0.0, o.memoryLimitMiB));
    poly::MeshExportReport mr;
    if (std::string e = poly::exportMesh(model, job.box, mo, job.path, mr, progress); !e.empty()) return e;
    out << "wrote " << job.path << ": sculpture '" << job.sculpture << "', " << job.edits << " edits\n"
        << poly::describe(mr, mo);
    report.summary = out.str();
    while (!report.summary.empty() && report.summary.back() == '\n') report.summary.pop_back();
    return "";
}

std::string exportSculptureFile(const GardenSession& session, int index, const std::string& path,
                                const ExportFileOptions& options, ExportFileReport& report,
                                const std::function<void(double)>& progress) {
    ExportJob job;
    if (std::string why = prepareExport(session, index, path, options, job, report); !why.empty()) return why;
    const std::string warning = report.warning;
    std::string why = writeExport(job, report, progress);
    report.warning = warning;
    return why;
}

}  // namespace hg::garden
