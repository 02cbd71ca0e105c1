// Scanned volumes (docs/volumes.md, "Scanned volumes"): a scalar field
// sampled on a lattice, read from a raw 8- or 16-bit file or from a float
// grid of a .vdb file, and its iso-surface turned into a sculpture's
// narrow-band level set at the sculpture's own resolution. The samples
// themselves are not a distance (a CT's densities), so the surface is
// extracted and a true signed distance rebuilt from it at the sculpture's
// voxel size: the garden's band, meshing and edits rely on one unit per
// voxel across the surface.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "frep/kernels/box.h"
#include "voxel/sampler.h"

namespace hg::voxel {

struct ScalarGrid;  // the samples as an OpenVDB FloatGrid (scalar_volume.cpp)

enum class SampleType { U8, U16 };  // u16: little-endian

// A raw volume's layout: samples x fastest, then y (up in the garden), then
// z; sample (i, j, k) sits at model point (i sx, j sy, k sz).
struct RawVolumeLayout {
    std::array<int, 3> dims{};
    SampleType type = SampleType::U8;
    std::array<double, 3> spacing{1.0, 1.0, 1.0};  // model units between samples
};

// Limits on a raw volume's dimensions.
constexpr int kMinRawDim = 2;
constexpr int kMaxRawDim = 8192;

class ScalarVolume {
public:
    ScalarVolume();
    ~ScalarVolume();
    ScalarVolume(ScalarVolume&&) noexcept;
    ScalarVolume& operator=(ScalarVolume&&) noexcept;

    double minValue = 0.0;    // over every sample (a .vdb's background included)
    double maxValue = 0.0;
    std::string description;  // what was read, for messages and tooltips
    bool levelSet = false;    // a .vdb grid of class level set (distance, negative inside)
    std::shared_ptr<const ScalarGrid> grid;
};

// Reads a raw volume. "" on success, else why not (the file named): it
// cannot be opened, or its size is not dims x the sample's bytes.
std::string readRawVolume(const std::string& path, const RawVolumeLayout& layout, ScalarVolume& out);
// Reads the float grid `gridName` ("": the first float grid) of a .vdb
// file, in its own transform (world units become model units). "" or why
// not (no such grid, none of type float, with the grids it has named).
std::string readScalarVdb(const std::string& path, const std::string& gridName, ScalarVolume& out);

struct IsoSurfaceRequest {
    double iso = 0.0;
    bool insideAbove = true;             // the solid is where samples exceed iso (else below it)
    std::optional<frep::Box3> box;       // none: the inside samples' bounds grown by a sample each side
    int resolution = 128;                // voxels along the model box's longest side
    float band = 3.0f;
    VolumeSource source;                 // recorded in the volume's metadata
    std::uint64_t memoryLimit = 0;       // bytes; 0: 80% of the memory available now
};

// The sculpture's grid: the trilinear iso-surface of the samples (outside
// the samples is outside), as a signed distance positive inside, in voxels
// (normalization 1 / voxelSize), clamped to +-band like every other
// sculpture's grid. The same bits every time for the same input. Refused
// with a reason when iso is not strictly within the samples' range, nothing
// is inside, the solid would be unbounded (a .vdb whose background is
// inside), or the grid would not fit the memory limit (with the resolution
// that would).
VoxelizeResult levelSetFromScalar(const ScalarVolume& volume, const IsoSurfaceRequest& request);

}  // namespace hg::voxel
