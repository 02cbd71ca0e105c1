#include <iostream>

#include "cli/load_model.h"
#include "io/checked_write.h"

namespace hg::garden::cli {

bool outputWritable(const std::string& path) {
    std::string why = io::checkWritable(path);
    if (!why.empty()) std::cerr << "error: " << why << "\n";
    return why.empty();
}

}  // namespace hg::garden::cli
