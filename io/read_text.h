// A whole file read into a string: session files, garden files, HyperFun
// sources brought into a garden. Errors as text, for the caller's message.
#pragma once

#include <string>

namespace hg::io {

// "" on success, else "PATH: reason" (the system's, from errno).
std::string readText(const std::string& path, std::string& text);

}  // namespace hg::io
