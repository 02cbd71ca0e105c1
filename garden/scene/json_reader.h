// Strict, path-aware reading of a JSON document: every error names the JSON
// path of the offending value ("$.sculptures[2].placement.position") and
// says what was expected. Objects refuse keys they do not know (with the
// nearest known key as a suggestion), so a typo never passes silently, and
// the parser refuses duplicate keys (nlohmann-json would keep the last one).
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "frep/language/near_miss.h"

namespace hg::garden {

// What is wrong and where. `path` is a JSON path ("$" for the document) or,
// for a syntax error, "line L, column C".
class JsonError : public std::runtime_error {
public:
    JsonError(std::string path, std::string reason)
        : std::runtime_error(path + ": " + reason), path_(std::move(path)), reason_(std::move(reason)) {}
    const std::string& path() const { return path_; }
    const std::string& reason() const { return reason_; }

private:
    std::string path_;
    std::string reason_;
};

// Parses `text`; throws JsonError on a syntax error (with line and column)
// or a duplicate key (with the path of the object that repeats it).
nlohmann::json parseStrictJson(const std::string& text);

// `parent` + ".key", or + "[\"key\"]" when the key is not an identifier.
std::string childPath(const std::string& parent, const std::string& key);
std::string indexPath(const std::string& parent, std::size_t index);

// One JSON object being read: each key is claimed by required() or
// optional(); finish() rejects whatever was not claimed.
class ObjectReader {
public:
    // Throws "PATH: expected an object" when `value` is not one.
    ObjectReader(const nlohmann::json& value, std::string path, std::initializer_list<const char*> known);

    const std::string& path() const { return path_; }
    std::string pathOf(const char* key) const { return childPath(path_, key); }
    bool has(const char* key) const;
    // Throws "PATH: missing key 'key'".
    const nlohmann::json& required(const char* key) const;
    // nullptr when absent.
    const nlohmann::json* optional(const char* key) const;
    // Throws "PATH.key: unknown key (did you mean 'x'?; expected one of ...)"
    // for the first key that is not in `known`.
    void finish() const;

private:
    const nlohmann::json& value_;
    std::string path_;
    std::vector<std::string> known_;
};

// A number as JSON writes it, without a trailing ".0" ("64.5", "0", "1e+30").
std::string formatNumber(double v);

// The candidate nearest to `word` when it is a near miss (frep/language/near_miss.h).
using frep::nearMiss;

// Typed values; each throws JsonError at `path` when the value does not fit.
double readNumber(const nlohmann::json& v, const std::string& path);
double readNumber(const nlohmann::json& v, const std::string& path, double lo, double hi);
double readPositive(const nlohmann::json& v, const std::string& path);
int readInt(const nlohmann::json& v, const std::string& path, int lo, int hi);
bool readBool(const nlohmann::json& v, const std::string& path);
std::string readString(const nlohmann::json& v, const std::string& path, bool allowEmpty = false);
std::vector<double> readNumbers(const nlohmann::json& v, const std::string& path);
std::array<double, 2> readVec2(const nlohmann::json& v, const std::string& path);
std::array<double, 3> readVec3(const nlohmann::json& v, const std::string& path);
// Three numbers in [0, 1] (a linear RGB colour).
std::array<float, 3> readColor(const nlohmann::json& v, const std::string& path);

}  // namespace hg::garden
