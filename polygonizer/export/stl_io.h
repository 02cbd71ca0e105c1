// STL files for 3D printing. Binary by default (smaller, exact floats);
// ASCII on request, with enough digits that every float reads back the
// same. Files are written to a temporary name beside the target and renamed
// into place, so a failure never leaves a partial file.
#pragma once

#include <string>

#include "polygonizer/mesh.h"

namespace hg::poly {

// Writes `mesh` with every coordinate multiplied by `scale` (for example
// millimetres per model unit; must be finite and positive, since a negative
// one would turn the solid inside out). Facet normals are computed from each
// triangle, not taken from the vertex normals. "" on success, otherwise what
// went wrong, with the path. Facets are formatted on TBB workers a slice at
// a time and written in order as slices are ready: the same bytes on any
// number of threads.
std::string writeStl(const Mesh& mesh, const std::string& path, bool ascii = false, double scale = 1.0,
                     const std::string& solidName = "hypergarden");

struct StlReadResult {
    Mesh mesh;          // a triangle soup: three fresh vertices per facet, no normals
    std::string error;  // "" on success; names the path (and the line, for ASCII)
    bool ascii = false;
    std::string solidName;  // ASCII: the name after "solid"; binary: the header text
};

// Reads binary or ASCII STL. A file is binary when its size is exactly what
// its triangle count says (84 + 50 * count bytes), even if it starts with
// "solid" as some exporters' are; otherwise ASCII if it starts with
// "solid". Weld the result (weldByPosition) before validating it.
StlReadResult readStl(const std::string& path);

}  // namespace hg::poly
