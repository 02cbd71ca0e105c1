// Garden files: a good file with every section, bad files refused with the
// JSON path and the reason, broken sculpture files shown as missing, and the
// repository's default garden.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <sstream>
#include <nlohmann/json.hpp>

#include "garden/scene/garden_file.h"
#include "garden/scene/json_reader.h"
#include "garden/scene/materials.h"
#include "garden_test_util.h"

namespace hg::garden {
namespace {

using json = nlohmann::json;

const char* kSphereFile = "ball(x[3], a[1]) { ball = a[1] - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2); }\n";

// A valid garden with every section.
json goodGarden() {
    return json::parse(R"({
      "version": 1,
      "name": "test garden",
      "ground": {"height": 0, "size": [20, 30], "material": "lawn"},
      "materials": {
        "lawn": {"color": [0.2, 0.4, 0.1], "roughness": 0.9},
        "bronze": {"color": [0.6, 0.4, 0.2], "roughness": 0.35, "metallic": 1}
      },
      "sculptures": [
        {"name": "one", "file": "hf/ball.hf", "a": [0.25], "resolution": 32,
         "placement": {"position": [0, 0, -3]}, "material": "bronze"},
        {"name": "two", "file": "hf/ball.hf", "body": "ball", "a": [0.16], "resolution": 32,
         "box": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]},
         "placement": {"position": [-2.6, 0, 1.5], "yaw": 120, "scale": 1.5}},
        {"name": "three", "file": "hf/ball.hf", "a": [0.2], "band": 4,
         "placement": {"position": [2.6, 0, 1.5], "yaw": -120},
         "material": {"color": [0.9, 0.9, 0.85]}}
      ],
      "paths": [{"name": "walk", "points": [[0, 10], [0, 4]], "width": 1.5}],
      "morph": {"sources": ["one", "two", "three"], "balance": "computed",
                "result": {"resolution": 40, "material": "bronze"}},
      "lights": [
        {"type": "ambient", "intensity": 0.3},
        {"type": "directional", "direction": [0, -2, 0], "color": [1, 0.95, 0.9]},
        {"type": "point", "position": [0, 3, 0], "range": 8, "intensity": 2}
      ],
      "start": {"position": [0, 1.7, 9], "look_at": [0, 1, 0]}
    })");
}

class GardenFile : public test::ScratchDir {
protected:
    void SetUp() override {
        ScratchDir::SetUp();
        write("hf/ball.hf", kSphereFile);
    }
    GardenLoad loadJson(const json& j) const { return loadGarden(write("garden.json", j.dump(2))); }
};

TEST_F(GardenFile, GoodFileLoadsEverySection) {
    GardenLoad load = loadJson(goodGarden());
    ASSERT_TRUE(load.ok()) << load.error;
    const Garden& g = *load.garden;
    EXPECT_EQ(g.name, "test garden");
    EXPECT_EQ(g.ground.size[1], 30.0);
    EXPECT_FLOAT_EQ(g.ground.material.color[1], 0.4f);
    ASSERT_EQ(g.sculptures.size(), 3u);
    ASSERT_EQ(load.sculptures.size(), 3u);
    EXPECT_EQ(load.missingCount(), 0u);
    for (const auto& s : load.sculptures) EXPECT_TRUE(s.ok()) << s.error;
    // Paths resolve against the garden file's folder.
    EXPECT_EQ(std::filesystem::path(g.sculptures[0].file), (dir / "hf/ball.hf").lexically_normal());
    EXPECT_EQ(g.sculptures[0].fileAsWritten, "hf/ball.hf");
    // Defaults and given values.
    EXPECT_EQ(g.sculptures[0].resolution, 32);
    EXPECT_EQ(g.sculptures[2].resolution, 128);
    EXPECT_EQ(g.sculptures[2].band, 4.0f);
    EXPECT_FALSE(g.sculptures[0].box.has_value());
    ASSERT_TRUE(g.sculptures[1].box.has_value());
    EXPECT_EQ(g.sculptures[1].box->hi[1], 1.0);
    EXPECT_EQ(g.sculptures[1].placement.yawDegrees, 120.0);
    EXPECT_EQ(g.sculptures[1].placement.scale, 1.5);
    EXPECT_EQ(g.sculptures[0].material.name, "bronze");
    EXPECT_FLOAT_EQ(g.sculptures[0].material.metallic, 1.0f);
    EXPECT_EQ(g.sculptures[2].material.name, "");
    EXPECT_FLOAT_EQ(g.sculptures[2].material.color[2], 0.85f);
    EXPECT_EQ(load.sculptures[1].model->body().name, "ball");
    EXPECT_EQ(load.sculptures[1].model->parameters()[0], 0.16);
    // Morph: sources by name, result at the centroid of the triangle.
    ASSERT_EQ(g.morphs.size(), 1u);
    EXPECT_TRUE(load.morphErrors.at(0).empty());
    EXPECT_EQ(g.morphs[0].sourceIndex[2], 2u);
    EXPECT_FALSE(g.morphs[0].balance.has_value());
    EXPECT_NEAR(g.morphs[0].resultPlacement.position[0], 0.0, 1e-12);
    EXPECT_NEAR(g.morphs[0].resultPlacement.position[2], 0.0, 1e-12);
    EXPECT_NEAR(g.morphs[0].selector[1], 0.0, 1e-12);
    EXPECT_EQ(g.morphs[0].resolution, 40);
    EXPECT_EQ(g.morphs[0].resultName, "metamorphosis");
    // Lights: the directional one normalized.
    ASSERT_EQ(g.lights.size(), 3u);
    EXPECT_EQ(g.lights[1].kind, Light::Kind::Directional);
    EXPECT_DOUBLE_EQ(g.lights[1].direction[1], -1.0);
    EXPECT_EQ(g.lights[2].range, 8.0);
    EXPECT_EQ(g.start.position[2], 9.0);
    ASSERT_EQ(g.paths.size(), 1u);
    EXPECT_EQ(g.paths[0].points.size(), 2u);
}

TEST_F(GardenFile, MinimalFileGetsDefaults) {
    GardenLoad load = loadJson(json::parse(R"({"version": 1})"));
    ASSERT_TRUE(load.ok()) << load.error;
    EXPECT_TRUE(load.garden->sculptures.empty());
    EXPECT_TRUE(load.garden->morphs.empty());
    EXPECT_EQ(load.garden->lights.size(), 2u);  // ambient and a sun
}

TEST_F(GardenFile, MaterialsAreNamedBuiltInsOrKindsWithTheirOwnValues) {
    json j = goodGarden();
    j["materials"]["green marble"] = {{"kind", "marble"}, {"color", {0.3, 0.5, 0.35}}};
    j["sculptures"][0]["material"] = "wood";            // built in, not in $.materials
    j["sculptures"][1]["material"] = "green marble";    // a kind with its own colour
    j["sculptures"][2]["material"] = {{"kind", "bronze"}, {"roughness", 0.6}};
    GardenLoad load = loadJson(j);
    ASSERT_TRUE(load.ok()) << load.error;
    const auto& s = load.garden->sculptures;
    EXPECT_EQ(s[0].material, *builtinMaterial("wood"));
    EXPECT_EQ(s[0].material.kind, MaterialKind::Wood);
    EXPECT_EQ(s[1].material.name, "green marble");
    EXPECT_EQ(s[1].material.kind, MaterialKind::Marble);
    EXPECT_FLOAT_EQ(s[1].material.color[1], 0.5f);
    EXPECT_FLOAT_EQ(s[1].material.roughness, builtinMaterial("marble")->roughness);  // the kind's, not given
    EXPECT_EQ(s[2].material.kind, MaterialKind::Bronze);
    EXPECT_FLOAT_EQ(s[2].material.metallic, 1.0f);
    EXPECT_FLOAT_EQ(s[2].material.roughness, 0.6f);
    // $.materials may redefine a built-in's name: the file's own wins.
    EXPECT_EQ(loadJson(goodGarden()).garden->sculptures[0].material.kind, MaterialKind::Plain);
    // Without a material a sculpture is plain, as before materials had kinds.
    EXPECT_EQ(loadJson(json::parse(R"({"version": 1, "sculptures": [{"name": "a", "file": "hf/ball.hf"}]})"))
                  .garden->sculptures[0]
                  .material.kind,
              MaterialKind::Plain);
    // Every kind by name, and the JSON written for one reads back the same.
    for (const Material& m : builtinMaterials()) {
        EXPECT_EQ(materialKindName(m.kind), m.name);
        EXPECT_EQ(readMaterialObject(materialObjectJson(m), "$", m.name), m);
    }
}

struct BadCase {
    const char* what;
    std::function<void(json&)> edit;
    const char* path;
    const char* reason;  // a part of the reason
};

TEST_F(GardenFile, BadFilesAreRefusedWithPathAndReason) {
    const BadCase cases[] = {
        {"position of 2", [](json& j) { j["sculptures"][2]["placement"]["position"] = {1, 2}; },
         "$.sculptures[2].placement.position", "expected an array of 3 numbers"},
        {"position item", [](json& j) { j["sculptures"][0]["placement"]["position"] = {1, "2", 3}; },
         "$.sculptures[0].placement.position", "expected an array of 3 numbers; item 1 is a string"},
        {"typo in a sculpture", [](json& j) { j["sculptures"][0]["placment"] = j["sculptures"][0]["placement"]; },
         "$.sculptures[0].placment", "unknown key (did you mean 'placement'?)"},
        {"typo at the top", [](json& j) { j["sculpture"] = json::array(); },
         "$.sculpture", "unknown key (did you mean 'sculptures'?)"},
        {"unknown key, no hint", [](json& j) { j["morph"]["colour_of_sky"] = 1; },
         "$.morph.colour_of_sky", "unknown key; expected one of: sources balance selector result"},
        {"no version", [](json& j) { j.erase("version"); }, "$", "missing key 'version'"},
        {"future version", [](json& j) { j["version"] = 2; }, "$.version", "unsupported version 2"},
        {"not an object", [](json& j) { j = json::array(); }, "$", "expected an object, found an array of 0 items"},
        {"resolution 0", [](json& j) { j["sculptures"][1]["resolution"] = 0; },
         "$.sculptures[1].resolution", "expected an integer in [4, 16384], found 0"},
        {"fractional resolution", [](json& j) { j["sculptures"][1]["resolution"] = 64.5; },
         "$.sculptures[1].resolution", "expected an integer, found 64.5"},
        {"missing file", [](json& j) { j["sculptures"][1].erase("file"); }, "$.sculptures[1]", "missing key 'file'"},
        {"empty name", [](json& j) { j["sculptures"][1]["name"] = ""; }, "$.sculptures[1].name", "expected a non-empty string"},
        {"same name twice", [](json& j) { j["sculptures"][1]["name"] = "one"; },
         "$.sculptures[1].name", "'one' is already the name of $.sculptures[0]"},
        {"a not numbers", [](json& j) { j["sculptures"][0]["a"] = {1, true}; }, "$.sculptures[0].a[1]",
         "expected a number, found true"},
        {"box inverted", [](json& j) { j["sculptures"][1]["box"]["max"][1] = -1; },
         "$.sculptures[1].box", "min must be below max on every axis (y: 0 >= -1)"},
        {"box as array", [](json& j) { j["sculptures"][1]["box"] = {0, 0, 0, 1, 1, 1}; },
         "$.sculptures[1].box", "expected an object"},
        {"negative scale", [](json& j) { j["sculptures"][1]["placement"]["scale"] = -1; },
         "$.sculptures[1].placement.scale", "expected a positive number"},
        {"unknown material", [](json& j) { j["sculptures"][0]["material"] = "bronz"; },
         "$.sculptures[0].material", "no material named 'bronz' in $.materials or built in (did you mean 'bronze'?)"},
        {"unknown built-in material", [](json& j) { j["sculptures"][1]["material"] = "marbel"; },
         "$.sculptures[1].material", "no material named 'marbel' in $.materials or built in (did you mean 'marble'?)"},
        {"unknown material kind", [](json& j) { j["sculptures"][2]["material"] = {{"kind", "woood"}}; },
         "$.sculptures[2].material.kind",
         "unknown material kind 'woood' (did you mean 'wood'?); expected one of: plain stone marble bronze clay plaster wood"},
        {"material kind not a word", [](json& j) { j["materials"]["bronze"]["kind"] = 3; },
         "$.materials.bronze.kind", "expected a string"},
        {"colour out of range", [](json& j) { j["materials"]["bronze"]["color"] = {0.6, 1.4, 0.2}; },
         "$.materials.bronze.color", "expected a colour of 3 numbers in [0, 1] (linear RGB); item 1 is 1.4"},
        {"unknown source", [](json& j) { j["morph"]["sources"][1] = "tow"; },
         "$.morph.sources[1]", "no sculpture named 'tow' (did you mean 'two'?)"},
        {"two sources", [](json& j) { j["morph"]["sources"] = {"one", "two"}; },
         "$.morph.sources", "expected an array of 3 sculpture names"},
        {"repeated source", [](json& j) { j["morph"]["sources"][2] = "one"; },
         "$.morph.sources[2]", "'one' is already source 0"},
        {"collinear sources", [](json& j) { j["sculptures"][2]["placement"]["position"] = {-5.2, 0, 6}; },
         "$.morph.sources", "stand on one line"},
        {"balance word", [](json& j) { j["morph"]["balance"] = "computd"; },
         "$.morph.balance", "expected \"computed\" or an array of 3 positive numbers"},
        {"balance zero", [](json& j) { j["morph"]["balance"] = {1, 0, 1}; },
         "$.morph.balance[1]", "expected a positive number, found 0"},
        {"result named like a sculpture", [](json& j) { j["morph"]["result"]["name"] = "two"; },
         "$.morph.result.name", "'two' is already the name of a sculpture"},
        {"morph and morphs", [](json& j) { j["morphs"] = json::array({j["morph"]}); },
         "$.morphs", "give $.morph or $.morphs, not both"},
        {"morphs not a list", [](json& j) { j["morphs"] = j["morph"]; j.erase("morph"); },
         "$.morphs", "expected an array of morphs"},
        {"a second morph's unknown source", [](json& j) {
             j["morphs"] = json::array({j["morph"], j["morph"]});
             j["morphs"][1]["sources"][0] = "on";
             j.erase("morph");
         },
         "$.morphs[1].sources[0]", "no sculpture named 'on' (did you mean 'one'?)"},
        {"two results of one name", [](json& j) {
             j["morphs"] = json::array({j["morph"], j["morph"]});
             j.erase("morph");
         },
         "$.morphs[1]", "the result's default name 'metamorphosis' is already the name of the result of morph 0; "
                        "give $.morphs[1].result.name"},
        {"a result named like another's", [](json& j) {
             j["morphs"] = json::array({j["morph"], j["morph"]});
             j["morphs"][0]["result"]["name"] = "blend";
             j["morphs"][1]["result"]["name"] = "blend";
             j.erase("morph");
         },
         "$.morphs[1].result.name", "'blend' is already the name of the result of morph 0"},
        {"light type", [](json& j) { j["lights"][0]["type"] = "spot"; },
         "$.lights[0].type", "unknown light type 'spot'"},
        {"light key of another type", [](json& j) { j["lights"][1]["position"] = {0, 1, 0}; },
         "$.lights[1].position", "unknown key"},
        {"zero direction", [](json& j) { j["lights"][1]["direction"] = {0, 0, 0}; },
         "$.lights[1].direction", "expected a non-zero direction"},
        {"path of one point", [](json& j) { j["paths"][0]["points"] = {{0, 1}}; },
         "$.paths[0].points", "expected an array of at least 2 points"},
        {"look at the eye", [](json& j) { j["start"]["look_at"] = {0, 1.7, 9}; },
         "$.start.look_at", "must differ from the position"},
        {"sculptures not a list", [](json& j) { j["sculptures"] = json::object(); },
         "$.sculptures", "expected an array of sculptures"},
        {"odd key", [](json& j) { j["ground"]["the size"] = 1; }, "$.ground[\"the size\"]", "unknown key"},
    };
    for (const BadCase& c : cases) {
        json j = goodGarden();
        c.edit(j);
        try {
            parseGarden(j.dump(), "garden.json", dir.string());
            ADD_FAILURE() << c.what << ": accepted";
        } catch (const JsonError& e) {
            EXPECT_EQ(e.path(), c.path) << c.what << ": " << e.what();
            EXPECT_NE(e.reason().find(c.reason), std::string::npos) << c.what << ": " << e.what();
        }
    }
}

TEST_F(GardenFile, ErrorNamesTheFileAndThePath) {
    json j = goodGarden();
    j["sculptures"][2]["placement"]["position"] = {1, 2};
    GardenLoad load = loadJson(j);
    ASSERT_FALSE(load.ok());
    EXPECT_EQ(load.errorPath, "$.sculptures[2].placement.position");
    EXPECT_NE(load.error.find("garden.json: $.sculptures[2].placement.position: expected an array of 3 numbers"),
              std::string::npos)
        << load.error;
    EXPECT_TRUE(load.sculptures.empty());
}

TEST_F(GardenFile, DuplicateKeysAndSyntaxErrorsAreRefused) {
    try {
        parseGarden("{\"version\": 1, \"sculptures\": [\n {\"name\": \"a\", \"file\": \"x.hf\", \"file\": \"y.hf\"}]}",
                    "g.json", dir.string());
        ADD_FAILURE() << "accepted a duplicate key";
    } catch (const JsonError& e) {
        EXPECT_EQ(e.path(), "$.sculptures[0]");
        EXPECT_EQ(e.reason(), "duplicate key 'file'");
    }
    try {
        parseGarden("{\n  \"version\": 1,\n  \"name\": \"x\"\n  \"ground\": {}\n}", "g.json", dir.string());
        ADD_FAILURE() << "accepted a missing comma";
    } catch (const JsonError& e) {
        // Where the parser stopped: the end of the unexpected "ground".
        EXPECT_EQ(e.path(), "line 4, column 10") << e.what();
        EXPECT_NE(e.reason().find("invalid JSON"), std::string::npos) << e.what();
    }
    try {  // found by the fuzzer: nlohmann-json throws out_of_range for these
        parseGarden("{\"version\": 1, \"ground\": {\"size\": [1, 8e999]}}", "g.json", dir.string());
        ADD_FAILURE() << "accepted a number past double's range";
    } catch (const JsonError& e) {
        EXPECT_EQ(e.path(), "$.ground.size[1]") << e.what();
        EXPECT_EQ(e.reason(), "a number too large for a double");
    }
    GardenLoad none = loadGarden((dir / "nope.json").string());
    EXPECT_FALSE(none.ok());
    EXPECT_NE(none.error.find("cannot open the garden file"), std::string::npos) << none.error;
}

TEST_F(GardenFile, BrokenSculptureFilesShowAsMissing) {
    write("hf/broken.hf", "ball(x[3], a[1]) {\n  ball = a[1] - (x[1]^2 + ;\n}\n");
    json j = goodGarden();
    j["sculptures"][1]["file"] = "hf/broken.hf";
    j["sculptures"][2]["file"] = "hf/not_there.hf";
    j["sculptures"].push_back(json::parse(R"({"name": "four", "file": "hf/ball.hf", "body": "nope"})"));
    j["sculptures"].push_back(json::parse(R"({"name": "five", "file": "hf/ball.hf", "a": [1, 2]})"));
    GardenLoad load = loadJson(j);
    ASSERT_TRUE(load.ok()) << load.error;
    ASSERT_EQ(load.sculptures.size(), 5u);
    EXPECT_EQ(load.missingCount(), 4u);
    EXPECT_TRUE(load.sculptures[0].ok());
    // A syntax error: file, line, column, the line and a caret.
    EXPECT_FALSE(load.sculptures[1].ok());
    EXPECT_NE(load.sculptures[1].error.find("broken.hf:2:"), std::string::npos) << load.sculptures[1].error;
    EXPECT_NE(load.sculptures[1].error.find("^"), std::string::npos) << load.sculptures[1].error;
    // A missing file says so.
    EXPECT_FALSE(load.sculptures[2].ok());
    EXPECT_NE(load.sculptures[2].error.find("not_there.hf"), std::string::npos) << load.sculptures[2].error;
    // No such body: the bodies the file has.
    EXPECT_NE(load.sculptures[3].error.find("no body named 'nope'; the file defines: ball"), std::string::npos)
        << load.sculptures[3].error;
    // More a[] values than the body declares.
    EXPECT_NE(load.sculptures[4].error.find("2 values given for a[], but body 'ball' declares a[1]"), std::string::npos)
        << load.sculptures[4].error;
    // The morph needs all three sources.
    EXPECT_NE(load.morphErrors.at(0).find("'two' is missing"), std::string::npos) << load.morphErrors.at(0);
}

TEST_F(GardenFile, TheDocumentedExampleLoads) {
    std::ifstream in(std::string(HG_SOURCE_DIR) + "/docs/garden-format.md");
    std::stringstream text;
    text << in.rdbuf();
    const std::string doc = text.str();
    const std::size_t start = doc.find("```json\n");
    ASSERT_NE(start, std::string::npos);
    const std::size_t end = doc.find("```", start + 8);
    GardenLoad load = loadGarden(write("example.json", doc.substr(start + 8, end - start - 8)));
    ASSERT_TRUE(load.ok()) << load.error;
    EXPECT_EQ(load.missingCount(), 0u);
    EXPECT_TRUE(load.morphErrors.at(0).empty());
    EXPECT_EQ(load.garden->sculptures.size(), 3u);
}

TEST(DefaultGarden, LoadsWithEverySculpture) {
    std::string path = std::string(HG_SOURCE_DIR) + "/content/gardens/default.json";
    GardenLoad load = loadGarden(path);
    ASSERT_TRUE(load.ok()) << load.error;
    const Garden& g = *load.garden;
    for (std::size_t i = 0; i < g.sculptures.size(); ++i)
        EXPECT_TRUE(load.sculptures[i].ok()) << g.sculptures[i].name << ": " << load.sculptures[i].error;
    EXPECT_TRUE(load.morphErrors.at(0).empty()) << load.morphErrors.at(0);
    ASSERT_EQ(g.morphs.size(), 1u);
    // The three keys at the corners, the result in the middle.
    const char* keys[] = {"key_dryad.hf", "key_orant.hf", "key_knot.hf"};
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(std::filesystem::path(g.sculptures[g.morphs[0].sourceIndex[i]].file).filename(), keys[i]);
    Vec2 centroid{0, 0};
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec3& p = g.sculptures[g.morphs[0].sourceIndex[i]].placement.position;
        centroid[0] += p[0] / 3;
        centroid[1] += p[2] / 3;
    }
    EXPECT_NEAR(g.morphs[0].resultPlacement.position[0], centroid[0], 1e-9);
    EXPECT_NEAR(g.morphs[0].resultPlacement.position[2], centroid[1], 1e-9);
    // Every piece of our content stands in it.
    for (const char* piece : {"path_stone.hf", "path_column.hf", "path_boulder.hf", "dancer.hf"}) {
        bool found = false;
        for (const auto& s : g.sculptures) found |= std::filesystem::path(s.file).filename() == piece;
        EXPECT_TRUE(found) << piece;
    }
    EXPECT_FALSE(g.paths.empty());
    EXPECT_FALSE(g.lights.empty());
}

}  // namespace
}  // namespace hg::garden
