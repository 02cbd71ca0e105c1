#include "garden/session/session_folder.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "garden/app/garden_session.h"
#include "garden/scene/json_reader.h"
#include "garden/sculpt/sculpture_edits.h"
#include "voxel/vdb_io.h"

namespace hg::garden {

namespace fs = std::filesystem;

namespace {

std::string writeTextAtomically(const std::string& path, const std::string& text) {
    return voxel::writeAtomically(path, [&](const std::string& tmp) -> std::string {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.flush();
        if (!out) return "cannot write " + path + ": " + std::strerror(errno);
        return "";
    });
}

std::string readText(const std::string& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return path + ": " + std::strerror(errno);
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
    return "";
}

}  // namespace

SessionPaths::SessionPaths(const std::string& d)
    : dir(d),
      manifest((fs::path(d) / "session.json").string()),
      garden((fs::path(d) / "garden.json").string()),
      journal((fs::path(d) / "journal.hgj").string()),
      snapshots((fs::path(d) / "snapshots").string()),
      snapshotManifest((fs::path(d) / "snapshots" / "snapshot.json").string()) {}

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

std::string ensureSession(const std::string& dir, const std::string& gardenFile, bool& created) {
    created = false;
    const SessionPaths paths(dir);
    if (fs::exists(paths.manifest)) return checkSessionManifest(paths);
    std::error_code ec;
    fs::create_directories(fs::path(dir) / "sources", ec);
    if (ec) return "cannot create the session folder " + dir + ": " + ec.message();
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
        for (auto& s : garden["sculptures"]) {
            if (!s.is_object() || !s.contains("file") || !s["file"].is_string()) continue;
            const fs::path source = gardenFolder / s["file"].get<std::string>();
            std::string name = source.filename().string();
            for (int n = 2; taken.count(name); ++n) name = source.stem().string() + "_" + std::to_string(n) + source.extension().string();
            taken.insert(name);
            if (fs::exists(source)) {
                fs::copy_file(source, fs::path(dir) / "sources" / name, fs::copy_options::overwrite_existing, ec);
                if (ec) return "cannot copy " + source.string() + " into the session: " + ec.message();
            }
            s["file"] = "sources/" + name;
        }
    }
    if (std::string why = writeTextAtomically(paths.garden, garden.dump(2) + "\n"); !why.empty()) return why;
    const nlohmann::json manifest = {{"format", "hypergarden-session"}, {"version", kSessionVersion}};
    if (std::string why = writeTextAtomically(paths.manifest, manifest.dump(2) + "\n"); !why.empty()) return why;
    created = true;
    return "";
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
        ObjectReader r(j, "$", {"records", "sculptures"});
        info.records = static_cast<std::size_t>(readInt(r.required("records"), "$.records", 0, 2000000000));
        const nlohmann::json& s = r.required("sculptures");
        if (!s.is_array()) throw JsonError("$.sculptures", "expected an array of names");
        for (std::size_t i = 0; i < s.size(); ++i) info.sculptures.push_back(readString(s[i], indexPath("$.sculptures", i)));
        r.finish();
        info.present = true;
    } catch (const JsonError& e) {
        info.error = paths.snapshotManifest + ": " + e.what();
    }
    return info;
}

SessionRecorder::SessionRecorder(std::string dir) : paths_(std::move(dir)) {}

SessionRecorder::~SessionRecorder() {
    if (session_) {
        session_->setJournal(nullptr);
        if (records_ != lastSnapshot_) snapshot();
    }
}

std::string SessionRecorder::readJournal() {
    if (!fs::exists(paths_.journal)) return "";
    read_ = garden::readJournal(paths_.journal);
    if (!read_.ok()) return read_.error;
    if (read_.damaged()) {
        // Nothing saved is lost: the whole file is kept beside the session
        // before its tail is cut.
        const std::string copy = paths_.journal + ".damaged";
        std::error_code ec;
        fs::copy_file(paths_.journal, copy, fs::copy_options::overwrite_existing, ec);
        notes_.push_back(paths_.journal + ": record " + std::to_string(read_.damagedRecord) + " at byte " +
                         std::to_string(read_.damagedOffset) + ": " + read_.damage + "; the " +
                         std::to_string(read_.records.size()) + " records before it are recovered" +
                         (ec ? std::string(" (the damaged journal could not be copied: ") + ec.message() + ")"
                             : " (the damaged journal is kept as " + copy + ")"));
    }
    return "";
}

std::string SessionRecorder::attach(GardenSession& session) {
    std::string error = session.restore(read_.records);
    if (!error.empty()) error = paths_.journal + ": " + error;
    if (std::string why = writer_.open(paths_.journal, read_.damaged() ? read_.goodBytes : ~std::uint64_t{0}); !why.empty())
        return why;
    session_ = &session;
    records_ = read_.records.size();
    lastSnapshot_ = readSnapshotInfo(paths_).records;
    session.setJournal([this](const JournalRecord& r) { onAction(r); });
    return error;
}

void SessionRecorder::onAction(const JournalRecord& r) {
    const std::string why = writer_.append(r);
    if (!why.empty()) {
        notes_.push_back(why);
        return;
    }
    ++records_;
    if (records_ - lastSnapshot_ >= kSnapshotEvery) snapshot();
}

std::string SessionRecorder::snapshot() {
    if (!session_) return "no session is attached";
    std::error_code ec;
    fs::create_directories(paths_.snapshots, ec);
    if (ec) return "cannot create " + paths_.snapshots + ": " + ec.message();
    nlohmann::json names = nlohmann::json::array();
    for (const Sculpture& s : session_->sculptures()) {
        // The morph result's grid follows its blend, which runs over frames:
        // its edits are in the journal, its grid is not snapshotted.
        if (!s.edits || s.missing() || s.morphResult()) continue;
        const std::string path = (fs::path(paths_.snapshots) / (s.name + ".vdb")).string();
        if (std::string why = voxel::writeVolume(*s.volume, path); !why.empty()) return why;
        names.push_back(s.name);
    }
    // Written last: a snapshot counts only once every grid it names is whole.
    const nlohmann::json manifest = {{"records", records_}, {"sculptures", names}};
    if (std::string why = writeTextAtomically(paths_.snapshotManifest, manifest.dump(2) + "\n"); !why.empty()) return why;
    lastSnapshot_ = records_;
    return "";
}

}  // namespace hg::garden
