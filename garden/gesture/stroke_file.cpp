#include "garden/gesture/stroke_file.h"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "garden/gesture/gesture_json.h"

namespace hg::garden {

using json = nlohmann::json;

namespace {

StrokePoint readPoint(const json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 2) throw GestureJsonError(path, "expected [x, y], found " + describeGestureJson(v));
    return {readGestureNumber(v[0], gestureJsonIndex(path, 0)), readGestureNumber(v[1], gestureJsonIndex(path, 1))};
}

FileStroke readStroke(const json& v, const std::string& path) {
    requireGestureObject(v, path, {"points", "label", "note"});
    FileStroke s;
    auto points = v.find("points");
    if (points == v.end()) throw GestureJsonError(path, "missing key 'points'");
    const std::string pointsPath = path + ".points";
    if (!points->is_array())
        throw GestureJsonError(pointsPath, "expected an array of [x, y] points, found " + describeGestureJson(*points));
    for (std::size_t i = 0; i < points->size(); ++i) s.points.push_back(readPoint((*points)[i], gestureJsonIndex(pointsPath, i)));
    if (auto label = v.find("label"); label != v.end()) {
        if (!label->is_string()) throw GestureJsonError(path + ".label", "expected a string, found " + describeGestureJson(*label));
        s.label = labelFromName(label->get<std::string>());
        if (!s.label)
            throw GestureJsonError(path + ".label",
                                   "unknown label '" + label->get<std::string>() + "'; expected one of " + labelNameList());
    }
    if (auto note = v.find("note"); note != v.end()) {
        if (!note->is_string()) throw GestureJsonError(path + ".note", "expected a string, found " + describeGestureJson(*note));
        s.note = note->get<std::string>();
    }
    return s;
}

}  // namespace

std::vector<FileStroke> readStrokeFile(const std::string& text) {
    const json doc = parseGestureJson(text);
    requireGestureObject(doc, "$", {"strokes", "about"});
    auto strokes = doc.find("strokes");
    if (strokes == doc.end()) throw GestureJsonError("$", "missing key 'strokes'");
    if (!strokes->is_array()) throw GestureJsonError("$.strokes", "expected an array of strokes, found " + describeGestureJson(*strokes));
    std::vector<FileStroke> out;
    out.reserve(strokes->size());
    for (std::size_t i = 0; i < strokes->size(); ++i) out.push_back(readStroke((*strokes)[i], gestureJsonIndex("$.strokes", i)));
    return out;
}

std::string readGestureTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw GestureJsonError(path, "cannot open the file");
    std::stringstream s;
    s << in.rdbuf();
    if (in.bad()) throw GestureJsonError(path, "cannot read the file");
    return s.str();
}

}  // namespace hg::garden
