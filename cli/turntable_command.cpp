// `hypergarden turntable (SESSION_DIR | GARDEN.json) --sculpture NAME -o DIR`:
// PNG frames of one sculpture turning once (docs/rendering.md,
// "Turntable"). A session is read as `export` reads it (its journal played,
// the folder not changed); every check that needs no rendering comes first.
#include <filesystem>
#include <iostream>

#include "cli/commands.h"
#include "cli/open_read_only.h"
#include "cli/progress_bar.h"
#include "garden/desktop/turntable.h"
#include "io/checked_write.h"

namespace hg::garden::cli {

int runTurntable(const TurntableCommandOptions& options) {
    TurntableOptions to;
    if (!parseImageSize(options.size, to.width, to.height)) {
        std::cerr << "error: --size '" << options.size << "': expected WIDTHxHEIGHT, each " << kMinImageSide << " to "
                  << kMaxImageSide << " pixels, for example 800x800\n";
        return 2;
    }
    to.frames = options.frames;
    to.elevationDeg = static_cast<float>(options.elevationDeg);
    to.distance = static_cast<float>(options.distance);
    to.quality = qualityOf(parseQualityPreset(options.quality).value_or(QualityPreset::High));
    std::error_code ec;
    if (std::filesystem::exists(options.output, ec) && !std::filesystem::is_directory(options.output, ec)) {
        std::cerr << "error: -o " << options.output << ": not a folder (the frames go into a folder)\n";
        return 2;
    }
    SessionSettings settings;
    // The sculpture close up, at its full detail: no coarser levels at all
    // (a session's edited sculpture would otherwise show a coarse level
    // first, with nothing left to mesh).
    settings.lod = false;
    settings.maxLevel = 0;
    settings.viewportHeight = to.height;
    settings.remeshChunksPerFrame = 64;  // meshing in few frames: nothing waits on a display
    settings.morphSamplesPerFrame = 1u << 22;
    int status = 0;
    std::unique_ptr<GardenSession> session = openReadOnly(options.input, settings, "rendering", status);
    if (!session) return status;
    const int index = findUsableSculpture(*session, options.input, options.sculpture, status);
    if (index < 0) return status;
    const Sculpture& s = session->sculptures()[static_cast<std::size_t>(index)];
    std::filesystem::create_directories(options.output, ec);
    if (ec) {
        std::cerr << "error: -o " << options.output << ": cannot make the folder: " << ec.message() << "\n";
        return 2;
    }
    const std::string first = (std::filesystem::path(options.output) / turntableFrameName(s.name, 0)).string();
    if (const std::string why = io::checkWritable(first); !why.empty()) {
        std::cerr << "error: " << why << "\n";
        return 2;
    }
    std::vector<std::string> written;
    std::string why;
    {
        ProgressBar bar("turntable " + s.name);
        why = renderTurntable(*session, index, to, options.output, written, &bar);
    }
    if (!why.empty()) {
        std::cerr << "error: " << why << "\n";
        return 1;
    }
    std::cout << "wrote " << written.size() << " frames of '" << s.name << "' (" << to.width << "x" << to.height << ", "
              << options.quality << ") to " << options.output << ": " << turntableFrameName(s.name, 0) << " ... "
              << turntableFrameName(s.name, to.frames - 1) << "\n";
    return 0;
}

}  // namespace hg::garden::cli
