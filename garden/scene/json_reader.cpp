#include "garden/scene/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

namespace hg::garden {

namespace {

using json = nlohmann::json;

bool isIdentifier(const std::string& key) {
    if (key.empty() || !(std::isalpha(static_cast<unsigned char>(key[0])) || key[0] == '_')) return false;
    return std::all_of(key.begin(), key.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// What the user wrote, in words: "a string", "an array of 2 items", ...
std::string describe(const json& v) {
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

// Where the parser is, for duplicate keys: one frame per open container.
struct Frame {
    bool array = false;
    std::size_t next = 0;  // index of the next array element
    std::string key;       // last key read (objects)
    std::set<std::string> keys;
    std::string path;
};

std::string syntaxReason(const std::string& what) {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..."
    std::size_t at = what.find("parse error");
    if (at == std::string::npos) return what;
    std::size_t colon = what.find(": ", at);
    return colon == std::string::npos ? what : what.substr(colon + 2);
}

}  // namespace

std::string childPath(const std::string& parent, const std::string& key) {
    if (isIdentifier(key)) return parent + "." + key;
    return parent + "[" + json(key).dump() + "]";
}

std::string indexPath(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

json parseStrictJson(const std::string& text) {
    std::vector<Frame> stack;
    auto openPath = [&]() -> std::string {
        if (stack.empty()) return "$";
        Frame& top = stack.back();
        return top.array ? indexPath(top.path, top.next++) : childPath(top.path, top.key);
    };
    json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start:
            case json::parse_event_t::array_start: {
                Frame f;
                f.path = openPath();
                f.array = event == json::parse_event_t::array_start;
                stack.push_back(std::move(f));
                break;
            }
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                stack.pop_back();
                break;
            case json::parse_event_t::key: {
                Frame& top = stack.back();
                top.key = parsed.get<std::string>();
                if (!top.keys.insert(top.key).second)
                    throw JsonError(top.path, "duplicate key '" + top.key + "'");
                break;
            }
            case json::parse_event_t::value:
                if (!stack.empty() && stack.back().array) ++stack.back().next;
                break;
        }
        return true;
    };
    try {
        return json::parse(text, callback);
    } catch (const json::parse_error& e) {
        std::size_t offset = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
        std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
        std::size_t lineStart = text.rfind('\n', offset == 0 ? 0 : offset - 1);
        std::size_t column = lineStart == std::string::npos || offset == 0 ? offset + 1 : offset - lineStart;
        if (offset > 0 && text[offset - 1] == '\n') column = 1;
        throw JsonError("line " + std::to_string(line) + ", column " + std::to_string(column),
                        "invalid JSON: " + syntaxReason(e.what()));
    } catch (const json::out_of_range&) {
        // A number past double's range (1e999): the value being read when
        // the parser gave up. Found by the fuzzer.
        std::string path = "$";
        if (!stack.empty()) {
            const Frame& top = stack.back();
            path = top.array ? indexPath(top.path, top.next) : childPath(top.path, top.key);
        }
        throw JsonError(path, "a number too large for a double");
    }
}

ObjectReader::ObjectReader(const json& value, std::string path, std::initializer_list<const char*> known)
    : value_(value), path_(std::move(path)), known_(known.begin(), known.end()) {
    if (!value_.is_object()) throw JsonError(path_, "expected an object, found " + describe(value_));
}

bool ObjectReader::has(const char* key) const { return value_.contains(key); }

const json& ObjectReader::required(const char* key) const {
    auto it = value_.find(key);
    if (it == value_.end()) throw JsonError(path_, std::string("missing key '") + key + "'");
    return *it;
}

const json* ObjectReader::optional(const char* key) const {
    auto it = value_.find(key);
    return it == value_.end() ? nullptr : &*it;
}

void ObjectReader::finish() const {
    for (auto it = value_.begin(); it != value_.end(); ++it) {
        if (std::find(known_.begin(), known_.end(), it.key()) != known_.end()) continue;
        std::string best = nearMiss(it.key(), known_);
        std::string reason = "unknown key";
        if (!best.empty()) reason += " (did you mean '" + best + "'?)";
        reason += "; expected one of:";
        for (const auto& k : known_) reason += " " + k;
        throw JsonError(childPath(path_, it.key()), reason);
    }
}

double readNumber(const json& v, const std::string& path) {
    if (!v.is_number()) throw JsonError(path, "expected a number, found " + describe(v));
    double d = v.get<double>();
    if (!std::isfinite(d)) throw JsonError(path, "expected a finite number");
    return d;
}

std::string formatNumber(double v) {
    std::string s = json(v).dump();
    if (s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0) s.resize(s.size() - 2);
    return s;
}

double readNumber(const json& v, const std::string& path, double lo, double hi) {
    double d = readNumber(v, path);
    if (d < lo || d > hi)
        throw JsonError(path, "expected a number in [" + formatNumber(lo) + ", " + formatNumber(hi) + "], found " +
                                  formatNumber(d));
    return d;
}

double readPositive(const json& v, const std::string& path) {
    double d = readNumber(v, path);
    if (!(d > 0.0)) throw JsonError(path, "expected a positive number, found " + formatNumber(d));
    return d;
}

int readInt(const json& v, const std::string& path, int lo, int hi) {
    bool integral = v.is_number_integer() || v.is_number_unsigned() ||
                    (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>());
    if (!integral) throw JsonError(path, "expected an integer, found " + (v.is_number() ? formatNumber(v.get<double>()) : describe(v)));
    double d = v.get<double>();
    if (d < lo || d > hi)
        throw JsonError(path, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], found " +
                                  formatNumber(d));
    return static_cast<int>(d);
}

bool readBool(const json& v, const std::string& path) {
    if (!v.is_boolean()) throw JsonError(path, "expected true or false, found " + describe(v));
    return v.get<bool>();
}

std::string readString(const json& v, const std::string& path, bool allowEmpty) {
    if (!v.is_string()) throw JsonError(path, "expected a string, found " + describe(v));
    std::string s = v.get<std::string>();
    if (s.empty() && !allowEmpty) throw JsonError(path, "expected a non-empty string");
    return s;
}

std::vector<double> readNumbers(const json& v, const std::string& path) {
    if (!v.is_array()) throw JsonError(path, "expected an array of numbers, found " + describe(v));
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(readNumber(v[i], indexPath(path, i)));
    return out;
}

template <std::size_t N>
static std::array<double, N> readVec(const json& v, const std::string& path) {
    const std::string expected = "expected an array of " + std::to_string(N) + " numbers";
    if (!v.is_array() || v.size() != N) throw JsonError(path, expected + ", found " + describe(v));
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
        if (!v[i].is_number()) throw JsonError(path, expected + "; item " + std::to_string(i) + " is " + describe(v[i]));
        out[i] = readNumber(v[i], indexPath(path, i));
    }
    return out;
}

std::array<double, 2> readVec2(const json& v, const std::string& path) { return readVec<2>(v, path); }
std::array<double, 3> readVec3(const json& v, const std::string& path) { return readVec<3>(v, path); }

std::array<float, 3> readColor(const json& v, const std::string& path) {
    std::array<double, 3> c = readVec<3>(v, path);
    std::array<float, 3> out{};
    for (std::size_t i = 0; i < 3; ++i) {
        if (c[i] < 0.0 || c[i] > 1.0)
            throw JsonError(path, "expected a colour of 3 numbers in [0, 1] (linear RGB); item " + std::to_string(i) +
                                      " is " + formatNumber(c[i]));
        out[i] = static_cast<float>(c[i]);
    }
    return out;
}

}  // namespace hg::garden
