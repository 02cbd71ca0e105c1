// Writing files so that every result is checked and a file is visible only
// when whole (docs/session-format.md, "What is promised"): each write(2) is
// repeated until all its bytes are down (a short write is not success),
// the file is fsync'ed before it is renamed into place, and its folder is
// synced after the rename. Every step passes through the fault seam
// (io/write_faults.h). Errors are messages that name the file and the
// reason ("No space left on device"), ready to show to the user.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "io/write_faults.h"

namespace hg::io {

// "" or why not: the steps on an open descriptor.
std::string writeAll(int fd, const void* data, std::size_t size, WriteSite site, const std::string& path);
std::string syncFile(int fd, WriteSite site, const std::string& path);
std::string truncateFile(int fd, std::uint64_t size, WriteSite site, const std::string& path);
// Makes a rename (or a new file) in `folder` durable.
std::string syncFolder(const std::string& folder, WriteSite site);
std::string renameFile(const std::string& from, const std::string& to, WriteSite site);

// The temporary beside `path` that a write fills before it is renamed:
// PATH.partial-PID (a folder's leftovers name their dead writers).
std::string temporaryPathFor(const std::string& path);
bool isTemporaryName(const std::string& fileName);

// A file filled in pieces, buffered, every flush checked; finish() syncs
// and closes it. The first failure sticks: later calls do nothing and
// error() keeps the first message.
class CheckedFile {
public:
    CheckedFile(const std::string& path, WriteSite site);  // created or truncated
    ~CheckedFile();
    CheckedFile(const CheckedFile&) = delete;
    CheckedFile& operator=(const CheckedFile&) = delete;

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }
    void write(const void* data, std::size_t size);
    void write(const std::string& bytes) { write(bytes.data(), bytes.size()); }
    // Flushes, syncs and closes; "" or the first failure.
    std::string finish();

private:
    void flush();
    int fd_ = -1;
    std::string path_;
    WriteSite site_;
    std::string buffer_;
    std::string error_;
};

// Writes a file atomically: `fill(temporaryPath)` writes the temporary
// (through CheckedFile, or any writer that reports failure), which is then
// synced, renamed to `path` and its folder synced; on any failure the
// temporary is removed and `path` is untouched. "" or why not.
template <class Fill>
std::string writeAtomically(const std::string& path, WriteSite site, Fill fill);
// The same for bytes already in memory.
std::string writeFileAtomically(const std::string& path, const std::string& bytes, WriteSite site);

// The last two steps of writeAtomically, for callers that publish several
// temporaries together (a snapshot): sync a finished temporary.
std::string syncPath(const std::string& path, WriteSite site);

}  // namespace hg::io

namespace hg::io::detail {
std::string publish(const std::string& tmp, const std::string& path, WriteSite site);
}

template <class Fill>
std::string hg::io::writeAtomically(const std::string& path, WriteSite site, Fill fill) {
    const std::string tmp = temporaryPathFor(path);
    std::string why = fill(tmp);
    if (why.empty()) why = detail::publish(tmp, path, site);
    if (!why.empty()) std::remove(tmp.c_str());
    return why;
}

namespace hg::io {
// Checks that `path` can be created (its folder exists and is writable)
// without leaving anything behind. "" when it can.
std::string checkWritable(const std::string& path);
}  // namespace hg::io
