// The model box a sculpture is sampled over: the one given, else the interval
// estimate (frep/eval/bounds.h), else, where that fails, the region found by
// sampling HyperFun's default box [-10, 10]^3. Interval bounds far from a
// blend or a twist are often too loose to prove space empty, and that must
// not make a bounded file unusable: HyperFun's own polygonizer samples that
// default box, so that is what its users expect. Only a solid that still
// reaches the default box's faces is refused as unbounded.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "frep/eval/bounds.h"
#include "frep/eval/model.h"
#include "voxel/volume.h"

namespace hg::voxel {

// HyperFun's default bounding box, [-s, s]^3.
constexpr double kDefaultBoxHalfSize = 10.0;
// Voxels along each side of the two coarse passes: the default box, then
// the occupied region it shows. 20 / 128 = 0.16 units between samples of
// the first pass.
constexpr int kSampledBoxResolution = 128;
// Coarse cells added around the inside samples of each pass: the surface
// lies within one cell of them; the second covers thin parts between samples.
constexpr int kSampledBoxMargin = 2;

struct ModelBox {
    frep::Box3 box;
    BoxOrigin origin = BoxOrigin::Given;
    // Sampled: why the interval estimate was not used, and what the coarse
    // passes cost.
    std::string estimateFailure;
    std::uint64_t samples = 0;
    double seconds = 0.0;
};

// Resolves `given`, or finds the box as above. "" on success, else why
// there is none (an empty solid, one that reaches the default box's faces
// with the faces named, or the coarse passes' own errors).
std::string resolveModelBox(const frep::Model& model, const std::optional<frep::Box3>& given, ModelBox& out);

// One line for the commands' output: the box and how it was found.
std::string describeModelBox(const ModelBox& box);

}  // namespace hg::voxel
