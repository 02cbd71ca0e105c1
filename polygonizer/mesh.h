// A triangle mesh as the renderer uploads it and the STL writer exports it:
// positions and normals as packed xyz floats, 32-bit indices, three per
// triangle, counter-clockwise seen from outside.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hg::poly {

struct Mesh {
    std::vector<float> positions;     // x, y, z per vertex (model units)
    std::vector<float> normals;       // unit outward normal per vertex (may be empty)
    std::vector<std::uint32_t> indices;

    std::size_t vertexCount() const { return positions.size() / 3; }
    std::size_t triangleCount() const { return indices.size() / 3; }
    bool empty() const { return indices.empty(); }
};

}  // namespace hg::poly
