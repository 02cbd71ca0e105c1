#include "garden/session/open_session.h"

namespace hg::garden {

OpenedSession openSession(const std::string& dir, const std::string& gardenFile, const SessionSettings& settings) {
    OpenedSession out;
    bool created = false;
    if (std::string why = ensureSession(dir, gardenFile, created); !why.empty()) {
        out.error = why;
        out.exitStatus = 2;
        return out;
    }
    if (created) out.notes.push_back("created the session " + dir + " from " + gardenFile);
    auto recorder = std::make_unique<SessionRecorder>(dir);
    if (std::string why = recorder->readJournal(); !why.empty()) {
        out.error = why;
        out.exitStatus = 2;
        return out;
    }
    GardenLoad load = loadGarden(recorder->paths().garden);
    if (!load.ok()) {
        out.error = load.error;
        out.exitStatus = 2;
        return out;
    }
    out.session = std::make_unique<GardenSession>(std::move(load), settings);
    const std::string played = recorder->attach(*out.session);
    for (const std::string& n : recorder->notes()) out.notes.push_back(n);
    if (!played.empty()) out.notes.push_back(played);
    if (!created)
        out.notes.push_back("reopened the session " + dir + " with " + std::to_string(recorder->journal().records.size()) +
                            " journalled actions");
    out.recorder = std::move(recorder);
    return out;
}

OpenedSession openLoadedOrSession(std::optional<GardenLoad> loaded, const std::string& dir, const std::string& gardenFile,
                                  const SessionSettings& settings) {
    if (dir.empty() && loaded) {
        OpenedSession out;
        out.session = std::make_unique<GardenSession>(std::move(*loaded), settings);
        return out;
    }
    return openSession(dir, gardenFile, settings);
}

std::vector<std::string> openedMessages(const OpenedSession& opened) {
    std::vector<std::string> lines;
    for (const std::string& n : opened.notes) lines.push_back("note: " + n);
    if (opened.session)
        for (const Sculpture& s : opened.session->sculptures()) {
            if (!s.missing()) continue;
            std::string error = s.error;
            while (!error.empty() && error.back() == '\n') error.pop_back();  // a parser's message may end its line
            lines.push_back("warning: sculpture '" + s.name + "' is missing: " + error);
        }
    return lines;
}

}  // namespace hg::garden
