// `hypergarden replay`: plays a scripted session (docs/replay-format.md),
// headless or offscreen with screenshots, and writes per-frame statistics.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "garden/app/garden_session.h"
#include "cli/commands.h"
#include "garden/desktop/offscreen_garden.h"
#include "garden/export/export_file.h"
#include "garden/export/part_export.h"
#include "garden/render/render_quality.h"
#include "garden/replay/replay_runner.h"
#include "garden/scene/json_reader.h"
#include "garden/session/open_session.h"
#include "io/checked_write.h"

namespace hg::garden::cli {

int runReplay(const ReplayCommandOptions& options) {
    ReplayScript script;
    try {
        script = loadReplayScript(options.script);
    } catch (const JsonError& e) {
        std::cerr << "error: " << options.script << ": " << e.what() << "\n";
        return 2;
    }
    if (!options.statsPath.empty()) {
        const std::string why = io::checkWritable(options.statsPath);
        if (!why.empty()) {
            std::cerr << "error: --stats: " << why << "\n";
            return 2;
        }
    }
    SessionSettings settings;
    settings.scheduler.budgetMs = script.budgetMs;
    settings.morphSamplesPerFrame = options.morphSamples;
    settings.remeshChunksPerFrame = options.remeshChunks;
    settings.lod = !options.noLod;
    settings.sculptureResolution = options.resolution;
    settings.morphResolution = options.resolution;
    int width = script.viewport[0], height = script.viewport[1];
    if (!options.headless && options.width > 0) {
        width = options.width;
        height = options.height;
    }
    settings.viewportHeight = height;
    // The garden, or a session folder made from it (its journal replayed,
    // the script's actions journalled).
    std::optional<GardenLoad> load;
    if (options.session.empty()) {
        load = loadGarden(script.garden);
        if (!load->ok()) {
            std::cerr << "error: " << load->error << "\n";
            return 2;
        }
    }
    OpenedSession opened =
        openLoadedOrSession(std::move(load), {options.session, script.garden, true, "hypergarden replay"}, settings);
    if (!opened.error.empty()) {
        std::cerr << "error: " << opened.error << "\n";
        return opened.exitStatus;
    }
    for (const std::string& m : openedMessages(opened)) std::cerr << m << "\n";
    reportSaveChangesOnStderr(opened);
    GardenSession& session = *opened.session;

    std::unique_ptr<OffscreenGarden> offscreen;
    if (!options.headless) {
        std::string why;
        offscreen = OffscreenGarden::create(width, height, why);
        if (!offscreen) {
            std::cerr << "error: " << why << "\n";
            return 1;
        }
        if (options.quality == "auto")
            offscreen->setAutoQuality(script.budgetMs);
        else
            offscreen->setQuality(qualityOf(parseQualityPreset(options.quality).value_or(QualityPreset::High)));
        offscreen->setImpostorDistance(options.impostorDistance);
    }
    ReplayOptions ro;
    ro.screenshotEvery = options.screenshotEvery;
    ro.screenshotDir = options.screenshotDir;
    // {"export": ...} writes as the desktop's Export panel does.
    ro.exporter = [](const GardenSession& s, int index, const std::string& path, int resolution, std::string& summary) {
        ExportFileOptions eo;
        eo.resolution = resolution;
        ExportFileReport report;
        const std::string why = exportSculptureFile(s, index, path, eo, report);
        summary = report.summary + (report.warning.empty() ? "" : " (" + report.warning + ")");
        return why;
    };
    ro.extractor = extractPart;  // {"extract": ...}
    if (!std::filesystem::exists(ro.screenshotDir)) std::filesystem::create_directories(ro.screenshotDir);
    ReplayResult result = hg::garden::runReplay(script, session, offscreen.get(), ro);
    for (const std::string& n : result.notes) std::cerr << "note: " << n << "\n";
    if (offscreen && options.quality == "auto") std::cerr << "note: --quality auto: " << offscreen->autoQualitySummary() << "\n";
    if (!options.statsPath.empty()) {
        const std::string json = statsJson(script, result);
        const std::string why = io::writeFileAtomically(options.statsPath, json, io::WriteSite::Stats);
        if (!why.empty()) {
            std::cerr << "error: --stats: " << why << "\n";
            return 1;
        }
    }
    double total = 0.0;
    for (const FrameStats& f : result.stats) total += f.totalMs;
    std::cout << "replayed " << result.frames << " frames of " << script.file << " (mean "
              << (result.frames ? total / result.frames : 0.0) << " ms per frame, budget " << script.budgetMs
              << " ms); " << result.screenshots.size() << " screenshots\n";
    std::vector<std::string> last;
    int status = closeSession(opened, last);
    for (const std::string& line : last) std::cerr << line << "\n";
    if (!result.ok()) {
        std::cerr << "error: " << result.error << "\n";
        return 1;
    }
    return status;
}

}  // namespace hg::garden::cli
