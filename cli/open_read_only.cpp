#include "cli/open_read_only.h"

#include <filesystem>
#include <iostream>
#include <vector>

#include "frep/language/near_miss.h"
#include "garden/session/journal.h"
#include "garden/session/session_folder.h"
#include "io/folder_lock.h"

namespace hg::garden::cli {

std::string lowerExtension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return e;
}

std::unique_ptr<GardenSession> openReadOnly(const std::string& input, const SessionSettings& settings,
                                            const std::string& doing, int& status) {
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
        // Only reading: a session open elsewhere is read as its
        // journal stands now, and the user is told so.
        if (const auto holder = io::lockHolder(input, kSessionLockFile))
            std::cerr << "note: " << input << " is open in " << holder->describe()
                      << "; " << doing << " what its journal holds now (the session is not changed)\n";
        if (std::filesystem::exists(paths.journal)) {
            journal = readJournal(paths.journal);
            if (!journal.ok()) {
                std::cerr << "error: " << journal.error << "\n";
                return nullptr;
            }
            if (journal.damaged())
                std::cerr << "warning: " << paths.journal << ": damaged from record " << journal.damagedRecord << " ("
                          << journal.damage << "); " << doing << " the " << journal.records.size()
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
    auto session = std::make_unique<GardenSession>(std::move(load), settings);
    // A session's added meshes and volumes are read from its imports/.
    if (std::filesystem::is_directory(input)) session->setSessionFolder(input);
    // A record that cannot be played ends what the session shows (it opens
    // read-only there, docs/session-format.md): what is written shows that too.
    const JournalPlayed played = session->restoreRecords(journal.records);
    if (!played.ok())
        std::cerr << "warning: " << input << ": journal " << played.message() << "; " << doing << " the "
                  << played.played << " records before it (hypergarden session " << input << " --cut-at "
                  << played.played + 1 << " makes the session writable again)\n";
    status = 0;
    return session;
}

int findUsableSculpture(const GardenSession& session, const std::string& input, const std::string& name, int& status) {
    const int index = session.findSculpture(name);
    if (index >= 0) {
        const Sculpture& s = session.sculptures()[static_cast<std::size_t>(index)];
        if (!s.missing()) return index;
        std::cerr << "error: sculpture '" << s.name << "' is missing: " << s.error
                  << (s.error.empty() || s.error.back() != '\n' ? "\n" : "");
        status = 1;
        return -1;
    }
    status = 2;
    std::vector<std::string> names;
    for (const Sculpture& s : session.sculptures())
        if (!s.removed) names.push_back(s.name);
    const std::string near = frep::nearMiss(name, names);
    std::cerr << "error: " << input << " has no sculpture '" << name << "'"
              << (near.empty() ? "" : " (did you mean '" + near + "'?)") << "; its sculptures:";
    for (const std::string& n : names) std::cerr << " '" << n << "'";
    std::cerr << "\n";
    return -1;
}

}  // namespace hg::garden::cli
