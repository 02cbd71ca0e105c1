// Meshes brought into a garden (docs/garden-format.md, "mesh"): STL (binary
// or ASCII, stl_io.h), Wavefront OBJ and PLY read into one indexed triangle
// mesh in the file's own coordinates. OBJ and PLY polygons are split into a
// fan of triangles from their first corner. Bad input is refused with where
// it is: "x.obj:12: face index 9 out of range (7 vertices)", a PLY's binary
// part by byte offset; a file with no triangle is refused as empty.
#pragma once

#include <string>

#include "polygonizer/mesh.h"

namespace hg::poly {

struct MeshReadResult {
    Mesh mesh;          // positions and indices; no normals
    std::string error;  // "" on success, else the message (the path and where in it)
};

// Wavefront OBJ: `v x y z [w]` and `f a b c ...` (indices 1-based, negative
// ones counted back from the latest vertex, `a/t/n` forms take `a`); every
// other statement (normals, texture coordinates, groups, materials, lines)
// is skipped.
MeshReadResult readObj(const std::string& path);
// PLY, `format ascii 1.0` or `binary_little_endian 1.0`: the `vertex`
// element's x, y, z and the `face` element's `vertex_indices` (or
// `vertex_index`) list; other elements and properties are read past.
MeshReadResult readPly(const std::string& path);
// By the name's extension, any case: .stl (welded by position, a facet
// soup becoming one surface), .obj or .ply.
MeshReadResult readMeshFile(const std::string& path);
// Whether readMeshFile reads files named so.
bool isMeshFileName(const std::string& path);

}  // namespace hg::poly
