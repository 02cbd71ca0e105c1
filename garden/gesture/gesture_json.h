// Path-aware JSON reading for the gesture files (strokes and weights), in
// the manner of garden/scene/json_reader.h: every error names the JSON path
// of the offending value ("$.strokes[2].points[5]") or, for a syntax error,
// its line and column. A copy rather than a use of json_reader because
// hg_gesture depends on the standard library and nlohmann_json only.
#pragma once

#include <initializer_list>
#include <stdexcept>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace hg::garden {

class GestureJsonError : public std::runtime_error {
public:
    GestureJsonError(const std::string& path, const std::string& reason)
        : std::runtime_error(path + ": " + reason), path_(path), reason_(reason) {}
    const std::string& path() const { return path_; }
    const std::string& reason() const { return reason_; }

private:
    std::string path_, reason_;
};

// Throws GestureJsonError at "line L, column C" for a syntax error.
nlohmann::json parseGestureJson(const std::string& text);

std::string gestureJsonIndex(const std::string& parent, std::size_t index);
// What a value is, in words: "a string", "an array of 3 items", ...
std::string describeGestureJson(const nlohmann::json& value);
// Throws at `path` unless `value` is an object whose keys are all in `known`.
void requireGestureObject(const nlohmann::json& value, const std::string& path, std::initializer_list<const char*> known);
// A finite number, or throws at `path`.
double readGestureNumber(const nlohmann::json& value, const std::string& path);

}  // namespace hg::garden
