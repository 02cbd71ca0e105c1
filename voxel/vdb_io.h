// Volumes in .vdb files. Our own grids keep HyperFun's sign (positive
// inside) and values in voxels, with metadata that says where they came
// from; the level-set export is for other tools (OpenVDB's convention:
// negative inside, world units, class level set). Files are written to a
// temporary name beside the target, synced and renamed into place, so a
// failure never leaves a partial file (io/checked_write.h).
#pragma once

#include <string>

#include "io/write_faults.h"
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

// "" on success, otherwise what went wrong (with the path). Every write is
// checked and passes the fault seam as `site` (io/checked_write.h).
std::string writeVolume(const Volume& volume, const std::string& path, io::WriteSite site = io::WriteSite::Export);
// The bytes writeVolume would write, for callers that publish several
// files together (a session's snapshot). "" or why not.
std::string encodeVolume(const Volume& volume, std::string& bytes);
// The level set for other tools: negative inside, signed distances; in
// model units, or in metres with the sculpture's metres per model unit
// (values and transform scaled alike).
std::string writeLevelSet(const Volume& volume, const std::string& path, double metresPerUnit = 0.0);

// Reads the grid named `gridName` ("" : the first Hypergarden grid in the
// file). "" on success.
std::string readVolume(const std::string& path, Volume& volume, const std::string& gridName = "");

}  // namespace hg::voxel
