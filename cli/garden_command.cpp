// No subcommand: the desktop garden.
#include "cli/commands.h"
#include "garden/desktop/desktop_app.h"
#include "garden/render/render_quality.h"
#include "xr/xr_garden.h"

namespace hg::garden::cli {

int runGarden(const GardenOptions& options) {
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
    d.screenshotDir = options.screenshotDir;
    d.session = options.session;
    d.quality = qualityOf(parseQualityPreset(options.quality).value_or(QualityPreset::High));
    // F9 takes the open garden into the headset and back.
    d.headset = xr::headsetFromDesktop(x);
    if (options.xr) {
        x.script = options.xrScript;
        x.frames = options.frames;
        x.desktop = d;
        return xr::runXrGarden(x);
    }
    d.frames = options.frames;
    d.exitScreenshot = options.exitScreenshot;
    return runDesktopGarden(d);
}

}  // namespace hg::garden::cli
