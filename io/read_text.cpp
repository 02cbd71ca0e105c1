#include "io/read_text.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace hg::io {

std::string readText(const std::string& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return path + ": " + std::strerror(errno);
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
    return "";
}

}  // namespace hg::io
