#include "cli/full_executable.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

namespace hg::garden::cli {

int runFullExecutable(char** argv) {
    std::error_code ec;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) self = argv[0];
    const std::string full = (self.parent_path() / "hypergarden-full").string();
    ::execv(full.c_str(), argv);
    std::fprintf(stderr, "error: cannot start %s: %s\n", full.c_str(), std::strerror(errno));
    return 2;
}

}  // namespace hg::garden::cli
