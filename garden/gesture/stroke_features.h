// What the network sees of a stroke (docs/gestures.md, "Features"): the
// seed's description by the sine and cosine of the local direction changes
// along the resampled path, plus a few whole-stroke numbers that separate
// loops from half turns and lines from curves. Every number depends on
// angles and length ratios only, so the description is the same whatever
// the stroke's position, size, rotation and drawing speed; mirroring it
// flips the sign of the sines (a left turn becomes a right turn).
#pragma once

#include <vector>

#include "garden/gesture/stroke.h"

namespace hg::garden {

// The fixed shape of the description; the weights file records them and
// is refused when they differ.
constexpr double kFeatureThinning = 0.05;  // points closer than this x the stroke's RMS radius are dropped
constexpr int kFeatureResample = 64;    // first, even resampling (removes speed and point density)
constexpr int kFeatureSmoothing = 2;    // [1 2 1]/4 passes over it (removes jitter)
constexpr int kFeatureSegments = 32;    // then this many equal segments
constexpr int kFeatureTurns = kFeatureSegments - 1;
constexpr int kFeatureExtras = 6;
constexpr int kFeatureCount = 2 * kFeatureTurns + kFeatureExtras;

// The turning angle between consecutive segments of the resampled path,
// in radians: positive turns clockwise on the screen (y down), that is to
// the pen's right. Empty for a degenerate stroke (under two distinct
// points).
std::vector<double> strokeTurns(const StrokePoints& points);

// kFeatureCount numbers: sin and cos of each turn, then
//   signed turning / 4 pi, absolute turning / 4 pi (each clamped to +-2),
//   signed / absolute turning, gap between the ends / path length,
//   the largest single turn / pi, and the stroke's roundness (the ratio of
//   its principal axes, 0 for a line, 1 for a circle).
// Empty for a degenerate stroke.
std::vector<double> strokeFeatures(const StrokePoints& points);

}  // namespace hg::garden
