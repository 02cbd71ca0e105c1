#include "polygonizer/realtime/meshing_worker.h"

#include <tbb/parallel_for.h>

namespace hg::poly {

void MeshingJob::run() {
    meshes.resize(samples.size());
    tbb::parallel_for(std::size_t{0}, samples.size(),
                      [this](std::size_t k) { meshes[k] = std::make_shared<const Mesh>(meshChunk(samples[k])); });
    samples.clear();
    samples.shrink_to_fit();
}

}  // namespace hg::poly
