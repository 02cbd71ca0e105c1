// No subcommand: the desktop garden.
#include "garden/cli/commands.h"
#include "garden/desktop/desktop_app.h"

namespace hg::garden::cli {

int runGarden(const GardenOptions& options) {
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
