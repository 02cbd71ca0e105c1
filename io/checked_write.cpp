#include "io/checked_write.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <unistd.h>

namespace hg::io {

namespace {

constexpr std::size_t kBufferBytes = 1 << 20;

std::string failure(const char* what, const std::string& path, int error) {
    return std::string("cannot ") + what + " " + path + ": " + std::strerror(error);
}

}  // namespace

std::string writeAll(int fd, const void* data, std::size_t size, WriteSite site, const std::string& path) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        if (const int e = injectedFailure(site)) return failure("write", path, e);
        const ssize_t n = ::write(fd, p, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            return failure("write", path, errno);
        }
        // A short write is repeated for the rest; a second one that writes
        // nothing means the device is full.
        if (n == 0) return failure("write", path, ENOSPC);
        p += n;
        size -= static_cast<std::size_t>(n);
    }
    return "";
}

std::string syncFile(int fd, WriteSite site, const std::string& path) {
    if (const int e = injectedFailure(site)) return failure("sync", path, e);
    if (::fsync(fd) != 0) return failure("sync", path, errno);
    return "";
}

std::string truncateFile(int fd, std::uint64_t size, WriteSite site, const std::string& path) {
    if (const int e = injectedFailure(site)) return failure("cut", path, e);
    if (::ftruncate(fd, static_cast<off_t>(size)) != 0) return failure("cut", path, errno);
    return "";
}

std::string syncFolder(const std::string& folder, WriteSite site) {
    const std::string dir = folder.empty() ? "." : folder;
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return failure("open the folder", dir, errno);
    std::string why = syncFile(fd, site, dir);
    ::close(fd);
    return why;
}

std::string renameFile(const std::string& from, const std::string& to, WriteSite site) {
    if (const int e = injectedFailure(site)) return failure("move the finished file into place as", to, e);
    if (std::rename(from.c_str(), to.c_str()) != 0) return failure("move the finished file into place as", to, errno);
    return "";
}

std::string temporaryPathFor(const std::string& path) { return path + ".partial-" + std::to_string(::getpid()); }

bool isTemporaryName(const std::string& fileName) { return fileName.find(".partial-") != std::string::npos; }

CheckedFile::CheckedFile(const std::string& path, WriteSite site) : path_(path), site_(site) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0) error_ = failure("create", path, errno);
}

CheckedFile::~CheckedFile() {
    if (fd_ >= 0) ::close(fd_);
}

void CheckedFile::write(const void* data, std::size_t size) {
    if (!ok()) return;
    if (size >= kBufferBytes) {
        flush();
        if (ok()) error_ = writeAll(fd_, data, size, site_, path_);
        return;
    }
    if (buffer_.size() + size > kBufferBytes) flush();
    buffer_.append(static_cast<const char*>(data), size);
}

void CheckedFile::flush() {
    if (!ok() || buffer_.empty()) return;
    error_ = writeAll(fd_, buffer_.data(), buffer_.size(), site_, path_);
    buffer_.clear();
}

std::string CheckedFile::finish() {
    flush();
    if (ok()) error_ = syncFile(fd_, site_, path_);
    if (fd_ >= 0) {
        if (::close(fd_) != 0 && ok()) error_ = failure("close", path_, errno);
        fd_ = -1;
    }
    return error_;
}

std::string syncPath(const std::string& path, WriteSite site) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return failure("open", path, errno);
    std::string why = syncFile(fd, site, path);
    ::close(fd);
    return why;
}

std::string checkWritable(const std::string& path) {
    if (path.empty()) return "no output file given";
    const std::string probe = temporaryPathFor(path);
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) return failure("write", path, errno);
    ::close(fd);
    std::remove(probe.c_str());
    return "";
}

std::string writeFileAtomically(const std::string& path, const std::string& bytes, WriteSite site) {
    return writeAtomically(path, site, [&](const std::string& tmp) {
        CheckedFile file(tmp, site);
        file.write(bytes);
        return file.finish();
    });
}

namespace detail {

std::string publish(const std::string& tmp, const std::string& path, WriteSite site) {
    // Synced before the rename, so a crash never publishes a file whose
    // data is not on disk (writers that did not use CheckedFile included).
    if (std::string why = syncPath(tmp, site); !why.empty()) return why;
    if (std::string why = renameFile(tmp, path, site); !why.empty()) return why;
    if (std::string why = syncFolder(std::filesystem::path(path).parent_path().string(), site); !why.empty())
        return "wrote " + path + " but it may not survive a power cut: " + why;
    return "";
}

}  // namespace detail

}  // namespace hg::io
