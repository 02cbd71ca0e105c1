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
#include "cli/progress_bar.h"
#include "garden/export/export_file.h"
#include "garden/export/hyperfun_export.h"
#include "garden/session/journal.h"
#include "garden/session/session_folder.h"
#include "io/folder_lock.h"

namespace hg::garden::cli {

namespace {

std::string lowerExtension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return e;
}

// The garden of `input` with its session's journal played (none for a
// garden file). Prints why not and sets `status` when it cannot be opened.
std::unique_ptr<GardenSession> openForExport(const std::string& input, int& status) {
    status = 2;
    std::string gardenFile = input;
    JournalRead journal;
    const bool folder = std::filesystem::is_directory(input);
    if (folder) {
        const SessionPaths paths(input);
        if (!std::filesystem::exists(paths.manifest)) {
            std::cerr << "error: " << input << " is not a session folder (no session.json)\n";
            return nullptr;
        }
        if (std::string why = checkSessionManifest(paths); !why.empty()) {
            std::cerr << "error: " << why << "\n";
            return nullptr;
        }
        gardenFile = paths.garden;
        // Exporting only reads: a session open elsewhere is read as its
        // journal stands now, and the user is told so.
        if (const auto holder = io::lockHolder(input, kSessionLockFile))
            std::cerr << "note: " << input << " is open in " << holder->describe()
                      << "; exporting what its journal holds now (the session is not changed)\n";
        if (std::filesystem::exists(paths.journal)) {
            journal = readJournal(paths.journal);
            if (!journal.ok()) {
                std::cerr << "error: " << journal.error << "\n";
                return nullptr;
            }
            if (journal.damaged())
                std::cerr << "warning: " << paths.journal << ": damaged from record " << journal.damagedRecord << " ("
                          << journal.damage << "); exporting the " << journal.records.size()
                          << " actions before it\n";
        }
    } else if (!std::filesystem::exists(input)) {
        std::cerr << "error: " << input << ": no such session folder or garden file\n";
        return nullptr;
    } else if (lowerExtension(input) != ".json") {
        std::cerr << "error: " << input << ": expected a session folder or a garden file (.json)\n";
        return nullptr;
    }
    GardenLoad load = loadGarden(gardenFile);
    if (!load.ok()) {
        std::cerr << "error: " << load.error << "\n";
        return nullptr;
    }
    SessionSettings settings;
    settings.maxLevel = 0;  // no window: the coarsest meshes are not wanted
    auto session = std::make_unique<GardenSession>(std::move(load), settings);
    // A record that cannot be played ends what the session shows (it opens
    // read-only there, docs/session-format.md): the export is of that too.
    const JournalPlayed played = session->restoreRecords(journal.records);
    if (!played.ok())
        std::cerr << "warning: " << input << ": journal " << played.message() << "; exporting the "
                  << played.played << " records before it (hypergarden session " << input << " --cut-at "
                  << played.played + 1 << " makes the session writable again)\n";
    status = 0;
    return session;
}

}  // namespace

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
    std::unique_ptr<GardenSession> session = openForExport(options.input, status);
    if (!session) return status;
    const int index = session->findSculpture(options.sculpture);
    if (index < 0) {
        std::cerr << "error: " << options.input << " has no sculpture '" << options.sculpture << "'; its sculptures:";
        for (const Sculpture& s : session->sculptures()) std::cerr << " '" << s.name << "'";
        std::cerr << "\n";
        return 2;
    }
    const Sculpture& s = session->sculptures()[static_cast<std::size_t>(index)];
    if (s.missing()) {
        std::cerr << "error: sculpture '" << s.name << "' is missing: " << s.error
                  << (s.error.empty() || s.error.back() != '\n' ? "\n" : "");
        return 1;
    }
    fo.resolution = options.resolution;
    if (options.mmPerUnit > 0.0) fo.mmPerUnit = options.mmPerUnit;
    fo.ascii = options.ascii;
    fo.simplifyError = options.simplifyError;
    fo.memoryLimitMiB = options.memoryLimitMiB;
    ExportFileReport report;
    std::string why;
    {
        ProgressBar bar("export " + s.name);
        why = exportSculptureFile(*session, index, options.output, fo, report, [&](double f) { bar.update(f); });
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
