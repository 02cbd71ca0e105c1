// A model evaluated in float at every point of a rectilinear lattice: the
// dense source cache and the normalization probe both sample this way. A
// model with a tape is evaluated in blocks of points, each with the tape
// specialized to its box (frep/eval/tape_specializer.h), which gives the same
// values bit for bit; an edited sculpture's pieces then run only near where
// they reach. Every value depends only on its point, so the result is the
// same whatever the number of threads.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "frep/language/domain_error.h"
#include "frep/eval/model.h"

namespace hg::voxel {

// axes[a]: the lattice's coordinates along axis a. `out` (and `failed`, if
// given: 1 where the program failed) receive one value per point, x fastest,
// then y, then z: f * scale. Domain errors are counted block by block (the
// interpreter's path: slice by slice), in a fixed order.
frep::ErrorReport evaluateLattice(const frep::Model& model, const std::array<std::vector<float>, 3>& axes, float* out,
                                  std::uint8_t* failed = nullptr, float scale = 1.0f);

}  // namespace hg::voxel
