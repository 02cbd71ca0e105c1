// Sketch to outline (issue 22, "Sketching"): a raw 2D path drawn on the
// sketch plane (plane coordinates, metres) becomes the closed simple outline
// the inflation starts from, or a clear refusal.
//
// The steps follow the seed (Kainz's thesis, after Igarashi's Teddy):
//  1. Jitter: points closer than a fraction of the sample spacing to the last
//     kept one are dropped (slow drawing piles points up), then the path is
//     lightly smoothed (endpoints fixed).
//  2. Self-crossing: the seed ends a sketch when the pen crosses its own
//     path and keeps the loop between the two passes, cutting the loose
//     ends; a crossing counts only when the loop holds most of the path
//     drawn up to it (the seed: more than half; here 60%), so a small curl
//     at the start does not end the sketch. Without a crossing the open
//     ends are joined. A figure eight is refused: either its first lobe is
//     too small a part of the path to end it (and the joined outline then
//     crosses itself) or its crossing leaves a tail as long as a second
//     lobe, where a lasso's overshoot is short.
//  3. The closed loop is resampled to uniform spacing along its length (the
//     number of samples sets the model's detail and cost).
//  4. Refusals, never a broken outline: too few points, too short, (almost)
//     no area, a remaining self-intersection. The outline is turned
//     counter-clockwise.
#pragma once

#include <string>
#include <vector>

#include "garden/sketch/geometry2d.h"

namespace hg::garden::sketch {

struct OutlineOptions {
    // Sample spacing in metres; when <= 0, `samples` samples over the loop.
    double spacing = 0.0;
    int samples = 96;
    // Points closer than this fraction of the spacing to the previous kept
    // point are jitter.
    double jitterFraction = 0.3;
    int smoothingPasses = 2;
    // A crossing ends the sketch when its loop holds at least this fraction
    // of the path drawn up to the crossing (the seed: more than half; 0.6
    // keeps a figure eight begun at its waist, whose first lobe is about
    // half of the path, from passing as a lasso).
    double minLoopFraction = 0.6;
    // ... and the path after the crossing is at most this fraction of the
    // loop; a longer tail is a figure eight (or a scribble) and is refused.
    double maxTailFraction = 0.3;
    // Fewest samples an outline may have, and the least isoperimetric ratio
    // 4 pi A / P^2 (1 for a circle; a 1:100 sliver is about 0.03).
    int minSamples = 8;
    double minRoundness = 0.01;
};

struct Outline {
    std::vector<Vec2> points;  // counter-clockwise, closed (last joins first), no repeats
    double spacing = 0.0;      // the loop's length / number of samples
    bool cutAtCrossing = false;  // a self-crossing ended the sketch (loose ends cut)
    std::string error;         // "" when `points` is a valid outline; else why it was refused
    bool ok() const { return error.empty(); }
};

Outline makeOutline(const std::vector<Vec2>& raw, const OutlineOptions& options = {});

// A closed polygon is simple when no two non-adjacent edges meet (crossing
// or touching within `tolerance` metres) and no edge has zero length.
bool isSimplePolygon(const std::vector<Vec2>& polygon, double tolerance = 0.0);

// `closed` (last joins first) resampled to `n` points evenly spaced along
// its length, starting at its first point.
std::vector<Vec2> resampleClosed(const std::vector<Vec2>& closed, int n);

}  // namespace hg::garden::sketch
