// One writer per folder (docs/session-format.md, "One writer"): an
// exclusive open-file-description lock (fcntl F_OFD_SETLK) on FOLDER/LOCK
// held while the folder is open for writing. The kernel releases it when
// the process dies, so a crash never leaves a stale lock; the file's text
// names the holder (process id, host, since when, what it is) for the
// message a second opener gets.
#pragma once

#include <memory>
#include <optional>
#include <string>

namespace hg::io {

struct LockHolder {
    long pid = 0;
    std::string host;
    std::string since;    // UTC, ISO 8601
    std::string program;  // "hypergarden replay", say
    // "process 1234 (hypergarden replay) on host since 2026-11-26 03:20:01 UTC"
    std::string describe() const;
};

class FolderLock {
public:
    ~FolderLock();
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

    // Takes the lock on `folder`/`fileName`, writing the holder note.
    // Null when another process (or another open in this one) holds it:
    // `holder` then says who, and `why` is the message; or when the lock
    // file cannot be made (`why`).
    static std::unique_ptr<FolderLock> acquire(const std::string& folder, const std::string& fileName,
                                               const std::string& program, std::string& why,
                                               std::optional<LockHolder>& holder);

private:
    FolderLock() = default;
    int fd_ = -1;
};

// Who holds the lock on `folder`/`fileName` now, without taking it (none
// when nobody does, or there is no lock file).
std::optional<LockHolder> lockHolder(const std::string& folder, const std::string& fileName);

}  // namespace hg::io
