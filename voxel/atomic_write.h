// Implementation of writeAtomically (voxel/vdb_io.h).
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include <unistd.h>

namespace hg::voxel {

std::string temporaryPathFor(const std::string& path);

template <class Write>
std::string writeAtomically(const std::string& path, Write write) {
    const std::string tmp = temporaryPathFor(path);
    std::string why = write(tmp);
    if (why.empty() && std::rename(tmp.c_str(), path.c_str()) != 0)
        why = "cannot write " + path + ": cannot move the finished file into place: " + std::strerror(errno);
    if (!why.empty()) std::remove(tmp.c_str());
    return why;
}

}  // namespace hg::voxel
