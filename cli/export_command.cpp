// `hypergarden export (SESSION_DIR | GARDEN.json) --sculpture NAME -o OUT`:
// one sculpture as it stands in a session (the journal played, read only:
// the folder is not changed) or as a garden file gives it, written as exact
// HyperFun (docs/export.md). Every check that needs no work comes first;
// the file is written atomically, so a failure leaves none.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "garden/app/garden_session.h"
#include "cli/commands.h"
#include "cli/load_model.h"
#include "cli/open_read_only.h"
#include "cli/progress_bar.h"
#include "garden/export/export_file.h"
#include "garden/export/hyperfun_export.h"

namespace hg::garden::cli {

int runExport(const ExportOptions& options) {
    if (!isExportExtension(options.output)) {
        std::cerr << "error: " << options.output << ": unknown format '" << lowerExtension(options.output)
                  << "': the export writes " << kExportExtensions << "\n";
        return 2;
    }
    if (options.resolution < 0) {
        std::cerr << "error: --res must be positive\n";
        return 2;
    }
    if (options.mmPerUnit < 0.0 || options.simplifyError < 0.0 || options.memoryLimitMiB < 0.0) {
        std::cerr << "error: --mm-per-unit, --simplify and --memory-limit must not be negative\n";
        return 2;
    }
    ExportFileOptions fo;
    if (!options.box.empty()) {
        std::optional<frep::Box3> box;
        if (!boxOption(options.box, box)) return 2;
        fo.box = box;
    }
    if (!outputWritable(options.output)) return 2;
    int status = 0;
    SessionSettings settings;
    settings.maxLevel = 0;  // no window: the coarsest meshes are not wanted
    std::unique_ptr<GardenSession> session = openReadOnly(options.input, settings, "exporting", status);
    if (!session) return status;
    const int index = findUsableSculpture(*session, options.input, options.sculpture, status);
    if (index < 0) return status;
    const Sculpture& s = session->sculptures()[static_cast<std::size_t>(index)];
    fo.resolution = options.resolution;
    if (options.mmPerUnit > 0.0) fo.mmPerUnit = options.mmPerUnit;
    fo.ascii = options.ascii;
    fo.simplifyError = options.simplifyError;
    fo.memoryLimitMiB = options.memoryLimitMiB;
    ExportFileReport report;
    std::string why;
    {
        ProgressBar bar("export " + s.name);
        why = exportSculptureFile(*session, index, options.output, fo, report, &bar);
    }
    if (!report.warning.empty()) std::cerr << "warning: " << report.warning << "\n";
    if (!why.empty()) {
        std::cerr << "error: " << why << (why.back() == '\n' ? "" : "\n");
        return 1;
    }
    std::cout << report.summary << "\n";
    return 0;
}

}  // namespace hg::garden::cli
