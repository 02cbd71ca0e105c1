// `hypergarden session DIR [--verify] [--json]`: what a session folder holds
// (its sculptures and the edits on each, the journal's actions, the
// snapshot, a damaged tail); --verify rebuilds every grid from the journal
// and compares it with the snapshot's grids.
#include <filesystem>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "garden/app/garden_session.h"
#include "garden/cli/commands.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/session/session_folder.h"
#include "voxel/vdb_io.h"

namespace hg::garden::cli {

namespace {

std::size_t differingVoxels(const voxel::Volume& a, const voxel::Volume& b) {
    const voxel::IndexBox& box = a.frame.indexBox;
    std::size_t n = 0;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) n += a.value(i, j, k) != b.value(i, j, k);
    return n;
}

}  // namespace

int runSessionCommand(const SessionCommandOptions& options) {
    const SessionPaths paths(options.dir);
    if (!std::filesystem::exists(paths.manifest)) {
        std::cerr << "error: " << options.dir << " is not a session folder (no session.json)\n";
        return 2;
    }
    if (std::string why = checkSessionManifest(paths); !why.empty()) {
        std::cerr << "error: " << why << "\n";
        return 2;
    }
    nlohmann::json report;
    report["session"] = options.dir;
    JournalRead journal;
    if (std::filesystem::exists(paths.journal)) {
        journal = readJournal(paths.journal);
        if (!journal.ok()) {
            std::cerr << "error: " << journal.error << "\n";
            return 2;
        }
    }
    std::map<std::string, int> kinds;
    for (const JournalRecord& r : journal.records) ++kinds[journalRecordKind(r)];
    report["journal"] = {{"records", journal.records.size()}, {"actions", kinds}};
    if (journal.damaged())
        report["journal"]["damaged_tail"] = {{"record", journal.damagedRecord}, {"byte_offset", journal.damagedOffset},
                                             {"reason", journal.damage}};
    const SnapshotInfo snap = readSnapshotInfo(paths);
    if (!snap.error.empty()) report["snapshot"] = {{"error", snap.error}};
    else if (snap.present) report["snapshot"] = {{"records", snap.records}, {"sculptures", snap.sculptures}};

    // The sculptures and their edits, from the journal played headless.
    GardenLoad load = loadGarden(paths.garden);
    if (!load.ok()) {
        std::cerr << "error: " << load.error << "\n";
        return 2;
    }
    SessionSettings settings;
    settings.maxLevel = 0;
    GardenSession session(std::move(load), settings);
    const std::size_t upTo = options.verify && snap.present ? std::min(snap.records, journal.records.size()) : journal.records.size();
    const std::vector<JournalRecord> played(journal.records.begin(), journal.records.begin() + static_cast<std::ptrdiff_t>(upTo));
    const std::string playError = session.restore(played);
    if (!playError.empty()) report["play_error"] = playError;
    nlohmann::json sculptures = nlohmann::json::array();
    for (std::size_t i = 0; i < session.sculptures().size(); ++i) {
        const Sculpture& s = session.sculptures()[i];
        nlohmann::json j = {{"name", s.name}, {"edits", session.editCount(static_cast<int>(i))}};
        if (s.missing()) j["missing"] = s.error;
        if (s.edits) {
            nlohmann::json list = nlohmann::json::array();
            for (const Edit& e : s.edits->list().edits()) list.push_back(describe(e));
            j["edit_list"] = std::move(list);
        }
        sculptures.push_back(std::move(j));
    }
    report["sculptures"] = std::move(sculptures);

    int status = journal.damaged() || !playError.empty() ? 1 : 0;
    if (options.verify) {
        nlohmann::json verify = nlohmann::json::array();
        if (!snap.present) report["verify"] = "no snapshot to compare with";
        for (const std::string& name : snap.sculptures) {
            const int i = session.findSculpture(name);
            voxel::Volume saved;
            const std::string path = (std::filesystem::path(paths.snapshots) / (name + ".vdb")).string();
            std::string why = voxel::readVolume(path, saved);
            nlohmann::json v = {{"sculpture", name}};
            if (i < 0) why = "no such sculpture in the garden";
            if (why.empty()) {
                const std::size_t d = differingVoxels(*session.sculptures()[static_cast<std::size_t>(i)].volume, saved);
                v["differing_voxels"] = d;
                if (d) status = 1;
            } else {
                v["error"] = why;
                status = 1;
            }
            verify.push_back(std::move(v));
        }
        if (snap.present) report["verify"] = std::move(verify);
    }
    if (options.json) {
        std::cout << report.dump(2) << "\n";
        return status;
    }
    std::cout << "session " << options.dir << "\n";
    std::cout << "journal: " << journal.records.size() << " actions";
    for (const auto& [k, n] : kinds) std::cout << ", " << n << " " << k;
    std::cout << "\n";
    if (journal.damaged())
        std::cout << "damaged tail: record " << journal.damagedRecord << " at byte " << journal.damagedOffset << ": "
                  << journal.damage << "\n";
    if (snap.present) std::cout << "snapshot: " << snap.records << " actions, " << snap.sculptures.size() << " grids\n";
    for (const auto& s : report["sculptures"]) {
        std::cout << "sculpture " << s["name"].get<std::string>() << ": " << s["edits"].get<std::size_t>() << " edits\n";
        if (s.contains("edit_list"))
            for (const auto& e : s["edit_list"]) std::cout << "  " << e.get<std::string>() << "\n";
    }
    if (!playError.empty()) std::cout << "not played: " << playError << "\n";
    if (options.verify && report["verify"].is_array())
        for (const auto& v : report["verify"])
            std::cout << "verify " << v["sculpture"].get<std::string>() << ": "
                      << (v.contains("error") ? v["error"].get<std::string>()
                                              : std::to_string(v["differing_voxels"].get<std::size_t>()) + " voxels differ")
                      << "\n";
    return status;
}

}  // namespace hg::garden::cli
