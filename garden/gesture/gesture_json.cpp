#include "garden/gesture/gesture_json.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

namespace hg::garden {

using json = nlohmann::json;

json parseGestureJson(const std::string& text) {
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        // nlohmann reports a byte offset; users want a line and column.
        const std::size_t offset = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
        std::size_t line = 1, column = 1;
        for (std::size_t i = 0; i < offset; ++i) {
            if (text[i] == '\n') { ++line; column = 1; }
            else ++column;
        }
        std::string why = e.what();
        const std::size_t colon = why.find(": ", why.find("parse error"));
        if (colon != std::string::npos) why = why.substr(colon + 2);
        throw GestureJsonError("line " + std::to_string(line) + ", column " + std::to_string(column), "invalid JSON: " + why);
    } catch (const json::out_of_range&) {
        throw GestureJsonError("$", "a number too large for a double");
    }
}

std::string gestureJsonIndex(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

std::string describeGestureJson(const json& v) {
    switch (v.type()) {
        case json::value_t::null: return "null";
        case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
        case json::value_t::string: return "a string";
        case json::value_t::number_integer:
        case json::value_t::number_unsigned:
        case json::value_t::number_float: return "a number";
        case json::value_t::object: return "an object";
        case json::value_t::array: return "an array of " + std::to_string(v.size()) + " item" + (v.size() == 1 ? "" : "s");
        default: return "something else";
    }
}

void requireGestureObject(const json& value, const std::string& path, std::initializer_list<const char*> known) {
    if (!value.is_object()) throw GestureJsonError(path, "expected an object, found " + describeGestureJson(value));
    for (auto it = value.begin(); it != value.end(); ++it) {
        if (std::any_of(known.begin(), known.end(), [&](const char* k) { return it.key() == k; })) continue;
        std::string expected;
        for (const char* k : known) expected += std::string(" ") + k;
        throw GestureJsonError(path + "." + it.key(), "unknown key; expected one of:" + expected);
    }
}

double readGestureNumber(const json& v, const std::string& path) {
    if (!v.is_number()) throw GestureJsonError(path, "expected a number, found " + describeGestureJson(v));
    const double d = v.get<double>();
    if (!std::isfinite(d)) throw GestureJsonError(path, "expected a finite number");
    return d;
}

}  // namespace hg::garden
