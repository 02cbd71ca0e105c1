// Stroke files and weights files: what they hold, and for bad input an
// error that names where (JSON path, or line and column).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "garden/gesture/gesture_json.h"
#include "garden/gesture/stroke_file.h"
#include "gesture_shapes.h"

namespace hg::garden {
namespace {

std::string errorOf(const std::string& text) {
    try {
        readStrokeFile(text);
    } catch (const GestureJsonError& e) {
        return e.what();
    }
    return "";
}

TEST(StrokeFile, ReadsPointsLabelsAndNotes) {
    const std::vector<FileStroke> s = readStrokeFile(
        R"({"about": "two", "strokes": [{"points": [[1, 2], [3.5, -4]], "label": "grow", "note": "n"}, {"points": []}]})");
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].points, (StrokePoints{{1, 2}, {3.5, -4}}));
    EXPECT_EQ(s[0].label, GestureLabel::Grow);
    EXPECT_EQ(s[0].note, "n");
    EXPECT_TRUE(s[1].points.empty());
    EXPECT_FALSE(s[1].label.has_value());
}

TEST(StrokeFile, BadInputSaysWhere) {
    const std::pair<std::string, std::string> cases[] = {
        {"{\"strokes\": [\n  {\"points\": [[1, 2],]}]}", "line 2, column 22: invalid JSON"},
        {"[]", "$: expected an object, found an array of 0 items"},
        {"{}", "$: missing key 'strokes'"},
        {R"({"strokes": {}})", "$.strokes: expected an array of strokes, found an object"},
        {R"({"strokes": [{"points": [[1, 2]]}, {"label": "sketch"}]})", "$.strokes[1]: missing key 'points'"},
        {R"({"strokes": [{"points": [[1, 2], [3, 4, 5]]}]})", "$.strokes[0].points[1]: expected [x, y], found an array of 3 items"},
        {R"({"strokes": [{"points": [[1, "2"]]}]})", "$.strokes[0].points[0][1]: expected a number, found a string"},
        {R"({"strokes": [{"points": [[1, 2]], "label": "unoin"}]})",
         "$.strokes[0].label: unknown label 'unoin'; expected one of none, sketch, union, intersect, deform, shrink, grow"},
        {R"({"strokes": [{"points": [[1, 2]], "lable": "union"}]})", "$.strokes[0].lable: unknown key"},
        {R"({"strokes": [], "extra": 1})", "$.extra: unknown key"},
        {R"({"strokes": [{"points": [[1, 1e999]]}]})", "a number too large"},
    };
    for (const auto& [text, message] : cases) {
        const std::string e = errorOf(text);
        EXPECT_NE(e.find(message), std::string::npos) << text << "\n" << e;
    }
}

TEST(StrokeFile, AMissingFileIsNamed) {
    try {
        readGestureTextFile("/nonexistent/strokes.json");
        FAIL();
    } catch (const GestureJsonError& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/strokes.json: cannot open the file");
    }
}

TEST(WeightsFile, WritesAndReadsBackExactly) {
    const GestureRecognizer r = test::committedRecognizer();
    const std::string text = writeGestureWeights(r, {{"note", "test"}});
    const GestureRecognizer back = readGestureWeights(text);
    EXPECT_EQ(gestureNetworkChecksum(back.network), gestureNetworkChecksum(r.network));
    EXPECT_EQ(back.threshold, r.threshold);
    EXPECT_EQ(writeGestureWeights(back, {{"note", "test"}}), text);
}

TEST(WeightsFile, RefusesWhatItCannotUse) {
    const GestureRecognizer r = test::committedRecognizer();
    const nlohmann::json good = nlohmann::json::parse(writeGestureWeights(r, nlohmann::json::object()));
    auto errorAfter = [&](auto change) {
        nlohmann::json j = good;
        change(j);
        try {
            readGestureWeights(j.dump());
        } catch (const GestureJsonError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(errorAfter([](nlohmann::json& j) { j["network"]["w1"][3] = 0.5; }).find("$.training.checksum: does not match"),
              std::string::npos);
    EXPECT_NE(errorAfter([](nlohmann::json& j) { j["features"]["segments"] = 16; }).find("$.features.segments: is 16 but"),
              std::string::npos);
    EXPECT_NE(errorAfter([](nlohmann::json& j) { j["network"]["b2"].erase(0); }).find("$.network.b2: expected an array of 7 numbers"),
              std::string::npos);
    EXPECT_NE(errorAfter([](nlohmann::json& j) { j["labels"][1] = "v"; }).find("$.labels: expected"), std::string::npos);
    EXPECT_NE(errorAfter([](nlohmann::json& j) { j["threshold"] = 2; }).find("$.threshold: expected a probability"),
              std::string::npos);
    EXPECT_NE(errorAfter([](nlohmann::json& j) { j.erase("network"); }).find("$: missing key 'network'"), std::string::npos);
    try {
        loadGestureWeights("/nonexistent/weights.json");
        FAIL();
    } catch (const GestureJsonError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/weights.json: cannot open"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace hg::garden
