// What a sampled grid needs before its chunks can be meshed: the coarse
// levels (poly::LodPyramid), the chunks (poly::ChunkLayout) and how far each
// chunk's coarse levels stray (poly::ChunkErrors). Building them costs tens
// of milliseconds for a 256^3 grid, so the background loader builds them
// next to the sampling (sculpture_loader.h) and the frame only attaches
// them (docs/design.md §6, "Progressive loading").
#pragma once

#include <memory>

namespace hg::voxel {
class Volume;
}

namespace hg::poly {
class ChunkErrors;
class ChunkLayout;
class LodPyramid;
}  // namespace hg::poly

namespace hg::garden {

// The session's meshing settings that shape these (SessionSettings).
struct MeshingShape {
    int levels = 4;              // maxLevel + 1
    int chunkSize = 32;
    bool measureErrors = true;   // levelErrorPixels > 0
};

struct PreparedMeshing {
    std::unique_ptr<poly::LodPyramid> pyramid;
    std::unique_ptr<poly::ChunkLayout> layout;
    std::unique_ptr<poly::ChunkErrors> errors;  // none unless measureErrors

    // Out of line: the pieces are incomplete here (this header is kept light).
    PreparedMeshing();
    ~PreparedMeshing();
    PreparedMeshing(PreparedMeshing&&) noexcept;
    PreparedMeshing& operator=(PreparedMeshing&&) noexcept;
};

// Built on `volume`, which must stay where it is (a heap Volume moved by
// its unique_ptr does) for as long as the result is used.
PreparedMeshing prepareMeshing(const voxel::Volume& volume, const MeshingShape& shape);
// `source` (built on a grid equal to `volume`'s) copied onto `volume`: what
// prepareMeshing would build there, in a fraction of its time.
PreparedMeshing copyMeshing(const PreparedMeshing& source, const voxel::Volume& volume);

}  // namespace hg::garden
