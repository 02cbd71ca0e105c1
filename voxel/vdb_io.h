// Volumes in .vdb files. Our own grids keep HyperFun's sign (positive
// inside) and values in voxels, with metadata that says where they came
// from; the level-set export is for other tools (OpenVDB's convention:
// negative inside, world units, class level set). Files are written to a
// temporary name beside the target and renamed into place, so a failure
// never leaves a partial file.
#pragma once

#include <string>

#include "voxel/volume.h"

namespace hg::voxel {

// Metadata keys (all prefixed "hypergarden.").
namespace meta {
constexpr const char* kFormat = "hypergarden.format";            // int, 1
constexpr const char* kKind = "hypergarden.kind";                // "narrow-band" | "dense-source"
constexpr const char* kSourceFile = "hypergarden.source_file";
constexpr const char* kBody = "hypergarden.body";
constexpr const char* kParameters = "hypergarden.a";             // "0.4,1" (round-trip exact)
constexpr const char* kNormalization = "hypergarden.normalization";  // stored = f * this
constexpr const char* kBand = "hypergarden.band";                // voxels
constexpr const char* kSign = "hypergarden.sign";                // human-readable convention
constexpr const char* kResolution = "hypergarden.resolution";
constexpr const char* kModelBoxMin = "hypergarden.model_box_min";
constexpr const char* kModelBoxMax = "hypergarden.model_box_max";
constexpr const char* kBoxEstimated = "hypergarden.box_estimated";  // bool: the box was not given
constexpr const char* kBoxOrigin = "hypergarden.box_origin";        // boxOriginName()
constexpr const char* kIndexMin = "hypergarden.index_min";
constexpr const char* kIndexMax = "hypergarden.index_max";
}  // namespace meta

// "" on success, otherwise what went wrong (with the path).
std::string writeVolume(const Volume& volume, const std::string& path);
// The level set for other tools: negative inside, signed distances; in
// model units, or in metres with the sculpture's metres per model unit
// (values and transform scaled alike).
std::string writeLevelSet(const Volume& volume, const std::string& path, double metresPerUnit = 0.0);

// Reads the grid named `gridName` ("" : the first Hypergarden grid in the
// file). "" on success.
std::string readVolume(const std::string& path, Volume& volume, const std::string& gridName = "");

// Writes `contents` to `path` atomically: `write(tmpPath)` fills a temporary
// file in the same directory, which is renamed to `path` when it returns ""
// and removed otherwise. Returns `write`'s message or the rename's.
template <class Write>
std::string writeAtomically(const std::string& path, Write write);

// Checks that `path` can be created (its directory exists and is writable)
// without leaving anything behind. "" when it can.
std::string checkWritable(const std::string& path);

}  // namespace hg::voxel

#include "voxel/atomic_write.h"
