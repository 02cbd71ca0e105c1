// The committed recognizer on strokes drawn in code and on fresh generated
// ones: every label, whatever the size, position and rotation; lines and
// scribbles are no gesture; the threshold and the shortest stroke.
#include <gtest/gtest.h>

#include "garden/gesture/stroke_generator.h"
#include "gesture_shapes.h"

namespace hg::garden {
namespace {

using namespace test;

struct Case {
    const char* name;
    StrokePoints points;
    GestureLabel label;
};

std::vector<Case> drawnInCode() {
    StrokePoints uFromRight = uShape();
    std::reverse(uFromRight.begin(), uFromRight.end());
    return {{"V", vShape(), GestureLabel::Sketch},
            {"U", uShape(), GestureLabel::Union},
            {"arch", archShape(), GestureLabel::Intersect},
            // Drawn from its right tip a U turns right: an arch upside down.
            {"U from the right", uFromRight, GestureLabel::Intersect},
            {"Z", zShape(), GestureLabel::Deform},
            {"clockwise loop", loopShape(true), GestureLabel::Shrink},
            {"counter-clockwise loop", loopShape(false), GestureLabel::Grow},
            {"line", lineShape(), GestureLabel::None},
            {"crossing out", crossingOut(), GestureLabel::None}};
}

TEST(GestureRecognizer, EveryLabelWhateverTheSizePositionAndRotation) {
    const GestureRecognizer r = committedRecognizer();
    for (const Case& c : drawnInCode())
        for (double angle = 0.0; angle < 2.0 * kPi; angle += kPi / 6.0)
            for (double scale : {0.3, 1.0, 3.0}) {
                const GestureResult g = r.classify(transformed(c.points, angle, scale, 640.0, 360.0));
                EXPECT_EQ(labelName(g.label), std::string(labelName(c.label)))
                    << c.name << " turned " << angle << " scaled " << scale << " (confidence " << g.confidence << ")";
            }
}

TEST(GestureRecognizer, TransformedGeneratedStrokesKeepTheirAnswer) {
    const GestureRecognizer r = committedRecognizer();
    int same = 0, total = 0;
    for (const LabelledStroke& s : generateStrokeSet(10, 20, 4242)) {
        const GestureResult a = r.classify(s.points);
        for (double angle : {1.0, 2.5, 4.0}) {
            const GestureResult b = r.classify(transformed(s.points, angle, 2.0, -50.0, 75.0));
            ++total;
            same += a.best == b.best && std::abs(a.confidence - b.confidence) < 1e-6;
        }
    }
    EXPECT_EQ(same, total);
}

TEST(GestureRecognizer, FreshGeneratedStrokesOfEachLabel) {
    // Another seed than training's and the held-out set's.
    const GestureRecognizer r = committedRecognizer();
    std::array<int, kGestureLabelCount> right{}, count{};
    for (const LabelledStroke& s : generateStrokeSet(60, 60, 777)) {
        ++count[static_cast<std::size_t>(labelIndex(s.label))];
        right[static_cast<std::size_t>(labelIndex(s.label))] += r.classify(s.points).label == s.label;
    }
    for (GestureLabel l : kGestureLabels) {
        const std::size_t k = static_cast<std::size_t>(labelIndex(l));
        EXPECT_GE(right[k], count[k] * 9 / 10) << labelName(l) << ": " << right[k] << " of " << count[k];
    }
}

TEST(GestureRecognizer, LinesAndScribblesAreNoGesture) {
    const GestureRecognizer r = committedRecognizer();
    // Lines in many directions, slightly bent, and back-and-forth scribbles.
    for (double angle = 0.0; angle < 2.0 * kPi; angle += kPi / 8.0) {
        EXPECT_EQ(r.classify(transformed(lineShape(), angle, 1.0, 0.0, 0.0)).label, GestureLabel::None) << angle;
        EXPECT_EQ(r.classify(transformed(crossingOut(), angle, 1.5, 0.0, 0.0)).label, GestureLabel::None) << angle;
        StrokePoints bent = polyline({{0, 0}, {150, 0}, {300, 30}});
        EXPECT_EQ(r.classify(transformed(bent, angle, 1.0, 0.0, 0.0)).label, GestureLabel::None) << angle;
    }
}

TEST(GestureRecognizer, BelowTheThresholdNothingHappens) {
    GestureRecognizer r = committedRecognizer();
    EXPECT_GT(r.threshold, 0.5);
    const GestureResult sure = r.classify(uShape());
    EXPECT_EQ(sure.label, GestureLabel::Union);
    EXPECT_GE(sure.confidence, r.threshold);
    double sum = 0.0;
    for (double p : sure.probabilities) sum += p;
    EXPECT_NEAR(sum, 1.0, 1e-9);
    // Raise the threshold past the confidence: the same stroke is none,
    // though the network's best guess stays.
    r.threshold = std::nextafter(sure.confidence, 2.0);
    const GestureResult unsure = r.classify(uShape());
    EXPECT_EQ(unsure.label, GestureLabel::None);
    EXPECT_EQ(unsure.best, GestureLabel::Union);
    EXPECT_EQ(unsure.confidence, sure.confidence);
    // A threshold of zero takes the best guess whatever it is.
    r.threshold = 0.0;
    for (const LabelledStroke& s : generateStrokeSet(5, 5, 31)) {
        const GestureResult g = r.classify(s.points);
        EXPECT_EQ(g.label, g.best);
    }
}

TEST(GestureRecognizer, AClickOrATinyStrokeIsNoGesture) {
    const GestureRecognizer r = committedRecognizer();
    for (const StrokePoints& p : {StrokePoints{}, StrokePoints{{10, 10}}, StrokePoints{{10, 10}, {10, 10}},
                                  transformed(loopShape(true), 0.0, 0.01, 100.0, 100.0)}) {  // 7.5 px round
        const GestureResult g = r.classify(p);
        EXPECT_EQ(g.label, GestureLabel::None);
        EXPECT_TRUE(g.tooShort);
    }
    // Just long enough: a small loop is recognized.
    EXPECT_EQ(r.classify(transformed(loopShape(true), 0.0, 0.1, 100.0, 100.0)).label, GestureLabel::Shrink);
}

}  // namespace
}  // namespace hg::garden
