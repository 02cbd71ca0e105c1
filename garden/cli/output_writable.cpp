#include <iostream>

#include "garden/cli/load_model.h"
#include "voxel/vdb_io.h"

namespace hg::garden::cli {

bool outputWritable(const std::string& path) {
    std::string why = voxel::checkWritable(path);
    if (!why.empty()) std::cerr << "error: " << why << "\n";
    return why.empty();
}

}  // namespace hg::garden::cli
