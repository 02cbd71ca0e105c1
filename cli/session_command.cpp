// `hypergarden session DIR [--verify] [--json] [--cut-at N]`: what a
// session folder holds (its sculptures and the edits on each, the
// journal's actions, the snapshot, a damaged tail, who has it open);
// --verify rebuilds every grid from the journal and compares it with the
// snapshot's grids; --cut-at cuts the journal before a record that cannot
// be played, keeping the whole journal beside it. Reporting reads a
// session another process holds; --verify and --cut-at take its lock.
#include <filesystem>
#include <iostream>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <memory>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "garden/app/garden_session.h"
#include "cli/commands.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/session/session_folder.h"
#include "io/checked_write.h"
#include "io/folder_lock.h"
#include "voxel/vdb_io.h"

#include <fcntl.h>
#include <unistd.h>

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

// The journal cut at record `n` (from 1): records n and after removed, the
// whole journal kept first as journal.hgj.before-cut-at-N, and a snapshot
// that covers cut records removed (its grids hold them).
int cutJournal(const SessionPaths& paths, std::size_t n) {
    const JournalRead journal = readJournal(paths.journal);
    if (!journal.ok()) {
        std::cerr << "error: " << journal.error << "\n";
        return 2;
    }
    if (n > journal.records.size()) {
        std::cerr << "error: --cut-at " << n << ": the journal has " << journal.records.size() << " readable records\n";
        return 2;
    }
    std::string bytes;
    if (std::string why = readText(paths.journal, bytes); !why.empty()) {
        std::cerr << "error: cannot read " << why << "\n";
        return 1;
    }
    std::string copy = paths.journal + ".before-cut-at-" + std::to_string(n);
    for (int k = 2; std::filesystem::exists(copy); ++k)
        copy = paths.journal + ".before-cut-at-" + std::to_string(n) + "-" + std::to_string(k);
    if (std::string why = io::writeFileAtomically(copy, bytes, io::WriteSite::Journal); !why.empty()) {
        std::cerr << "error: the journal was not cut: " << why << "\n";
        return 1;
    }
    const int fd = ::open(paths.journal.c_str(), O_WRONLY | O_CLOEXEC);
    std::string why = fd < 0 ? "cannot open " + paths.journal + ": " + std::strerror(errno) : "";
    if (why.empty()) why = io::truncateFile(fd, journal.recordOffsets[n - 1], io::WriteSite::Journal, paths.journal);
    if (why.empty()) why = io::syncFile(fd, io::WriteSite::Journal, paths.journal);
    if (fd >= 0) ::close(fd);
    if (!why.empty()) {
        std::cerr << "error: the journal was not cut: " << why << " (the whole journal is kept as " << copy << ")\n";
        return 1;
    }
    std::cout << "cut the journal of " << paths.dir << " at record " << n << ": records 1 to " << n - 1
              << " kept, " << journal.records.size() - n + 1 << " removed; the whole journal is kept as " << copy << "\n";
    const SnapshotInfo snap = readSnapshotInfo(paths);
    if (snap.present && snap.records > n - 1) {
        std::error_code ec;
        std::filesystem::remove(paths.snapshotManifest, ec);
        for (const std::string& f : snap.files) std::filesystem::remove(std::filesystem::path(paths.snapshots) / f, ec);
        std::cout << "removed the snapshot of " << snap.records << " records (it held records that were cut)\n";
    }
    return 0;
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
    // Verifying and cutting want the session still: they take its lock.
    std::unique_ptr<io::FolderLock> lock;
    std::optional<io::LockHolder> holder;
    if (options.verify || options.cutAt) {
        std::string why;
        lock = io::FolderLock::acquire(options.dir, kSessionLockFile, "hypergarden session", why, holder);
        if (!lock) {
            std::cerr << "error: " << why << "\n";
            return 2;
        }
        if (options.cutAt) return cutJournal(paths, options.cutAt);
    } else if ((holder = io::lockHolder(options.dir, kSessionLockFile))) {
        std::cerr << "note: " << options.dir << " is open in " << holder->describe()
                  << "; this reads what its journal holds now and changes nothing\n";
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
    for (const Action& r : journal.records) ++kinds[actionKind(r)];
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
    // The snapshot's grids, read first: a session played at another
    // resolution (`replay --res`) is rebuilt at the resolution its grids have.
    std::vector<voxel::Volume> saved(snap.sculptures.size());
    std::vector<std::string> unreadable(snap.sculptures.size());
    if (options.verify) {
        std::set<int> resolutions;
        for (std::size_t k = 0; k < snap.sculptures.size(); ++k) {
            const std::string path = (std::filesystem::path(paths.snapshots) / snap.files[k]).string();
            unreadable[k] = voxel::readVolume(path, saved[k]);
            if (unreadable[k].empty()) resolutions.insert(saved[k].frame.resolution);
        }
        if (resolutions.size() == 1) settings.sculptureResolution = *resolutions.begin();
    }
    GardenSession session(std::move(load), settings);
    session.setSessionFolder(paths.dir);  // added meshes and volumes are read from its imports/
    const std::size_t upTo = options.verify && snap.present ? std::min(snap.records, journal.records.size()) : journal.records.size();
    const std::vector<Action> played(journal.records.begin(), journal.records.begin() + static_cast<std::ptrdiff_t>(upTo));
    const JournalPlayed result = session.restoreRecords(played);
    std::string playError = result.message();
    if (!result.ok()) {
        const std::size_t after = journal.records.size() - result.played - 1;
        playError += "; " + std::to_string(after) + " record" + (after == 1 ? "" : "s") +
                     " after it; to go on from the records before it: hypergarden session " + options.dir +
                     " --cut-at " + std::to_string(result.played + 1);
    }
    if (!playError.empty()) report["play_error"] = playError;
    nlohmann::json sculptures = nlohmann::json::array();
    for (std::size_t i = 0; i < session.sculptures().size(); ++i) {
        const Sculpture& s = session.sculptures()[i];
        if (s.removed) continue;
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
        for (std::size_t k = 0; k < snap.sculptures.size(); ++k) {
            const std::string& name = snap.sculptures[k];
            const int i = session.findSculpture(name);
            std::string why = unreadable[k];
            nlohmann::json v = {{"sculpture", name}};
            if (i < 0) why = "no such sculpture in the garden";
            const voxel::Volume* rebuilt = i < 0 ? nullptr : session.sculptures()[static_cast<std::size_t>(i)].volume.get();
            const auto sameBox = [](const voxel::IndexBox& x, const voxel::IndexBox& y) {
                return std::equal(x.lo, x.lo + 3, y.lo) && std::equal(x.hi, x.hi + 3, y.hi);
            };
            if (why.empty() && (!rebuilt || !sameBox(rebuilt->frame.indexBox, saved[k].frame.indexBox)))
                why = "the snapshot's grid (resolution " + std::to_string(saved[k].frame.resolution) +
                      ") does not cover the same voxels as the rebuilt one";
            if (why.empty()) {
                const std::size_t d = differingVoxels(*rebuilt, saved[k]);
                v["differing_voxels"] = d;
                if (d) status = 1;
            } else {
                v["error"] = why;
                status = 1;
            }
            verify.push_back(std::move(v));
        }
        if (snap.present) report["verify"] = std::move(verify);
        // What was checked, in words, also when there was nothing to compare.
        std::string summary;
        if (!playError.empty())
            summary = "the journal does not play to its end (" + playError + ")";
        else if (!snap.error.empty())
            summary = "the snapshot cannot be read (" + snap.error + "); the journal's " +
                      std::to_string(journal.records.size()) + " records play";
        else if (!snap.present)
            summary = "no snapshot yet (one is written every " + std::to_string(kSnapshotEvery) +
                      " actions and when the session closes): the journal's " + std::to_string(journal.records.size()) +
                      " records play on the session's garden; no grid to compare";
        else if (snap.records > journal.records.size())
            summary = "the snapshot covers " + std::to_string(snap.records) + " records but the journal holds only " +
                      std::to_string(journal.records.size());
        else
            summary = "the journal's first " + std::to_string(snap.records) + " of " +
                      std::to_string(journal.records.size()) + " records played and " +
                      std::to_string(snap.sculptures.size()) + " snapshot grid" + (snap.sculptures.size() == 1 ? "" : "s") +
                      " compared voxel by voxel" + (status ? ": they differ (see above)" : ": all equal");
        if (!snap.error.empty() || snap.records > journal.records.size()) status = 1;
        report["verify_summary"] = summary;
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
    if (options.verify) std::cout << "verify: " << report["verify_summary"].get<std::string>() << "\n";
    if (options.verify && report["verify"].is_array())
        for (const auto& v : report["verify"])
            std::cout << "verify " << v["sculpture"].get<std::string>() << ": "
                      << (v.contains("error") ? v["error"].get<std::string>()
                                              : std::to_string(v["differing_voxels"].get<std::size_t>()) + " voxels differ")
                      << "\n";
    return status;
}

}  // namespace hg::garden::cli
