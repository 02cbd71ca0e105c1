// The small garden (tests/garden/session_garden.h) seen from the origin
// looking along -z, so the mock runtime's stage is the world, with the mock
// runtime selected and its read-back folder in the test's scratch folder.
#pragma once

#include <fstream>

#include <nlohmann/json.hpp>

#include "../garden/session_garden.h"
#include "mock_xr_fixture.h"

namespace hg::xr::test {

class XrGarden : public garden::test::SmallGarden {
protected:
    void SetUp() override {
        garden::test::SmallGarden::SetUp();
        HG_REQUIRE_DISPLAY();
        useMockRuntime();
        ::setenv("HG_MOCK_XR_READBACK", (dir / "readback").c_str(), 1);
        // The viewer at the origin looking along -z: the stage is the world.
        // No morph, so nothing depends on how far a time-budgeted blend got.
        gardenFile = writeGarden(nlohmann::json::parse(
            R"({"start": {"position": [0, 1.7, 0], "look_at": [0, 1.7, -1]}, "morph": null})"));
    }
    std::string script(const std::string& steps) {
        const std::string path = (dir / "carve.json").string();
        std::ofstream(path) << R"({"garden": "garden.json", "steps": )" << steps << "}";
        return path;
    }
    nlohmann::json readback() {
        std::ifstream in(dir / "readback" / "frames.json");
        return nlohmann::json::parse(in);
    }
    std::string gardenFile;
};

}  // namespace hg::xr::test
