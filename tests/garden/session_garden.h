// A small garden for the session and replay tests: three balls of different
// sizes at the morph triangle's corners (4 m apart), the result in the
// middle, one sculpture whose file is missing, all at 32^3, so a session
// opens in a fraction of a second.
#pragma once

#include <memory>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "garden/app/garden_session.h"
#include "garden_test_util.h"

namespace hg::garden::test {

// Writes ball.hf and garden.json into `dir`; returns the garden's path.
inline std::string writeSmallGarden(const std::filesystem::path& dir, nlohmann::json patch = nlohmann::json::object()) {
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "ball.hf") << "ball(x[3], a[1]) { ball = a[1] - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2); }\n";
    nlohmann::json j = nlohmann::json::parse(R"({
      "version": 1,
      "name": "small",
      "materials": {"red": {"color": [0.9, 0.1, 0.1], "roughness": 0.6}},
      "sculptures": [
        {"name": "a", "file": "ball.hf", "a": [0.25], "resolution": 32, "material": "red",
         "box": {"min": [-0.6, -0.1, -0.6], "max": [0.6, 1.1, 0.6]}, "placement": {"position": [0, 0, -2.3094]}},
        {"name": "b", "file": "ball.hf", "a": [0.16], "resolution": 32, "material": "red",
         "box": {"min": [-0.6, -0.1, -0.6], "max": [0.6, 1.1, 0.6]}, "placement": {"position": [-2, 0, 1.1547]}},
        {"name": "c", "file": "ball.hf", "a": [0.36], "resolution": 32, "material": "red",
         "box": {"min": [-0.6, -0.1, -0.6], "max": [0.6, 1.1, 0.6]}, "placement": {"position": [2, 0, 1.1547]}},
        {"name": "lost", "file": "nowhere.hf", "placement": {"position": [6, 0, 6]}}
      ],
      "morph": {"sources": ["a", "b", "c"], "result": {"resolution": 32, "material": "red"}},
      "start": {"position": [0, 1.7, 8], "look_at": [0, 0.5, 0]}
    })");
    j.merge_patch(patch);
    std::ofstream(dir / "garden.json") << j.dump(2);
    return (dir / "garden.json").string();
}

class SmallGarden : public ScratchDir {
protected:
    std::string writeGarden(nlohmann::json patch = nlohmann::json::object()) { return writeSmallGarden(dir, patch); }
};

// A session on the small garden that settles in a few frames: 16^3 chunks,
// two levels, a 32^3 blend over a dozen frames.
inline SessionSettings smallSessionSettings() {
    SessionSettings s;
    s.morphSamplesPerFrame = 2000;
    s.remeshChunksPerFrame = 3;
    s.chunkSize = 16;
    s.maxLevel = 1;
    s.viewportHeight = 200;
    return s;
}

// A session's finished actions, kept in a list (a journal in memory).
struct ActionList : JournalSink {
    std::vector<Action> actions;
    void append(const Action& a) override { actions.push_back(a); }
    SaveStatus saveStatus() const override { return {}; }
    bool retrySave() override { return true; }
};

// The small garden open in a session; `c` is ball c, of radius 0.6 about
// (2, 0.5, 1.1547), its pivot (2, 0, 1.1547).
class SmallGardenSession : public SmallGarden {
protected:
    void SetUp() override {
        SmallGarden::SetUp();
        session = std::make_unique<GardenSession>(loadGarden(writeGarden()), smallSessionSettings());
        c = session->findSculpture("c");
    }
    std::unique_ptr<GardenSession> session;
    int c = -1;
};

// The session as the desktop tests see it: flying 3 m in front of ball c
// at its centre's height, looking along -z, through a 1280 x 720 window.
class FlyingBeforeBallC : public SmallGardenSession {
protected:
    void SetUp() override {
        SmallGardenSession::SetUp();
        session->navigator().setMode(NavigationMode::Fly);
        session->navigator().setPose({2.0f, 0.5f, 4.1547f}, 0.0f, 0.0f);
        projection = glm::perspective(static_cast<float>(session->settings().fovY), kViewport.x / kViewport.y, 0.05f, 500.0f);
    }
    static constexpr glm::vec2 kViewport{1280.0f, 720.0f};
    static constexpr glm::vec2 kCentre{640.0f, 360.0f};
    glm::mat4 projection{1.0f};
};

}  // namespace hg::garden::test
