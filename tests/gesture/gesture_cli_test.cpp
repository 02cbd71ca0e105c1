// `hypergarden gesture`: one line per stroke, the accuracy and confusion
// table where strokes are labelled, JSON with --json, and clear errors that
// say where the input is wrong.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "gesture_shapes.h"
#include "tests/cli_fixture.h"

namespace hg::garden {
namespace {

class GestureCliTest : public ::hg::test::CliTest {
protected:
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return path(name);
    }
    static nlohmann::json stroke(const StrokePoints& p, const char* label) {
        nlohmann::json points = nlohmann::json::array();
        for (const StrokePoint& q : p) points.push_back({q[0], q[1]});
        nlohmann::json s = {{"points", points}};
        if (label) s["label"] = label;
        return s;
    }
    std::string strokes() {
        using namespace test;
        const nlohmann::json doc = {{"strokes",
                                     {stroke(uShape(), "union"), stroke(loopShape(false), "grow"),
                                      stroke(lineShape(), "none"), stroke(zShape(), "sketch")}}};
        return write("strokes.json", doc.dump());
    }
};

TEST_F(GestureCliTest, PrintsEachStrokeTheAccuracyAndTheConfusionTable) {
    const ::hg::test::CommandRun r = ::hg::test::runHypergarden("gesture " + strokes());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("stroke 1: union"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("stroke 2: grow"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("stroke 3: none"), std::string::npos) << r.output;
    // The Z is labelled wrongly on purpose: the table shows it.
    EXPECT_NE(r.output.find("stroke 4: deform"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("WRONG, truth sketch"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("accuracy: 3 of 4 labelled strokes right (75.00%)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("truth \\ answer"), std::string::npos) << r.output;
}

TEST_F(GestureCliTest, JsonHasTheSameAnswers) {
    const ::hg::test::CommandRun r = ::hg::test::runHypergarden("gesture --json " + strokes());
    ASSERT_EQ(r.status, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output);
    ASSERT_EQ(j["strokes"].size(), 4u);
    EXPECT_EQ(j["strokes"][0]["label"], "union");
    EXPECT_EQ(j["strokes"][3]["label"], "deform");
    EXPECT_EQ(j["strokes"][3]["truth"], "sketch");
    EXPECT_EQ(j["summary"]["correct"], 3);
    EXPECT_EQ(j["summary"]["confusion"]["counts"][1][4], 1);  // truth sketch, answered deform
    // A threshold of 1 turns every answer to none.
    const ::hg::test::CommandRun strict = ::hg::test::runHypergarden("gesture --json --threshold 1 " + path("strokes.json"));
    ASSERT_EQ(strict.status, 0) << strict.output;
    // Named: a range-for over parse(...)["strokes"] would outlive the parsed temporary.
    const nlohmann::json strictJson = nlohmann::json::parse(strict.output);
    for (const auto& s : strictJson.at("strokes")) EXPECT_EQ(s["label"], "none");
}

TEST_F(GestureCliTest, TheCommittedHandLikeSetMeetsTheTargets) {
    const ::hg::test::CommandRun r =
        ::hg::test::runHypergarden("gesture --json '" + std::string(HG_SOURCE_DIR) + "/content/gestures/handlike.json'");
    ASSERT_EQ(r.status, 0) << r.output;
    const nlohmann::json s = nlohmann::json::parse(r.output)["summary"];
    EXPECT_GE(s["gesture_accuracy"].get<double>(), 0.95);
    EXPECT_LE(s["false_gesture_rate"].get<double>(), 0.02);
}

TEST_F(GestureCliTest, BadInputSaysWhere) {
    struct Case {
        std::string args, message;
    };
    const Case cases[] = {
        {write("bad.json", "{\"strokes\": [{\"points\": [[1, 2], [3]]}]}"),
         "bad.json: $.strokes[0].points[1]: expected [x, y], found an array of 1 item"},
        {write("syntax.json", "{\"strokes\": [\n  {\"points\": }]}"), "syntax.json: line 2, column 14: invalid JSON"},
        {write("label.json", "{\"strokes\": [{\"points\": [[1, 2]], \"label\": \"circle\"}]}"), "unknown label 'circle'"},
        {path("missing.json"), "missing.json: cannot open the file"},
        {write("ok.json", "{\"strokes\": []}") + " --weights " + path("none.json"), "gesture weights"},
        {write("ok2.json", "{\"strokes\": []}") + " --weights " + write("w.json", "{}"), "$: missing key"},
    };
    for (const Case& c : cases) {
        const ::hg::test::CommandRun r = ::hg::test::runHypergarden("gesture " + c.args);
        EXPECT_EQ(r.status, 1) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find("error: "), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
    }
    EXPECT_NE(::hg::test::runHypergarden("gesture").status, 0);
    EXPECT_NE(::hg::test::runHypergarden("gesture " + path("ok.json") + " --threshold 2").status, 0);
}

}  // namespace
}  // namespace hg::garden
