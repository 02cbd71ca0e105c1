// GardenSession's sources edited on disk (issue 23, docs/desktop.md
// "Sources edited on disk"): a sculpture whose HyperFun file changed is read
// again and, when it parses and samples, its grid is replaced in place and
// its edits applied again; a broken file keeps the last good grid and says
// why. Nothing the user made (edits, undo history, placement) is touched.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <system_error>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_sampling.h"
#include "garden/sculpt/sculpture_edits.h"
#include "voxel/sampler.h"

namespace hg::garden {

std::int64_t GardenSession::sourceStamp(const std::string& path) {
    std::error_code ec;
    const auto t = std::filesystem::last_write_time(path, ec);
    if (ec) return 0;
    return static_cast<std::int64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count());
}

std::vector<GardenSession::SourceReload> GardenSession::reloadChangedSources() {
    std::vector<SourceReload> out;
    const Garden& g = *load_.garden;
    for (std::size_t i = 0; i < fileSculptures_ && i < sculptures_.size(); ++i) {
        Sculpture& s = sculptures_[i];
        if (s.removed || s.loading) continue;
        const SculptureSpec& spec = g.sculptures[i];
        const std::int64_t stamp = sourceStamp(spec.file);
        if (stamp == 0 || stamp == s.sourceStamp) continue;
        s.sourceStamp = stamp;
        std::string problem;
        const bool morphSource =
            g.morph && std::find(g.morph->sourceIndex.begin(), g.morph->sourceIndex.end(), i) != g.morph->sourceIndex.end();
        if (morphSource) {
            problem = spec.file + " changed: a source of the metamorphosis is read again when the garden is reopened";
        } else {
            SculptureLoad loaded = loadSculpture(spec);
            if (!loaded.ok()) {
                problem = loaded.error;
            } else {
                voxel::VoxelizeResult r = sampleSculptureSource(spec, loaded, volumeRequest(spec));
                if (!r.volume) problem = spec.file + ": cannot be sampled: " + r.error;
                else problem = replaceSource(i, std::move(loaded), std::move(*r.volume));
            }
        }
        while (!problem.empty() && problem.back() == '\n') problem.pop_back();
        s.sourceProblem = problem;
        out.push_back({s.name, problem});
    }
    return out;
}

std::string GardenSession::replaceSource(std::size_t index, SculptureLoad loaded, voxel::Volume fresh) {
    Sculpture& s = sculptures_[index];
    const SculptureSpec& spec = load_.garden->sculptures[index];
    if (s.missing()) {
        // A sculpture that was missing comes in as if it had loaded at the start.
        s.error.clear();
        s.source.program = loaded.program;
        load_.sculptures[index] = std::move(loaded);
        attachGrid(index, std::make_unique<voxel::Volume>(std::move(fresh)), "");
        return "";
    }
    // In place, so that the meshes already shown are replaced chunk by chunk
    // like an edit's: the grid's frame (box, resolution) must be the one it had.
    const voxel::VolumeFrame& was = s.volume->frame;
    const voxel::VolumeFrame& now = fresh.frame;
    bool same = now.voxelSize == was.voxelSize && now.band == was.band;
    for (int a = 0; a < 3; ++a)
        same = same && now.modelBox.lo[a] == was.modelBox.lo[a] && now.modelBox.hi[a] == was.modelBox.hi[a] &&
               now.indexBox.lo[a] == was.indexBox.lo[a] && now.indexBox.hi[a] == was.indexBox.hi[a];
    if (!same)
        return spec.file + " changed its model box (the solid grew, shrank or moved) and the garden gives it no "
                           "\"box\": give the sculpture a box in the garden file, or reopen the garden to see it";
    if (stroking() && strokeSculpture_ == static_cast<int>(index)) endStroke();
    if (liveMove_ == static_cast<int>(index)) endLiveMove();
    *s.volume = std::move(fresh);
    s.source.program = loaded.program;
    load_.sculptures[index] = std::move(loaded);
    if (s.edits) s.edits->rebase();
    showChanged(static_cast<int>(index), s.volume->frame.indexBox);
    return "";
}

}  // namespace hg::garden
