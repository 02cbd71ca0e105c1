// The journal (garden/session/journal.h): records round-trip; a torn or
// damaged tail keeps every record before it and says where the damage is;
// an unknown format version is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "garden/session/journal.h"
#include "garden_test_util.h"

namespace hg::garden {
namespace {

class JournalTest : public test::ScratchDir {};

std::vector<Action> everyKind() {
    StrokeAction s{"column west", StrokeTool::Melt, 0.031, 2.5, {{0.1, 0.2, 0.3}, {0.1000000000000001, -2.5e-9, 7.0}},
                   MirrorPlane{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, 1.0, Falloff::Smooth, {}};
    Perturbation q;
    q.shape = QuadricShape::Torus;
    q.center = {1.0 / 3.0, 0.5, -0.25};
    q.radii = {0.1, 0.03, 0.0};
    q.strength = -2.75;
    Placement moved;
    moved.position = {1.5, 0.0, -2.25};
    moved.yawDegrees = 33.0;
    moved.scale = 1.25;
    ImpactSeries series;
    Impact m;
    m.shape = ImpactShape::Chisel;
    m.tip = {0.25, 1.0 / 7.0, -0.5};
    m.depth = 0.0125;
    series.impacts = {m, m};
    series.rayOrigins = {{0.5, 1.5, 0.25}};
    series.rayDirections = {{0.0, -1.0, 0.0}};
    series.volume = 3e-6;
    return {s, PerturbAction{"dancer", q}, UndoAction{}, RedoAction{}, DiscardAction{"metamorphosis"},
            MorphWeightsAction{{0.2, 0.3, 0.5}, {1.1, 0.9, 1.0}, "metamorphosis"}, MoveAction{"dryad", moved}, ImpactsAction{"knot", series},
            ReplaceAction{"dancer", 3, q},
            MaterialAction{"dryad", Material{"oak", MaterialKind::Wood, {0.5f, 0.3f, 1.0f / 7.0f}, 0.65f, 0.0f}}};
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST_F(JournalTest, RecordsRoundTripExactly) {
    const std::string path = (dir / "j.hgj").string();
    {
        JournalWriter w;
        ASSERT_EQ(w.open(path), "");
        for (const Action& r : everyKind()) ASSERT_EQ(w.append(r), "");
    }
    const JournalRead read = readJournal(path);
    ASSERT_TRUE(read.ok()) << read.error;
    EXPECT_FALSE(read.damaged()) << read.damage;
    const auto expected = everyKind();
    ASSERT_EQ(read.records.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_EQ(actionJson(read.records[i]), actionJson(expected[i])) << i;
    // Doubles come back bit for bit.
    const auto& s = std::get<StrokeAction>(read.records[0]);
    EXPECT_EQ(s.path[1][0], 0.1000000000000001);
    EXPECT_EQ(s.path[1][1], -2.5e-9);
    EXPECT_EQ(std::get<PerturbAction>(read.records[1]).perturbation.center[0], 1.0 / 3.0);
    EXPECT_EQ(std::get<MaterialAction>(read.records.back()).material, std::get<MaterialAction>(expected.back()).material);
    // Appending to an existing journal keeps what is there.
    {
        JournalWriter w;
        ASSERT_EQ(w.open(path), "");
        ASSERT_EQ(w.append(UndoAction{}), "");
    }
    EXPECT_EQ(readJournal(path).records.size(), expected.size() + 1);
}

TEST_F(JournalTest, EveryTruncationKeepsTheRecordsBeforeIt) {
    const std::string path = (dir / "j.hgj").string();
    {
        JournalWriter w;
        ASSERT_EQ(w.open(path), "");
        for (const Action& r : everyKind()) ASSERT_EQ(w.append(r), "");
    }
    const std::string text = slurp(path);
    // Where each record's line starts.
    std::vector<std::size_t> starts;
    for (std::size_t p = text.find('\n') + 1; p < text.size(); p = text.find('\n', p) + 1) starts.push_back(p);
    for (std::size_t cut = starts[0]; cut < text.size(); ++cut) {
        const JournalRead r = parseJournal(text.substr(0, cut), "cut");
        ASSERT_TRUE(r.ok());
        std::size_t whole = 0;
        while (whole < starts.size() && (whole + 1 < starts.size() ? starts[whole + 1] : text.size()) <= cut) ++whole;
        ASSERT_EQ(r.records.size(), whole) << "cut at " << cut;
        if (cut == (whole < starts.size() ? starts[whole] : text.size())) {
            EXPECT_FALSE(r.damaged()) << "cut at a record boundary " << cut;
        } else {
            ASSERT_TRUE(r.damaged()) << "cut at " << cut;
            EXPECT_EQ(r.damagedRecord, whole + 1);
            EXPECT_EQ(r.damagedOffset, starts[whole]);
            EXPECT_EQ(r.goodBytes, starts[whole]);
        }
    }
}

TEST_F(JournalTest, AFlippedBitStopsAtItsRecord) {
    const std::string path = (dir / "j.hgj").string();
    {
        JournalWriter w;
        ASSERT_EQ(w.open(path), "");
        for (const Action& r : everyKind()) ASSERT_EQ(w.append(r), "");
    }
    std::string text = slurp(path);
    std::size_t third = text.find('\n') + 1;
    for (int i = 0; i < 2; ++i) third = text.find('\n', third) + 1;
    text[third + 20] ^= 0x04;
    const JournalRead r = parseJournal(text, "flipped");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.records.size(), 2u);
    EXPECT_EQ(r.damagedRecord, 3u);
    EXPECT_EQ(r.damagedOffset, third);
    EXPECT_NE(r.damage.find("checksum"), std::string::npos) << r.damage;
}

TEST_F(JournalTest, UnknownVersionsAndOtherFilesAreRefused) {
    const JournalRead v = parseJournal("hypergarden-journal 2\n", "future.hgj");
    EXPECT_FALSE(v.ok());
    EXPECT_NE(v.error.find("version '2'"), std::string::npos) << v.error;
    const JournalRead other = parseJournal("{\"garden\": 1}\n", "other.hgj");
    EXPECT_FALSE(other.ok());
    EXPECT_NE(other.error.find("not a Hypergarden journal"), std::string::npos) << other.error;
    // A well-formed line whose record is not one we know.
    const std::string json = R"({"action":"chisel"})";
    char crc[16];
    std::snprintf(crc, sizeof crc, "%08x ", crc32(json));
    const JournalRead bad = parseJournal("hypergarden-journal 1\n" + std::string(crc) + json + "\n", "bad.hgj");
    ASSERT_TRUE(bad.ok());
    EXPECT_TRUE(bad.damaged());
    EXPECT_NE(bad.damage.find("unknown action 'chisel'"), std::string::npos) << bad.damage;
}

}  // namespace
}  // namespace hg::garden
