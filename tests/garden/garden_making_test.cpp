// Gardens made from a HyperFun file and sculptures added to garden files
// (garden/scene/garden_making.h, `hypergarden FILE.hf`, `hypergarden garden
// add`): the model sized and stood on the ground, the result read back as a
// garden, refusals with the file's messages and the garden file untouched.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "garden/scene/garden_file.h"
#include "garden/scene/garden_making.h"
#include "garden_test_util.h"

namespace hg::garden {
namespace {

class GardenMakingTest : public test::ScratchDir {
protected:
    // A ball of radius 10 model units about (5, 10, 0): its box is about 20 units wide.
    std::string writeBall(const std::string& name = "ball.hf") {
        return write(name, "my_model(x[3], a[1]) {\n  my_model = 100 - ((x[1]-5)^2 + (x[2]-10)^2 + x[3]^2);\n}\n");
    }
    static std::string read(const std::string& path) {
        std::ifstream in(path);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
};

TEST_F(GardenMakingTest, OneModelBecomesAGardenWithItStandingOnTheGround) {
    ModelToPlace m;
    m.file = writeBall();
    std::string error;
    const std::string text = gardenOfOneModel(m, error);
    ASSERT_EQ(error, "");
    const std::string path = write("garden.json", text);
    const GardenLoad load = loadGarden(path);
    ASSERT_TRUE(load.ok()) << load.error;
    ASSERT_EQ(load.garden->sculptures.size(), 1u);
    ASSERT_TRUE(load.sculptures[0].ok()) << load.sculptures[0].error;
    const SculptureSpec& s = load.garden->sculptures[0];
    EXPECT_EQ(s.name, "ball");
    // About 1.5 m across, centred over the origin, its lowest point (y = 0
    // in the model, give or take the box's margin) on the ground.
    const double across = 20.0 * s.placement.scale;
    EXPECT_GT(across, 1.2);
    EXPECT_LE(across, 1.5);
    EXPECT_NEAR(s.placement.position[0] + 5.0 * s.placement.scale, 0.0, 0.05);
    EXPECT_NEAR(s.placement.position[1], 0.0, 0.1);
    // The visitor looks at it.
    EXPECT_GT(load.garden->start.position[2], 1.5);
}

TEST_F(GardenMakingTest, AModelIsAddedBesideTheSculpturesAndTheFileStillReads) {
    ModelToPlace m;
    m.file = writeBall();
    std::string error;
    const std::string garden = write("g/garden.json", gardenOfOneModel(m, error));
    ASSERT_EQ(error, "");
    m.file = writeBall("models/pebble.hf");
    m.size = 0.5;
    m.resolution = 64;
    const std::string text = gardenWithModel(read(garden), garden, m, error);
    ASSERT_EQ(error, "");
    const std::string written = write("g/garden.json", text);
    const GardenLoad load = loadGarden(written);
    ASSERT_TRUE(load.ok()) << load.error;
    ASSERT_EQ(load.garden->sculptures.size(), 2u);
    const SculptureSpec& p = load.garden->sculptures[1];
    EXPECT_EQ(p.name, "pebble");
    EXPECT_EQ(p.fileAsWritten, "../models/pebble.hf");  // relative to the garden's folder
    EXPECT_EQ(p.resolution, 64);
    EXPECT_TRUE(load.sculptures[1].ok());
    EXPECT_NEAR(20.0 * p.placement.scale, 0.49, 0.06);
    EXPECT_GT(p.placement.position[0] + 5.0 * p.placement.scale, 2.5);  // beside the first

    // The same name again, a broken file and a broken garden are refused.
    EXPECT_EQ(gardenWithModel(read(written), written, m, error), "");
    EXPECT_NE(error.find("already has a sculpture named 'pebble'"), std::string::npos) << error;
    m.name = "other";
    m.file = write("broken.hf", "my_model(x[3], a[1]) {\n  my_model = 1 - ;\n}\n");
    EXPECT_EQ(gardenWithModel(read(written), written, m, error), "");
    EXPECT_NE(error.find("broken.hf:2:"), std::string::npos) << error;
    m.file = writeBall();
    EXPECT_EQ(gardenWithModel("{\"version\": 1, \"sculptures\": 3}", written, m, error), "");
    EXPECT_NE(error.find("sculptures"), std::string::npos) << error;
}

#ifdef HG_HYPERGARDEN_EXE
TEST_F(GardenMakingTest, TheCommandLineAddsAndSuggests) {
    ModelToPlace m;
    m.file = writeBall();
    std::string error;
    const std::string garden = write("garden.json", gardenOfOneModel(m, error));
    const std::string before = read(garden);
    test::ShellRun r = test::shell("\"$HG\" garden add '" + garden + "' '" + m.file + "' --name twin --size 1");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("added 'twin'"), std::string::npos) << r.output;
    EXPECT_EQ(nlohmann::json::parse(read(garden))["sculptures"].size(), 2u);
    r = test::shell("\"$HG\" garden add '" + garden + "' '" + m.file + "' --name twin");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("already has a sculpture named 'twin'"), std::string::npos) << r.output;
    // A mistyped command gets a suggestion, not "argument not expected".
    r = test::shell("\"$HG\" chek '" + m.file + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("did you mean 'check'?"), std::string::npos) << r.output;
    // So does a mistyped option, of the program or of a command.
    r = test::shell("\"$HG\" --sesion '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("unknown option '--sesion' (did you mean '--session'?)"), std::string::npos) << r.output;
    r = test::shell("\"$HG\" garden add '" + garden + "' '" + m.file + "' --nmae x");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("did you mean '--name'?"), std::string::npos) << r.output;
    EXPECT_NE(before, read(garden));
}
#endif

}  // namespace
}  // namespace hg::garden
