// Stroke files, as `hypergarden gesture` reads them and as the committed
// hand-like set is stored (docs/gestures.md):
//   {"strokes": [{"points": [[x, y], ...], "label": "union", "note": "..."}],
//    "about": "..."}
// Points in screen pixels, y down; "label" (one of gesture_labels.h) and
// "note" are optional.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "garden/gesture/gesture_labels.h"
#include "garden/gesture/stroke.h"

namespace hg::garden {

struct FileStroke {
    StrokePoints points;
    std::optional<GestureLabel> label;
    std::string note;
};

// Throws GestureJsonError naming the path of the first bad value
// ("$.strokes[2].points[5]: expected [x, y], found an array of 3 items").
std::vector<FileStroke> readStrokeFile(const std::string& text);

// The whole file at `path`; throws GestureJsonError with the file named
// when it cannot be read.
std::string readGestureTextFile(const std::string& path);

}  // namespace hg::garden
