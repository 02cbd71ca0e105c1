// `hypergarden turntable`: PNG frames of one sculpture turning once, for
// sharing (docs/rendering.md, "Turntable"). The camera orbits the
// sculpture's shown surface, framed to it, from the side the garden's
// visitor starts on; the garden's sun, sky, ground and paths are as the
// window shows them, the other sculptures are not drawn.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "garden/render/render_quality.h"
#include "io/progress.h"

namespace hg::garden {

class GardenSession;
struct Sculpture;

struct TurntableOptions {
    int frames = 36;            // one full turn in this many frames
    int width = 800, height = 800;
    float elevationDeg = 20.0f; // the camera above the sculpture's centre, in degrees
    float distance = 0.0f;      // metres from the centre (0: the whole sculpture framed)
    RenderQuality quality;
};

// A sphere around what is on show of a sculpture (its meshes, world frame).
struct ShownBound {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};
// None when the sculpture shows no surface.
std::optional<ShownBound> shownBound(const Sculpture& sculpture);

struct TurntableCamera {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 eye{0.0f};
};

// The camera of frame `frame`: turned by frame / frames of a full turn
// about the vertical through the bound's centre from `startAzimuth`
// (radians, 0 looking from +z), looking at the centre.
TurntableCamera turntableCamera(const ShownBound& bound, const TurntableOptions& options, float fovY, float startAzimuth,
                                int frame);

// "NAME-0007.png"; a name with characters a file name should not hold
// has them as '_'.
std::string turntableFrameName(const std::string& sculpture, int frame);

// Renders the frames of sculpture `index` of a session into folder `dir`
// (which exists) with a hidden window's GL context: the session is first
// run until it is idle (every chunk meshed at full detail when the session
// was opened without level of detail). "" on success with the paths in
// `written`, else why not (nothing is left half-written: each PNG is
// written whole or not at all). `progress` (may be null) is told the
// share done and asked for a cancel after each settling frame and each
// PNG: cancelled, it stops there and says so, the frames written so far
// (whole) in `written`.
std::string renderTurntable(GardenSession& session, int index, const TurntableOptions& options, const std::string& dir,
                            std::vector<std::string>& written, io::Progress* progress = nullptr);

}  // namespace hg::garden
