// Tool intents (garden/hands/tool_intents.h) applied by the session's one
// function (GardenSession::applyToolIntents, garden/app/tool_intents.cpp),
// whatever the device made them. What is tested:
//  * a tool choice, a reverse toggle and the mirror intents (toggle, on,
//    off) change the tool and the selected sculpture's mirror plane;
//  * size and strength factors step the tool in hand within the one set of
//    bounds (garden/sculpt/tool_settings.h), the perturbation's radii
//    together (their ratio kept); a NaN, zero or negative factor does
//    nothing;
//  * a 3 m stroke radius (the desktop's bound is 5 m) stays 3 m under a
//    small size step, as the headset's stick makes (it used to be clamped to
//    1 m there);
//  * the selection's scale: a gesture (factors, or `held` frames between
//    them) is one live move, journalled and undone as one; a frame with
//    neither ends it; two gestures are two undo steps; with the move tool
//    the size factor scales the selection; a pulled trigger ends it;
//  * a replay script's step "intents" (docs/replay-format.md): choices and
//    toggles at the step's first frame, factors spread over its frames (the
//    whole step multiplies by them), a scale over a step one undo step; bad
//    intents refused at their JSON path.
#include <gtest/gtest.h>

#include <cmath>

#include "garden/app/sculpture_gizmos.h"
#include "garden/app/tool_intents.h"
#include "garden/replay/replay_runner.h"
#include "garden/replay/replay_script.h"
#include "garden/scene/json_reader.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

using Kind = ToolSettings::Kind;

class ToolIntentsTest : public test::SmallGardenSession {
protected:
    void frame(const ToolIntents& intents, float trigger = 0.0f) {
        Hands h;
        h.tool.tracked = true;
        h.tool.trigger = trigger;
        // Aimed at the sky: a trigger there acts on no sculpture.
        h.tool.aim.position = glm::vec3(0.0f, 50.0f, 0.0f);
        h.tool.aim.orientation = glm::quatLookAt(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
        h.intents = intents;
        session->frame(FrameInput(h, 1.0 / 90.0));
    }
    ToolIntents pick(ToolChoice c) {
        ToolIntents i;
        i.tool = c;
        return i;
    }
    ToolIntents sized(double f) {
        ToolIntents i;
        i.size = f;
        return i;
    }
    ToolIntents scaled(double f, bool held = false) {
        ToolIntents i;
        i.selectionScale = f;
        i.held = held;
        return i;
    }
    Sculpture& ball() { return session->sculptures()[static_cast<std::size_t>(c)]; }
};

TEST_F(ToolIntentsTest, ChoiceReverseAndMirror) {
    ToolSettings& t = session->tool();
    const ToolChoice choices[] = {ToolChoice::None, ToolChoice::Carve,   ToolChoice::Add, ToolChoice::Melt,
                                  ToolChoice::Perturb, ToolChoice::Impacts, ToolChoice::Move};
    const Kind kinds[] = {Kind::None, Kind::Carve, Kind::Add, Kind::Melt, Kind::Perturb, Kind::Impacts, Kind::Move};
    for (std::size_t i = 0; i < std::size(choices); ++i) {
        frame(pick(choices[i]));
        EXPECT_EQ(t.kind, kinds[i]);
        EXPECT_EQ(toolChoiceOf(kinds[i]), choices[i]);
        EXPECT_EQ(toolKindOf(choices[i]), kinds[i]);
        frame({});
        EXPECT_EQ(t.kind, kinds[i]) << "no choice: the tool stays";
    }
    ToolIntents reverse;
    reverse.reverse = true;
    frame(reverse);
    EXPECT_TRUE(t.reverse);
    frame({});
    EXPECT_TRUE(t.reverse) << "a toggle, once";
    frame(reverse);
    EXPECT_FALSE(t.reverse);

    ToolIntents mirror;
    mirror.mirror = MirrorIntent::Toggle;
    frame(mirror);
    for (const Sculpture& s : session->sculptures()) EXPECT_FALSE(s.mirror) << "nothing selected";
    session->select(c);
    frame(mirror);
    ASSERT_TRUE(ball().mirror);
    EXPECT_EQ(ball().mirror->point, centralMirror(ball()).point);
    frame(mirror);
    EXPECT_FALSE(ball().mirror);
    mirror.mirror = MirrorIntent::On;
    frame(mirror);
    frame(mirror);
    EXPECT_TRUE(ball().mirror) << "on stays on";
    mirror.mirror = MirrorIntent::Off;
    frame(mirror);
    frame(mirror);
    EXPECT_FALSE(ball().mirror);
}

TEST_F(ToolIntentsTest, SizeAndStrengthStepTheToolInHandWithinTheBounds) {
    ToolSettings& t = session->tool();
    frame(pick(ToolChoice::Carve));
    const double r = t.radius;
    frame(sized(2.0));
    EXPECT_DOUBLE_EQ(t.radius, 2.0 * r);
    for (int i = 0; i < 100; ++i) frame(sized(2.0));
    EXPECT_EQ(t.radius, kMaxToolSize);
    for (int i = 0; i < 100; ++i) frame(sized(0.5));
    EXPECT_EQ(t.radius, kMinToolSize);
    for (double bad : {std::nan(""), 0.0, -2.0, HUGE_VAL}) {
        frame(sized(bad));
        EXPECT_EQ(t.radius, kMinToolSize) << bad;
    }

    // The perturbation: its radii together, their ratio kept; its strength
    // with its sign.
    frame(pick(ToolChoice::Perturb));
    t.radii = {0.2, 0.1, 0.05};
    t.strength = -3.0;
    frame(sized(1.5));
    EXPECT_EQ(t.radii, (std::array<double, 3>{0.2, 0.1, 0.05}));
    EXPECT_DOUBLE_EQ(t.perturbRadii()[0], 0.3);
    EXPECT_DOUBLE_EQ(t.perturbRadii()[0] / t.perturbRadii()[2], 4.0);
    for (int i = 0; i < 100; ++i) frame(sized(2.0));
    EXPECT_DOUBLE_EQ(t.perturbRadii()[0], std::min(kMaxToolSize, 0.2 * kMaxPerturbScale));
    EXPECT_DOUBLE_EQ(t.perturbRadii()[0] / t.perturbRadii()[2], 4.0);
    ToolIntents stronger;
    stronger.strength = 2.0;
    frame(stronger);
    EXPECT_EQ(t.strength, -6.0);
    for (int i = 0; i < 100; ++i) frame(stronger);
    EXPECT_EQ(t.strength, -kMaxPerturbStrength);
    EXPECT_EQ(t.radius, kMinToolSize) << "another tool's size stays";

    frame(pick(ToolChoice::Impacts));
    for (int i = 0; i < 100; ++i) frame(sized(2.0));
    EXPECT_EQ(t.impactSize, kMaxImpactSize);
    for (int i = 0; i < 100; ++i) frame(stronger);
    EXPECT_EQ(t.compactionCm3, kMaxCompactionCm3);
}

// Issue 21: the desktop's keys took a radius to 5 m while the headset's
// stick clamped every size to 1 m, so a 3 m radius became 1 m at the first
// nudge of the stick. Both now step within the same bounds.
TEST_F(ToolIntentsTest, AThreeMetreRadiusStaysAtTheFirstNudge) {
    ToolSettings& t = session->tool();
    frame(pick(ToolChoice::Carve));
    t.radius = 3.0;
    const double nudge = std::exp2(0.1 / 90.0);  // the stick a little up, one frame
    frame(sized(nudge));
    EXPECT_DOUBLE_EQ(t.radius, 3.0 * nudge);
    frame(sized(1.0 / nudge));
    EXPECT_DOUBLE_EQ(t.radius, 3.0);
}

TEST_F(ToolIntentsTest, OneScaleGestureIsOneUndoStep) {
    test::ActionList journal;
    session->setJournal(&journal);
    session->select(c);
    const double start = ball().placement.scale;
    // Three steps with held frames between them (a burst of wheel notches,
    // or a stick held out): one live move, nothing journalled yet.
    frame(scaled(1.25, true));
    EXPECT_DOUBLE_EQ(ball().placement.scale, start * 1.25);
    frame(scaled(1.0, true));
    frame(scaled(1.25, true));
    frame(scaled(1.0, true));
    frame(scaled(1.25, true));
    EXPECT_DOUBLE_EQ(ball().placement.scale, start * std::pow(1.25, 3));
    EXPECT_TRUE(session->movingLive());
    EXPECT_TRUE(journal.actions.empty());
    // The gesture ends: one move, journalled.
    frame({});
    EXPECT_FALSE(session->movingLive());
    ASSERT_EQ(journal.actions.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<MoveAction>(journal.actions[0]));
    // A second gesture: its own step.
    frame(scaled(0.5));
    frame(scaled(0.5));
    frame({});
    EXPECT_EQ(journal.actions.size(), 2u);
    EXPECT_DOUBLE_EQ(ball().placement.scale, start * std::pow(1.25, 3) / 4.0);
    ASSERT_TRUE(session->undo());
    EXPECT_DOUBLE_EQ(ball().placement.scale, start * std::pow(1.25, 3));
    ASSERT_TRUE(session->undo());
    EXPECT_DOUBLE_EQ(ball().placement.scale, start) << "three steps, one undo";
    EXPECT_FALSE(session->undo());
    session->setJournal(nullptr);
}

TEST_F(ToolIntentsTest, TheMoveToolsSizeScalesTheSelection) {
    ToolSettings& t = session->tool();
    frame(pick(ToolChoice::Move));
    const double radius = t.radius, start = ball().placement.scale;
    frame(sized(2.0));
    EXPECT_EQ(ball().placement.scale, start) << "nothing selected: nothing scaled";
    session->select(c);
    frame(sized(2.0));
    frame(sized(2.0));
    EXPECT_DOUBLE_EQ(ball().placement.scale, 4.0 * start);
    EXPECT_EQ(t.radius, radius) << "the move tool has no size of its own";
    frame({});
    // A pulled trigger is the tools': the scaling ends there, and the
    // scale asked for meanwhile does nothing.
    frame(sized(2.0));
    frame(sized(2.0), 1.0f);
    EXPECT_FALSE(session->movingLive());
    EXPECT_DOUBLE_EQ(ball().placement.scale, 8.0 * start);
    frame({});
    ASSERT_TRUE(session->undo());
    EXPECT_DOUBLE_EQ(ball().placement.scale, 4.0 * start);
    ASSERT_TRUE(session->undo());
    EXPECT_DOUBLE_EQ(ball().placement.scale, start);
    // Scales stay in the sculptures' bounds.
    session->select(c);  // the pull on nothing let the selection go
    for (int i = 0; i < 40; ++i) frame(scaled(10.0));
    EXPECT_EQ(ball().placement.scale, kMaxSculptureScale);
    frame({});
}

TEST_F(ToolIntentsTest, ReplayScriptsDriveTheIntents) {
    const std::string garden = writeGarden();
    const ReplayScript script = parseReplayScript(R"({
      "garden": ")" + garden + R"(",
      "steps": [
        {"intents": {"tool": "perturb", "size": 2, "strength": 0.5, "reverse": true}, "frames": 10},
        {"commands": [{"select": "c"}], "intents": {"mirror": "on"}},
        {"intents": {"tool": "move", "selection_scale": 1.5}, "frames": 30},
        {"frames": 2},
        {"intents": {"size": 0.5}, "frames": 5},
        {"frames": 2}
      ]})", "intents.json", "");
    const Hands first = stepHands(script.steps[0], 0), later = stepHands(script.steps[0], 9);
    EXPECT_EQ(first.intents.tool, ToolChoice::Perturb);
    EXPECT_TRUE(first.intents.reverse);
    EXPECT_FALSE(later.intents.tool);
    EXPECT_FALSE(later.intents.reverse);
    EXPECT_DOUBLE_EQ(later.intents.size, std::pow(2.0, 0.1));

    test::ActionList journal;
    GardenSession s(loadGarden(garden), test::smallSessionSettings());
    s.setJournal(&journal);
    const int ball = s.findSculpture("c");
    const double start = s.sculptures()[static_cast<std::size_t>(ball)].placement.scale;
    const ReplayResult r = runReplay(script, s, nullptr, {});
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(s.tool().kind, Kind::Move);
    EXPECT_FALSE(s.tool().reverse) << "the move tool's own reverse";
    EXPECT_TRUE(s.tool().kept[static_cast<std::size_t>(Kind::Perturb)].reverse)
        << "perturb's, toggled once, not every frame, kept while the move tool is in hand";
    EXPECT_NEAR(s.tool().perturbScale, 2.0, 1e-12);
    EXPECT_NEAR(s.tool().strength, 1.0, 1e-12);
    EXPECT_TRUE(s.sculptures()[static_cast<std::size_t>(ball)].mirror);
    EXPECT_NEAR(s.sculptures()[static_cast<std::size_t>(ball)].placement.scale, start * 0.75, 1e-12);
    std::size_t moves = 0;
    for (const Action& a : journal.actions) moves += std::holds_alternative<MoveAction>(a) ? 1 : 0;
    EXPECT_EQ(moves, 2u) << "one move a step";
    s.setJournal(nullptr);

    for (const auto& [bad, where] : {std::pair{R"({"tool": "chisel"})", "$.steps[0].intents.tool"},
                                     std::pair{R"({"size": 0})", "$.steps[0].intents.size"},
                                     std::pair{R"({"mirror": "flip"})", "$.steps[0].intents.mirror"},
                                     std::pair{R"({"sizes": 2})", "$.steps[0].intents"}}) {
        try {
            parseReplayScript(std::string(R"({"garden": "g.json", "steps": [{"intents": )") + bad + "}]}", "bad.json", "");
            ADD_FAILURE() << bad;
        } catch (const JsonError& e) {
            EXPECT_EQ(e.path().rfind(where, 0), 0u) << e.path() << " for " << bad;
        }
    }
}

}  // namespace
}  // namespace hg::garden
