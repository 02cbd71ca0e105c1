// No subcommand: the desktop garden.
#include "garden/cli/commands.h"
#include "garden/desktop/desktop_app.h"
#include "xr/xr_garden.h"

namespace hg::garden::cli {

int runGarden(const GardenOptions& options) {
    if (options.xr) {
        xr::XrOptions x;
        x.garden = options.garden;
        x.session = options.session;
        x.script = options.xrScript;
        x.frames = options.frames;
        // The flags only switch on; without them the user's settings hold.
        if (options.leftHanded) x.leftHanded = true;
        if (options.seated) x.seated = true;
        if (options.smoothTurn) x.smoothTurn = true;
        return xr::runXrGarden(x);
    }
    DesktopOptions d;
    d.garden = options.garden;
    d.width = options.width;
    d.height = options.height;
    d.vsync = !options.noVsync;
    d.budgetMs = options.budgetMs;
    d.frames = options.frames;
    d.screenshotDir = options.screenshotDir;
    d.exitScreenshot = options.exitScreenshot;
    d.session = options.session;
    return runDesktopGarden(d);
}

}  // namespace hg::garden::cli
