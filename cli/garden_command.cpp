// No subcommand: the desktop garden (of a garden file, or of one .hf file);
// and `garden add`, which adds a sculpture to a garden file.
#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "cli/commands.h"
#include "garden/desktop/desktop_app.h"
#include "garden/render/render_quality.h"
#include "garden/scene/garden_making.h"
#include "garden/scene/json_reader.h"
#include "io/checked_write.h"
#include "io/read_text.h"
#include "xr/xr_garden.h"

namespace hg::garden::cli {

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kCommands = {"check", "eval", "voxelize", "mesh", "replay", "session",
                                            "export", "garden", "gesture"};

// A garden file for `hypergarden FILE.hf` in a folder of its own under the
// temporary directory (the sculpture's file is named by its absolute path),
// or "" after saying why not.
std::string gardenForModel(const std::string& model, std::size_t extraArgs) {
    if (fs::path(model).extension() == ".hf" && extraArgs > 0) {
        std::cerr << "error: one HyperFun file opens as a garden; the words after '" << model << "' are not expected\n";
        return "";
    }
    if (fs::path(model).extension() != ".hf") {
        std::cerr << "error: '" << model << "' is neither a command nor a HyperFun file (.hf)";
        const std::string near = nearMiss(model, kCommands);
        if (!near.empty()) std::cerr << " (did you mean '" << near << "'?)";
        std::cerr << "\nRun hypergarden --help for the commands.\n";
        return "";
    }
    ModelToPlace m;
    m.file = model;
    std::string error;
    const std::string text = gardenOfOneModel(m, error);
    if (text.empty()) {
        std::cerr << error;
        if (error.empty() || error.back() != '\n') std::cerr << '\n';
        return "";
    }
    const fs::path dir = fs::temp_directory_path() /
                         ("hypergarden-" + fs::path(model).stem().string() + "-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::create_directories(dir, ec);
    const std::string path = (dir / "garden.json").string();
    if (std::string why = io::writeFileAtomically(path, text, io::WriteSite::SessionFile); !why.empty()) {
        std::cerr << "error: " << why << '\n';
        return "";
    }
    return path;
}

}  // namespace

int runGarden(const GardenOptions& given) {
    GardenOptions options = given;
    if (!options.model.empty()) {
        if (options.gardenGiven) {
            std::cerr << "error: give a garden (--garden) or a HyperFun file, not both\n";
            return 2;
        }
        options.garden = gardenForModel(options.model, options.extraArgs);
        if (options.garden.empty()) return 2;
        options.gardenGiven = true;
    }
    xr::XrOptions x;
    x.garden = options.garden;
    x.gardenGiven = options.gardenGiven;
    x.session = options.session;
    // The flags only switch on; without them the user's settings hold.
    if (options.leftHanded) x.leftHanded = true;
    if (options.seated) x.seated = true;
    if (options.smoothTurn) x.smoothTurn = true;

    DesktopOptions d;
    d.garden = options.garden;
    d.gardenGiven = options.gardenGiven;
    d.width = options.width;
    d.height = options.height;
    d.vsync = !options.noVsync;
    d.budgetMs = options.budgetMs;
    d.memoryBudgetBytes = x.memoryBudgetBytes = options.memoryBudgetMiB << 20;
    d.impostorDistance = x.impostorDistance = options.impostorDistance;
    d.screenshotDir = options.screenshotDir;
    d.session = options.session;
    // "auto" (no preset) is decided once the window knows its GL renderer.
    if (const auto preset = parseQualityPreset(options.quality)) {
        d.quality = qualityOf(*preset);
        x.quality = d.quality;
    } else {
        d.autoQuality = x.autoQuality = true;
    }
    // F9 takes the open garden into the headset and back.
    d.headset = xr::headsetFromDesktop(x);
    if (options.xr) {
        x.script = options.xrScript;
        x.frames = options.frames;
        x.desktop = desktopAfterHeadset(d);  // F9 in the headset: this desktop, whose F9 comes back
        return xr::runXrGarden(x);
    }
    d.frames = options.frames;
    d.exitScreenshot = options.exitScreenshot;
    return runDesktopGarden(d);
}

int runGardenAdd(const GardenAddOptions& options) {
    std::string text;
    if (std::string why = io::readText(options.garden, text); !why.empty()) {
        std::cerr << "cannot open the garden file " << why << '\n';
        return 1;
    }
    ModelToPlace m;
    m.file = options.file;
    m.name = options.name;
    m.body = options.body;
    m.resolution = options.resolution;
    m.size = options.size;
    std::string error;
    const std::string out = gardenWithModel(text, options.garden, m, error);
    if (out.empty()) {
        std::cerr << error;
        if (error.empty() || error.back() != '\n') std::cerr << '\n';
        return 1;
    }
    if (std::string why = io::writeFileAtomically(options.garden, out, io::WriteSite::SessionFile); !why.empty()) {
        std::cerr << "error: " << why << " (the garden file is unchanged)\n";
        return 1;
    }
    std::cout << "added '" << (m.name.empty() ? fs::path(m.file).stem().string() : m.name) << "' to " << options.garden
              << '\n';
    return 0;
}

}  // namespace hg::garden::cli
