#include "io/folder_lock.h"

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

#include "io/checked_write.h"

namespace hg::io {

namespace {

std::string nowUtc() {
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    ::gmtime_r(&t, &tm);
    char buf[40];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S UTC", &tm);
    return buf;
}

std::string hostName() {
    char buf[256] = {};
    if (::gethostname(buf, sizeof buf - 1) != 0) return "unknown host";
    return buf;
}

// The holder note: one "key value" line each, read back loosely (a note
// cut short by a full disk still names what it can).
std::string noteText(const LockHolder& h) {
    return "pid " + std::to_string(h.pid) + "\nhost " + h.host + "\nsince " + h.since + "\nprogram " + h.program + "\n";
}

LockHolder parseNote(const std::string& text) {
    LockHolder h;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const std::size_t sp = line.find(' ');
        if (sp == std::string::npos) continue;
        const std::string key = line.substr(0, sp), value = line.substr(sp + 1);
        if (key == "pid") h.pid = std::strtol(value.c_str(), nullptr, 10);
        else if (key == "host") h.host = value;
        else if (key == "since") h.since = value;
        else if (key == "program") h.program = value;
    }
    return h;
}

std::string readNote(int fd) {
    std::string text;
    char buf[512];
    off_t at = 0;
    for (;;) {
        const ssize_t n = ::pread(fd, buf, sizeof buf, at);
        if (n <= 0) break;
        text.append(buf, static_cast<std::size_t>(n));
        at += n;
        if (text.size() > 4096) break;
    }
    return text;
}

struct flock wholeFile(short type) {
    struct flock l {};
    l.l_type = type;
    l.l_whence = SEEK_SET;
    l.l_start = 0;
    l.l_len = 0;
    return l;
}

}  // namespace

std::string LockHolder::describe() const {
    std::string s = "process " + (pid > 0 ? std::to_string(pid) : std::string("(unknown)"));
    if (!program.empty()) s += " (" + program + ")";
    if (!host.empty()) s += " on " + host;
    if (!since.empty()) s += " since " + since;
    return s;
}

FolderLock::~FolderLock() {
    if (fd_ >= 0) ::close(fd_);  // releases the lock
}

std::unique_ptr<FolderLock> FolderLock::acquire(const std::string& folder, const std::string& fileName,
                                                const std::string& program, std::string& why,
                                                std::optional<LockHolder>& holder) {
    holder.reset();
    const std::string path = (std::filesystem::path(folder) / fileName).string();
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
        why = "cannot open the lock " + path + ": " + std::strerror(errno);
        return nullptr;
    }
    struct flock l = wholeFile(F_WRLCK);
    if (::fcntl(fd, F_OFD_SETLK, &l) != 0) {
        const int e = errno;
        if (e == EAGAIN || e == EACCES) {
            holder = parseNote(readNote(fd));
            why = folder + " is open in " + holder->describe() + "; close it there first";
        } else {
            why = "cannot lock " + path + ": " + std::strerror(e);
        }
        ::close(fd);
        return nullptr;
    }
    std::unique_ptr<FolderLock> lock(new FolderLock());
    lock->fd_ = fd;
    // The note is a courtesy for the next opener: a full disk must not stop
    // the session opening, so its failure is not one.
    LockHolder me;
    me.pid = static_cast<long>(::getpid());
    me.host = hostName();
    me.since = nowUtc();
    me.program = program;
    const std::string note = noteText(me);
    if (truncateFile(fd, 0, WriteSite::SessionFile, path).empty() && ::lseek(fd, 0, SEEK_SET) == 0)
        (void)writeAll(fd, note.data(), note.size(), WriteSite::SessionFile, path);
    return lock;
}

std::optional<LockHolder> lockHolder(const std::string& folder, const std::string& fileName) {
    const std::string path = (std::filesystem::path(folder) / fileName).string();
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::nullopt;
    struct flock l = wholeFile(F_WRLCK);
    std::optional<LockHolder> out;
    if (::fcntl(fd, F_OFD_GETLK, &l) == 0 && l.l_type != F_UNLCK) out = parseNote(readNote(fd));
    ::close(fd);
    return out;
}

}  // namespace hg::io
