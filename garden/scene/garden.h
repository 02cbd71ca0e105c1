// The garden as its file describes it (docs/garden-format.md): ground and
// paths, the sculptures with their HyperFun sources and placements, the
// morph triangle, lights and where the visitor starts. Plain data: loading
// and checking live in garden_file.h, the sculptures' models next to it.
// Units: metres in the world, the program's own units in a model box,
// degrees for angles, linear RGB in [0, 1] for colours.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "frep/kernels/box.h"

namespace hg::garden {

using Vec2 = std::array<double, 2>;  // a point on the ground: (x, z) in metres
using Vec3 = std::array<double, 3>;  // (x, y, z), y up

// The look of a material beyond its colour: the procedural detail it shows
// (veins, grain, patina, speckle), in the sculpture's model frame
// (docs/rendering.md "Materials", garden/scene/materials.h for the names).
enum class MaterialKind { Plain, Stone, Marble, Bronze, Clay, Plaster, Wood };

struct Material {
    std::string name;                 // the key in "materials" or a built-in's, or "" when written inline
    MaterialKind kind = MaterialKind::Plain;
    std::array<float, 3> color = {0.7f, 0.7f, 0.7f};
    float roughness = 0.5f;           // 0 mirror .. 1 matte
    float metallic = 0.0f;            // 0 dielectric .. 1 metal

    bool operator==(const Material& o) const {
        return name == o.name && kind == o.kind && color == o.color && roughness == o.roughness && metallic == o.metallic;
    }
    bool operator!=(const Material& o) const { return !(*this == o); }
};

// Where a model stands: model point p goes to position + R_y(yaw) * (scale * p).
struct Placement {
    Vec3 position = {0.0, 0.0, 0.0};  // metres
    double yawDegrees = 0.0;          // about +y, counter-clockwise seen from above
    double scale = 1.0;               // metres per model unit
};

// A scanned scalar volume as a sculpture's source (docs/garden-format.md,
// "volume"; docs/volumes.md, "Scanned volumes"): a raw 8- or 16-bit file or
// a float grid of a .vdb, and the iso-value whose surface is the solid.
struct ScanSpec {
    enum class Format { Raw, Vdb };
    Format format = Format::Raw;
    std::string grid;                 // .vdb: the float grid's name ("": the first)
    std::array<int, 3> dims{};        // raw: samples along x, y, z (x fastest)
    bool sixteenBit = false;          // raw: u16 little-endian, else u8
    Vec3 spacing = {1.0, 1.0, 1.0};   // raw: model units between samples
    double iso = 0.0;
    bool insideAbove = true;          // the solid is where samples exceed iso ("inside": "above")
    std::string at;                   // "garden.json: $.sculptures[2].volume": where its messages point
};

// A triangle mesh as a sculpture's source (docs/garden-format.md, "mesh"):
// an STL, OBJ or PLY file whose coordinates are the model frame, turned
// into the sculpture's level set by OpenVDB's mesh-to-volume.
struct MeshSpec {
    std::string at;                   // "garden.json: $.sculptures[2].mesh": where its messages point
};

struct SculptureSpec {
    std::string name;                 // unique in the garden
    std::string file;                 // the .hf path (or the scan's or mesh's file) resolved against the garden file's folder
    std::string fileAsWritten;        // as in the garden file (for messages and saving)
    std::optional<ScanSpec> scan;     // set: the source is this scanned volume, `file` its file
    std::optional<MeshSpec> mesh;     // set: the source is this mesh, `file` its file
    std::string body;                 // "": my_model, else the first body
    std::vector<double> a;            // a[1], a[2], ... (missing items are 0)
    std::optional<frep::Box3> box;    // model box; none: voxel::resolveModelBox
    int resolution = 128;             // voxels along the model box's longest side
    float band = 3.0f;                // narrow band half-width, voxels
    Placement placement;
    Material material;
};

// A metamorphosis (docs/design.md §4): three sources stand at the corners of the
// triangle (the corners are their positions on the ground), the result
// stands at its own placement, by default the triangle's centroid. A garden
// may hold several, each with its own sources, result and weights.
struct MorphSpec {
    std::array<std::string, 3> sources;       // sculpture names
    std::array<std::size_t, 3> sourceIndex{}; // into Garden::sculptures
    std::optional<std::array<double, 3>> balance;  // given balancing factors; none: computed
    Vec2 selector{};                          // the morph point at start (x, z), clamped to the triangle
    // The result.
    std::string resultName = "metamorphosis";
    Placement resultPlacement;
    std::optional<frep::Box3> box;            // shared model frame; none: union of the sources' boxes
    int resolution = 128;
    float band = 3.0f;
    Material material;
};

struct Ground {
    double height = 0.0;              // y of the ground plane, metres
    Vec2 size = {40.0, 40.0};         // extent along x and z, centred on the origin, metres
    Material material;
};

struct PathSpec {
    std::string name;
    std::vector<Vec2> points;         // a polyline on the ground (x, z), at least 2 points
    double width = 1.2;               // metres
    bool closed = false;              // the last point joins the first
    Material material;
};

struct Light {
    enum class Kind { Ambient, Directional, Point };
    Kind kind = Kind::Directional;
    std::array<float, 3> color = {1.0f, 1.0f, 1.0f};
    double intensity = 1.0;
    Vec3 direction = {0.0, -1.0, 0.0};  // directional: the way the light travels (normalized on load)
    Vec3 position = {0.0, 3.0, 0.0};    // point: metres
    double range = 10.0;                // point: metres beyond which it adds nothing
};

struct StartPose {
    Vec3 position = {0.0, 1.7, 8.0};  // the eye, metres
    Vec3 lookAt = {0.0, 1.0, 0.0};    // a point the eye looks at
};

struct Garden {
    std::string file;                 // the garden file as given
    std::string folder;               // where relative paths in it are resolved
    int version = 1;
    std::string name;
    Ground ground;
    std::vector<Material> materials;  // the named materials, in the file's order
    std::vector<SculptureSpec> sculptures;
    std::vector<PathSpec> paths;
    std::vector<MorphSpec> morphs;    // $.morph (one) or $.morphs, in the file's order
    std::vector<Light> lights;
    StartPose start;

    // Index of the sculpture with that name, or -1.
    int findSculpture(const std::string& sculptureName) const;
    // Index of the morph whose result has that name, or -1.
    int findMorph(const std::string& resultName) const;
};

}  // namespace hg::garden
