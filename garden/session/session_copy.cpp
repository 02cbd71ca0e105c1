#include "garden/session/session_copy.h"

#include <filesystem>
#include <system_error>

#include "garden/session/session_folder.h"
#include "io/checked_write.h"

namespace hg::garden {

namespace fs = std::filesystem;

namespace {

// The folder as one spelling (absolute, no trailing separator).
fs::path folderPath(const std::string& dir) {
    std::error_code ec;
    fs::path p = fs::absolute(dir, ec).lexically_normal();
    if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();
    return p;
}

bool inside(const fs::path& p, const fs::path& folder) {
    const fs::path rel = p.lexically_relative(folder);
    return !rel.empty() && *rel.begin() != "..";
}

std::string copyFile(const fs::path& from, const fs::path& to) {
    std::string bytes;
    if (std::string why = io::readText(from.string(), bytes); !why.empty()) return why;
    io::CheckedFile out(to.string(), io::WriteSite::SessionFile);
    out.write(bytes);
    return out.finish();
}

std::string copyTree(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::create_directories(to, ec);
    if (ec) return "cannot make " + to.string() + ": " + ec.message();
    for (fs::recursive_directory_iterator it(from, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name == kSessionLockFile || io::isTemporaryName(name)) {
            if (it->is_directory()) it.disable_recursion_pending();
            continue;
        }
        const fs::path target = to / it->path().lexically_relative(from);
        if (it->is_directory()) {
            fs::create_directories(target, ec);
            if (ec) return "cannot make " + target.string() + ": " + ec.message();
        } else if (it->is_regular_file()) {
            if (std::string why = copyFile(it->path(), target); !why.empty()) return why;
        }
    }
    if (ec) return "cannot read " + from.string() + ": " + ec.message();
    return "";
}

}  // namespace

std::string copySession(const SessionRecorder& recorder, const std::string& to) {
    const SaveStatus status = recorder.saveStatus();
    if (!status.saved())
        return "not every action of " + recorder.paths().dir + " is saved (" + status.headline() +
               "): a copy would lack them";
    if (to.empty()) return "name the folder the copy goes into";
    const fs::path from = folderPath(recorder.paths().dir);
    const fs::path target = folderPath(to);
    if (target == from || inside(target, from)) return to + " is inside the session " + recorder.paths().dir;
    const FolderKind kind = folderKind(target.string());
    if (kind != FolderKind::Missing && kind != FolderKind::Empty)
        return to + " is not a new or empty folder: a copy of a session goes into one";
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    if (ec) return "cannot make " + target.parent_path().string() + ": " + ec.message();
    const fs::path temporary = io::temporaryPathFor(target.string());
    fs::remove_all(temporary, ec);
    std::string why = copyTree(from, temporary);
    if (why.empty() && kind == FolderKind::Empty) {
        fs::remove(target, ec);  // an empty folder, replaced by the whole copy
        if (ec) why = "cannot replace the empty folder " + to + ": " + ec.message();
    }
    if (why.empty()) why = io::renameFile(temporary.string(), target.string(), io::WriteSite::SessionFile);
    if (why.empty()) why = io::syncFolder(target.parent_path().string(), io::WriteSite::SessionFile);
    if (!why.empty()) fs::remove_all(temporary, ec);
    return why;
}

}  // namespace hg::garden
