#include "garden/session/session_folder.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "garden/app/garden_session.h"
#include "garden/scene/json_reader.h"
#include "io/checked_write.h"
#include "voxel/vdb_io.h"

namespace hg::garden {

namespace fs = std::filesystem;

namespace {

// What a session's making writes before session.json: a folder holding
// only these (and temporaries) is a session cut short while being made.
bool isMakingLeftover(const std::string& name) {
    return name == "garden.json" || name == "sources" || name == kSessionLockFile || io::isTemporaryName(name);
}

std::string gridFileName(const std::string& sculpture, std::size_t records) {
    return sculpture + "." + std::to_string(records) + ".vdb";
}

}  // namespace

SessionPaths::SessionPaths(const std::string& d)
    : dir(d),
      manifest((fs::path(d) / "session.json").string()),
      garden((fs::path(d) / "garden.json").string()),
      journal((fs::path(d) / "journal.hgj").string()),
      snapshots((fs::path(d) / "snapshots").string()),
      snapshotManifest((fs::path(d) / "snapshots" / "snapshot.json").string()) {}

FolderKind folderKind(const std::string& dir) {
    std::error_code ec;
    const fs::file_status st = fs::status(dir, ec);
    if (!fs::exists(st)) return FolderKind::Missing;
    if (!fs::is_directory(st)) return FolderKind::Other;
    if (fs::exists(SessionPaths(dir).manifest)) return FolderKind::Session;
    bool any = false;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
        any = true;
        if (!isMakingLeftover(e.path().filename().string())) return FolderKind::Other;
    }
    if (ec) return FolderKind::Other;
    return any ? FolderKind::Unfinished : FolderKind::Empty;
}

std::string checkSessionManifest(const SessionPaths& paths) {
    std::string text;
    if (std::string why = readText(paths.manifest, text); !why.empty()) return why;
    try {
        const nlohmann::json j = parseStrictJson(text);
        ObjectReader r(j, "$", {"format", "version"});
        if (readString(r.required("format"), "$.format") != "hypergarden-session")
            return paths.manifest + ": not a Hypergarden session";
        const int version = readInt(r.required("version"), "$.version", 0, 1000000);
        if (version != kSessionVersion)
            return paths.manifest + ": session format version " + std::to_string(version) +
                   " is not one this program reads (it reads " + std::to_string(kSessionVersion) + ")";
        r.finish();
    } catch (const JsonError& e) {
        return paths.manifest + ": " + e.what();
    }
    return "";
}

std::string makeSession(const std::string& dir, const std::string& gardenFile) {
    const SessionPaths paths(dir);
    std::error_code ec;
    fs::create_directories(fs::path(dir) / "sources", ec);
    if (ec) return "cannot create " + (fs::path(dir) / "sources").string() + ": " + ec.message();
    std::string text;
    if (std::string why = readText(gardenFile, text); !why.empty()) return "cannot read the garden: " + why;
    nlohmann::json garden;
    try {
        garden = parseStrictJson(text);
    } catch (const JsonError& e) {
        return gardenFile + ": " + e.what();
    }
    // The sculptures' files come along, so the session keeps its sources
    // as they were when it was made.
    const fs::path gardenFolder = fs::path(gardenFile).parent_path();
    std::set<std::string> taken;
    if (garden.is_object() && garden.contains("sculptures") && garden["sculptures"].is_array()) {
        for (auto& entry : garden["sculptures"]) {
            // A scanned volume's file is in its "volume" object.
            const bool scan = entry.is_object() && entry.contains("volume") && entry["volume"].is_object();
            nlohmann::json& s = scan ? entry["volume"] : entry;
            if (!s.is_object() || !s.contains("file") || !s["file"].is_string()) continue;
            const fs::path source = gardenFolder / s["file"].get<std::string>();
            std::string name = source.filename().string();
            for (int n = 2; taken.count(name); ++n) name = source.stem().string() + "_" + std::to_string(n) + source.extension().string();
            taken.insert(name);
            if (fs::exists(source)) {
                std::string bytes;
                if (std::string why = readText(source.string(), bytes); !why.empty())
                    return "cannot copy " + source.string() + " into the session: " + why;
                const std::string copy = (fs::path(dir) / "sources" / name).string();
                if (std::string why = io::writeFileAtomically(copy, bytes, io::WriteSite::SessionFile); !why.empty())
                    return why;
            }
            s["file"] = "sources/" + name;
        }
    }
    if (std::string why = io::writeFileAtomically(paths.garden, garden.dump(2) + "\n", io::WriteSite::SessionFile);
        !why.empty())
        return why;
    // Written last: a folder without it is not (yet) a session.
    const nlohmann::json manifest = {{"format", "hypergarden-session"}, {"version", kSessionVersion}};
    return io::writeFileAtomically(paths.manifest, manifest.dump(2) + "\n", io::WriteSite::SessionFile);
}

SnapshotInfo readSnapshotInfo(const SessionPaths& paths) {
    SnapshotInfo info;
    if (!fs::exists(paths.snapshotManifest)) return info;
    std::string text;
    if (std::string why = readText(paths.snapshotManifest, text); !why.empty()) {
        info.error = why;
        return info;
    }
    try {
        const nlohmann::json j = parseStrictJson(text);
        ObjectReader r(j, "$", {"records", "sculptures", "files"});
        info.records = static_cast<std::size_t>(readInt(r.required("records"), "$.records", 0, 2000000000));
        const nlohmann::json& s = r.required("sculptures");
        if (!s.is_array()) throw JsonError("$.sculptures", "expected an array of names");
        for (std::size_t i = 0; i < s.size(); ++i) info.sculptures.push_back(readString(s[i], indexPath("$.sculptures", i)));
        // Snapshots before the file names were recorded hold NAME.vdb.
        if (const nlohmann::json* f = r.optional("files")) {
            if (!f->is_array() || f->size() != s.size())
                throw JsonError("$.files", "expected one file name for each sculpture");
            for (std::size_t i = 0; i < f->size(); ++i) {
                std::string name = readString((*f)[i], indexPath("$.files", i));
                if (name.find('/') != std::string::npos || name == "." || name == "..")
                    throw JsonError(indexPath("$.files", i), "expected a file name in snapshots/");
                info.files.push_back(std::move(name));
            }
        } else {
            for (const std::string& name : info.sculptures) info.files.push_back(name + ".vdb");
        }
        r.finish();
        info.present = true;
    } catch (const JsonError& e) {
        info.error = paths.snapshotManifest + ": " + e.what();
    }
    return info;
}

std::vector<std::string> removeLeftovers(const SessionPaths& paths) {
    std::vector<std::string> removed;
    const SnapshotInfo snap = readSnapshotInfo(paths);
    const std::set<std::string> named(snap.files.begin(), snap.files.end());
    const auto sweep = [&](const fs::path& folder, bool orphanGrids) {
        std::error_code ec;
        std::vector<fs::path> doomed;
        for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
            const std::string name = e.path().filename().string();
            // A grid no snapshot names was written by a snapshot that was
            // never published (an unreadable snapshot.json keeps them all).
            const bool orphan = orphanGrids && snap.error.empty() && e.path().extension() == ".vdb" && !named.count(name);
            if (e.is_regular_file(ec) && (io::isTemporaryName(name) || orphan)) doomed.push_back(e.path());
        }
        for (const fs::path& p : doomed)
            if (fs::remove(p, ec)) removed.push_back(p.string());
    };
    sweep(paths.dir, false);
    sweep(fs::path(paths.dir) / "sources", false);
    sweep(fs::path(paths.dir) / "imports", false);
    sweep(paths.snapshots, true);
    return removed;
}

// ---------------------------------------------------------------- recorder

SessionRecorder::SessionRecorder(std::string dir, std::unique_ptr<io::FolderLock> lock)
    : paths_(std::move(dir)), lock_(std::move(lock)) {
    status_.folder = paths_.dir;
}

SessionRecorder::~SessionRecorder() { close(); }

std::string SessionRecorder::readJournal() {
    if (!fs::exists(paths_.journal)) return "";
    read_ = garden::readJournal(paths_.journal);
    if (!read_.ok()) return read_.error;
    if (read_.damaged()) {
        // Nothing saved is lost: the whole file is kept beside the session
        // before its tail is cut.
        const std::string copy = paths_.journal + ".damaged";
        std::string bytes, why = readText(paths_.journal, bytes);
        if (why.empty()) why = io::writeFileAtomically(copy, bytes, io::WriteSite::Journal);
        // Cutting the tail without a copy would lose what the user may
        // still want: the session is not opened.
        if (!why.empty()) return "the journal's tail is damaged and it cannot be kept before cutting it: " + why;
        notes_.push_back(paths_.journal + ": record " + std::to_string(read_.damagedRecord) + " at byte " +
                         std::to_string(read_.damagedOffset) + ": " + read_.damage + "; the " +
                         std::to_string(read_.records.size()) + " records before it are recovered" +
                         " (the damaged journal is kept as " + copy + ")");
    }
    return "";
}

void SessionRecorder::attach(GardenSession& session) {
    session_ = &session;
    // Added meshes and volumes are copied into, and read from, its imports/.
    session.setSessionFolder(paths_.dir);
    restored_ = session.restoreRecords(read_.records);
    records_ = restored_.played;
    lastSnapshot_ = readSnapshotInfo(paths_).records;
    session.setJournal(this);
    if (!restored_.ok()) {
        const std::size_t after = read_.records.size() - restored_.played - 1;
        const auto records = [](std::size_t n) { return std::to_string(n) + (n == 1 ? " record" : " records"); };
        setStatus(SaveStatus::State::ReadOnly,
                  paths_.journal + ": " + restored_.message() + "; the session shows the " + records(restored_.played) +
                      " before it" +
                      (after ? ", and the " + records(after) + " after it " + (after == 1 ? "is" : "are") +
                                   " kept on disk, not played"
                             : std::string()),
                  "to go on from the records before it: hypergarden session " + paths_.dir + " --cut-at " +
                      std::to_string(restored_.played + 1) + " (the whole journal is kept beside it)");
        return;
    }
    // A journal cut short by a crash (or damaged) is cut back to its last
    // whole record before anything is appended.
    const std::uint64_t keep = fs::exists(paths_.journal) ? read_.goodBytes : ~std::uint64_t{0};
    if (std::string why = writer_.open(paths_.journal, keep); !why.empty()) {
        setStatus(SaveStatus::State::NotSaved, why);
        return;
    }
    writerOpen_ = true;
}

void SessionRecorder::setStatus(SaveStatus::State state, const std::string& reason, const std::string& remedy) {
    const bool changed = state != status_.state || reason != status_.reason;
    status_.state = state;
    status_.reason = reason;
    status_.remedy = remedy;
    status_.unsaved = backlog_.size();
    if (!changed) return;
    ++status_.revision;
    if (listener_) listener_(status_);
}

void SessionRecorder::append(const Action& record) {
    backlog_.push_back(record);
    if (status_.state == SaveStatus::State::ReadOnly) {
        status_.unsaved = backlog_.size();
        return;
    }
    writeBacklog();
}

bool SessionRecorder::retrySave() {
    if (status_.state == SaveStatus::State::ReadOnly) return false;
    return writeBacklog();
}

bool SessionRecorder::writeBacklog() {
    if (!writerOpen_) {
        if (std::string why = writer_.open(paths_.journal, read_.goodBytes); !why.empty()) {
            setStatus(SaveStatus::State::NotSaved, why);
            return false;
        }
        writerOpen_ = true;
    }
    std::size_t written = 0;
    std::string why;
    for (; written < backlog_.size(); ++written) {
        why = writer_.append(backlog_[written]);
        if (!why.empty()) break;
        ++records_;
    }
    backlog_.erase(backlog_.begin(), backlog_.begin() + static_cast<std::ptrdiff_t>(written));
    if (!why.empty()) {
        setStatus(SaveStatus::State::NotSaved, why);
        return false;
    }
    setStatus(SaveStatus::State::Saved, "");
    if (records_ - lastSnapshot_ >= kSnapshotEvery) snapshot();
    return true;
}

std::string SessionRecorder::snapshot() {
    if (!session_) return "no session is attached";
    // The grids hold every action in memory: a snapshot of them is true
    // only when the journal holds all of those.
    if (!status_.saved()) return "not every action is saved";
    session_->settleEdits();  // an edit spread over frames, whole in the grids
    std::error_code ec;
    fs::create_directories(paths_.snapshots, ec);
    if (ec) return snapshotProblem_ = "cannot create " + paths_.snapshots + ": " + ec.message();
    const SnapshotInfo previous = readSnapshotInfo(paths_);
    // Every grid and the manifest are written as temporaries and synced;
    // they are renamed only when all of them are whole, the manifest last,
    // so a snapshot is published whole or not at all.
    struct Pending {
        std::string tmp, path;
        io::WriteSite site;
    };
    std::vector<Pending> pending;
    const auto abandon = [&](const std::string& why) {
        for (const Pending& p : pending) std::remove(p.tmp.c_str());
        snapshotProblem_ = "the snapshot was not written: " + why;
        return snapshotProblem_;
    };
    nlohmann::json names = nlohmann::json::array(), files = nlohmann::json::array();
    for (const Sculpture& s : session_->sculptures()) {
        // The morph result's grid follows its blend, which runs over frames:
        // its edits are in the journal, its grid is not snapshotted.
        if (!s.edits || !s.onShow() || s.morphResult()) continue;
        const std::string file = gridFileName(s.name, records_);
        const std::string path = (fs::path(paths_.snapshots) / file).string();
        std::string bytes;
        if (std::string why = voxel::encodeVolume(*s.volume, bytes); !why.empty()) return abandon(why);
        pending.push_back({io::temporaryPathFor(path), path, io::WriteSite::SnapshotGrid});
        io::CheckedFile out(pending.back().tmp, io::WriteSite::SnapshotGrid);
        out.write(bytes);
        if (std::string why = out.finish(); !why.empty()) return abandon(why);
        names.push_back(s.name);
        files.push_back(file);
    }
    const nlohmann::json manifest = {{"records", records_}, {"sculptures", names}, {"files", files}};
    pending.push_back({io::temporaryPathFor(paths_.snapshotManifest), paths_.snapshotManifest,
                       io::WriteSite::SnapshotManifest});
    {
        io::CheckedFile out(pending.back().tmp, io::WriteSite::SnapshotManifest);
        out.write(manifest.dump(2) + "\n");
        if (std::string why = out.finish(); !why.empty()) return abandon(why);
    }
    for (std::size_t i = 0; i < pending.size(); ++i)
        if (std::string why = io::renameFile(pending[i].tmp, pending[i].path, pending[i].site); !why.empty()) {
            // Grids renamed so far are named by no manifest: removed too.
            for (std::size_t k = 0; k < i; ++k) std::remove(pending[k].path.c_str());
            return abandon(why);
        }
    if (std::string why = io::syncFolder(paths_.snapshots, io::WriteSite::SnapshotManifest); !why.empty())
        return snapshotProblem_ = "the snapshot may not survive a power cut: " + why;
    // The previous snapshot's grids are no longer named.
    std::set<std::string> kept;
    for (const auto& f : files) kept.insert(f.get<std::string>());
    for (const std::string& f : previous.files)
        if (!kept.count(f)) fs::remove(fs::path(paths_.snapshots) / f, ec);
    lastSnapshot_ = records_;
    snapshotProblem_.clear();
    return "";
}

SaveStatus SessionRecorder::close() {
    if (closed_ || !session_) return status_;
    closed_ = true;
    if (status_.state == SaveStatus::State::NotSaved) writeBacklog();
    if (status_.saved() && records_ != lastSnapshot_) snapshot();
    session_->setJournal(nullptr);
    return status_;
}

}  // namespace hg::garden
