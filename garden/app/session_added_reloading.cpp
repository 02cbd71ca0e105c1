// Sculptures added from a HyperFun file, read again when the file changes
// on disk (issue 23, docs/desktop.md "Sources edited on disk"). Unlike a
// garden file's sculpture, whose file the session copied, an added one
// holds its text in its AddAction; a change is taken in as a ReloadAction
// carrying the new text, journalled, so that playing the journal gives the
// same grids without the file. Its edits are applied again on the new grid
// (replaceSource); a broken file keeps the last good one and says why.
#include <filesystem>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_sampling.h"
#include "io/read_text.h"
#include "voxel/sampler.h"

namespace hg::garden {

namespace fs = std::filesystem;

void GardenSession::watchAddedSource(std::size_t index, const std::string& text) {
    SculptureSpec& spec = load_.garden->sculptures[static_cast<std::size_t>(sculptures_[index].source.spec)];
    if (spec.file.empty()) {
        // The file it was added from, as named then (a sketch's or a part's
        // origin names no file, and a file gone is not watched).
        std::error_code ec;
        if (spec.fileAsWritten.empty() || !fs::is_regular_file(spec.fileAsWritten, ec)) return;
        spec.file = fs::absolute(spec.fileAsWritten).lexically_normal().string();
    }
    addedSources_[index] = text;
    // A file that no longer holds the text applied (it changed while the
    // session was closed) is read again at the next look.
    std::string now;
    const bool same = io::readText(spec.file, now).empty() && now == text;
    sculptures_[index].sourceStamp = same ? sourceStamp(spec.file) : -1;
}

void GardenSession::reloadAddedSources(std::vector<std::size_t>& reported) {
    for (const auto& [index, text] : addedSources_) {
        Sculpture& s = sculptures_[index];
        const std::string& file = load_.garden->sculptures[static_cast<std::size_t>(s.source.spec)].file;
        if (s.removed) continue;  // looked at again once redone
        const std::int64_t stamp = sourceStamp(file);
        if (stamp == 0 || stamp == s.sourceStamp) continue;
        s.sourceStamp = stamp;
        std::string now;
        std::string problem = io::readText(file, now);
        if (problem.empty() && now == text) {
            if (s.sourceProblem.empty()) continue;  // touched, not changed
        } else if (problem.empty()) {
            problem = apply(ReloadAction{s.name, now});
        }
        s.sourceProblem = problem;
        reported.push_back(index);
    }
}

std::string GardenSession::applyReloadModel(const ReloadAction& a) {
    const int i = findSculpture(a.sculpture);
    if (i < 0) return "no sculpture named '" + a.sculpture + "'";
    const auto index = static_cast<std::size_t>(i);
    const Sculpture& s = sculptures_[index];
    if (index < fileSculptures_ || s.source.kind != SculptureSource::Kind::HyperFun || s.missing())
        return "'" + a.sculpture + "' was not added from a HyperFun file: it has no text to replace";
    const auto specIndex = static_cast<std::size_t>(s.source.spec);
    SculptureSpec spec = load_.garden->sculptures[specIndex];
    // The model box is found from the new text, as for a garden entry
    // without one: a solid that grew is not cut at the old box.
    spec.box.reset();
    SculptureLoad loaded = sculptureFromText(spec, a.source);
    if (!loaded.ok()) return loaded.error;
    voxel::VoxelizeResult r = sampleSculptureSource(spec, loaded, volumeRequest(spec));
    if (!r.volume) return spec.fileAsWritten + ": cannot be sampled: " + r.error;
    load_.garden->sculptures[specIndex] = spec;
    if (std::string why = replaceSource(index, std::move(loaded), std::move(*r.volume)); !why.empty()) return why;
    watchAddedSource(index, a.source);
    record(a);
    return "";
}

}  // namespace hg::garden
