// Plays a replay script on a garden session, frame by frame with the
// script's fixed timestep (docs/replay-format.md). Headless, nothing is
// drawn; with a FrameRenderer (the offscreen window) each frame is uploaded
// and drawn, and screenshots are written.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "garden/app/garden_session.h"
#include "garden/replay/replay_script.h"

namespace hg::garden {

// What `replay --offscreen` plugs in: the frame's views (upload and
// render, garden/app/view_sink.h), and a screenshot of the last frame drawn.
class FrameRenderer : public ViewSink {
public:
    // "" on success, else why the file could not be written.
    virtual std::string screenshot(const std::string& path) = 0;
};

// What an {"export": ...} command calls (garden/export sits beside this
// folder, so the program plugs it in: `hypergarden replay` passes
// exportSculptureFile): sculpture `index` written to `path` at
// `resolution` (0: the grid's), as the desktop's Export panel writes it.
// "" and the report's line in `summary`, or why not.
using ReplayExporter = std::function<std::string(const GardenSession& session, int index, const std::string& path,
                                                 int resolution, std::string& summary)>;

// What an {"extract": ...} command calls (garden/export writes the part:
// `hypergarden replay` passes extractPart): "" or why not.
using ReplayExtractor = std::function<std::string(GardenSession& session, const std::string& from,
                                                  const std::string& model, const std::string& name)>;

struct ReplayOptions {
    int screenshotEvery = 0;         // also a screenshot every N frames (0: only the script's)
    std::string screenshotDir = ".";  // where screenshots go (relative names)
    ReplayExporter exporter;         // none: an export command fails, saying so
    ReplayExtractor extractor;       // none: an extract command fails, saying so
};

struct ReplayResult {
    std::string error;               // non-empty: the replay stopped there
    int frames = 0;
    std::vector<FrameStats> stats;   // one per frame
    std::vector<std::string> screenshots;
    std::vector<std::string> exports;  // the files export commands wrote
    std::vector<std::string> notes;  // what was skipped (screenshots when headless)

    bool ok() const { return error.empty(); }
};

// One command on the session, as a replay runs it at its step's first
// frame; a screenshot is the caller's to take (nothing is done here). ""
// or why it was refused.
std::string runReplayCommand(const ReplayCommand& c, GardenSession& session);

ReplayResult runReplay(const ReplayScript& script, GardenSession& session, FrameRenderer* renderer,
                       const ReplayOptions& options);

// The stats as JSON: the script, per-frame rows (every stage's time,
// samples, chunks, triangles, queues) and a summary (mean and max per stage).
std::string statsJson(const ReplayScript& script, const ReplayResult& result);

}  // namespace hg::garden
