#include "garden/desktop/turntable.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "garden/app/garden_session.h"
#include "garden/desktop/offscreen_garden.h"
#include "garden/render/garden_ground.h"
#include "garden/scene/to_glm.h"

namespace hg::garden {

namespace {

constexpr float kPi = 3.14159265358979f;
// Frames a session may take to mesh everything before the turntable gives up
// (a small garden settles in tens; a large one at full detail in hundreds).
constexpr int kMaxSettleFrames = 20000;
// Room around the framed sphere, so the silhouette does not touch the edge.
constexpr float kFrameMargin = 1.08f;

// The horizontal direction from the sculpture to where the visitor starts
// (radians about +y, 0 towards +z): frame 0 shows the side one walks up to.
float startAzimuth(const GardenSession& session, const glm::vec3& centre) {
    const glm::vec3 d = toGlm(session.garden().start.position) - centre;
    return std::hypot(d.x, d.z) > 1e-4f ? std::atan2(d.x, d.z) : 0.0f;
}

}  // namespace

std::optional<ShownBound> shownBound(const Sculpture& sculpture) {
    if (!sculpture.onShow()) return std::nullopt;
    glm::vec3 lo(1e30f), hi(-1e30f);
    const poly::RemeshQueue& q = *sculpture.queue;
    for (std::size_t c = 0; c < q.count(); ++c) {
        const auto mesh = q.mesh(c);
        if (!mesh) continue;
        for (std::size_t v = 0; v + 2 < mesh->positions.size(); v += 3) {
            const glm::vec3 w(sculpture.modelToWorld() *
                              glm::vec4(mesh->positions[v], mesh->positions[v + 1], mesh->positions[v + 2], 1.0f));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
    }
    if (lo.x > hi.x) return std::nullopt;
    return ShownBound{0.5f * (lo + hi), std::max(0.5f * glm::length(hi - lo), 1e-3f)};
}

TurntableCamera turntableCamera(const ShownBound& bound, const TurntableOptions& options, float fovY, float startAzimuth,
                                int frame) {
    const float aspect = static_cast<float>(options.width) / static_cast<float>(std::max(options.height, 1));
    // The sphere fits the narrower of the two fields of view.
    const float halfFov = 0.5f * std::min(fovY, 2.0f * std::atan(std::tan(0.5f * fovY) * aspect));
    const float distance =
        options.distance > 0.0f ? options.distance : kFrameMargin * bound.radius / std::sin(halfFov);
    const float azimuth = startAzimuth + 2.0f * kPi * static_cast<float>(frame) / static_cast<float>(options.frames);
    const float elevation = options.elevationDeg * kPi / 180.0f;
    TurntableCamera c;
    c.eye = bound.centre + distance * glm::vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                                std::cos(elevation) * std::cos(azimuth));
    c.view = glm::lookAt(c.eye, bound.centre, glm::vec3(0.0f, 1.0f, 0.0f));
    // Near enough for a camera close to a small sculpture, far enough for
    // depth precision; the far plane takes in the garden behind it.
    const float nearPlane = std::clamp(0.02f * distance, 0.005f, 0.05f);
    c.projection = glm::perspective(fovY, aspect, nearPlane, std::max(kGardenFarPlane, 4.0f * distance));
    return c;
}

std::string turntableFrameName(const std::string& sculpture, int frame) {
    std::string name = sculpture;
    for (char& ch : name)
        if (ch == '/' || ch == '\\' || ch == ':' || static_cast<unsigned char>(ch) < 32) ch = '_';
    char number[16];
    std::snprintf(number, sizeof number, "-%04d.png", frame);
    return name + number;
}

std::string renderTurntable(GardenSession& session, int index, const TurntableOptions& options, const std::string& dir,
                            std::vector<std::string>& written, io::Progress* progress) {
    io::ProgressRange shown(progress, 0.0, 1.0);  // a flag to ask even when nobody watches
    std::string why;
    std::unique_ptr<OffscreenGarden> offscreen = OffscreenGarden::create(options.width, options.height, why);
    if (!offscreen) return why;
    offscreen->setQuality(options.quality);
    offscreen->showOnly(index);
    // Meshed and uploaded first (counted as the first tenth of the work).
    int settle = 0;
    for (; settle < kMaxSettleFrames && !session.idle(); ++settle) {
        session.frame(FrameInput{}, *offscreen);
        if (shown.interrupted(settle % 16 == 0 ? 0.1 * (1.0 - 1.0 / (1.0 + settle / 64.0)) : -1.0))
            return io::kCancelled;
    }
    if (!session.idle())
        return "the garden was still meshing after " + std::to_string(kMaxSettleFrames) + " frames (chunks waiting " +
               std::to_string(session.remeshPending()) + ")";
    offscreen->upload(session, 1e9);
    const Sculpture& sculpture = session.sculptures()[static_cast<std::size_t>(index)];
    const std::optional<ShownBound> bound = shownBound(sculpture);
    if (!bound) return "sculpture '" + sculpture.name + "' shows no surface: there is nothing to turn";
    const float fovY = static_cast<float>(session.settings().fovY);
    const float azimuth = startAzimuth(session, bound->centre);
    for (int f = 0; f < options.frames; ++f) {
        const TurntableCamera c = turntableCamera(*bound, options, fovY, azimuth, f);
        offscreen->setCamera(OffscreenGarden::Camera{c.view, c.projection, c.eye});
        offscreen->render(session);
        const std::string path = (std::filesystem::path(dir) / turntableFrameName(sculpture.name, f)).string();
        if (std::string failed = offscreen->screenshot(path); !failed.empty()) return failed;
        written.push_back(path);
        if (shown.interrupted(0.1 + 0.9 * static_cast<double>(f + 1) / options.frames) && f + 1 < options.frames)
            return "cancelled after " + std::to_string(f + 1) + " of " + std::to_string(options.frames) + " frames";
    }
    return "";
}

}  // namespace hg::garden
