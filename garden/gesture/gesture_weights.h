// The weights file, content/gestures/weights.json (docs/gestures.md): the
// network, the threshold, the feature layout it was trained on (refused
// when it differs from this build's) and how it was trained, with a
// checksum of every weight so that a test can tell a retrained file from
// the committed one.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "garden/gesture/gesture_recognizer.h"

namespace hg::garden {

// FNV-1a over the bits of every number of the network, in file order.
std::uint64_t gestureNetworkChecksum(const GestureNetwork& network);
std::string checksumHex(std::uint64_t checksum);

// The file's text: one row of weights a line, every number written so that
// it reads back to the same double. `training` is stored as given, with
// "checksum" added.
std::string writeGestureWeights(const GestureRecognizer& recognizer, const nlohmann::json& training);

// Throws GestureJsonError (JSON path and reason) for a file that is not a
// weights file of this build's features and labels, or whose weights do not
// match their checksum.
GestureRecognizer readGestureWeights(const std::string& text);

// readGestureWeights of the file at `path`; errors name the file.
GestureRecognizer loadGestureWeights(const std::string& path);

}  // namespace hg::garden
