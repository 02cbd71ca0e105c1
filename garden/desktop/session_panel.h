// The Garden panel's Session section (issue 23): the folder the window
// saves into, Duplicate (a copy of the session to keep, the user goes on
// here) and Save As (the copy, and the user goes on in it), both with the
// current view (garden/session/session_copy.h, session_view.h), and the
// recent sessions (recent_sessions.h) to open. Without a session folder
// nothing is saved: the section says so and how to start one.
#pragma once

#include <string>
#include <vector>

namespace hg::garden {

class GardenSession;
class SessionRecorder;

class SessionPanel {
public:
    // `recentPath`: the recent-sessions file ("" : none kept).
    explicit SessionPanel(std::string recentPath);

    // ImGui calls for one frame, inside an open window. Returns the folder
    // the user chose to go on in (Save As, a recent session), else "".
    std::string draw(GardenSession& session, const SessionRecorder* recorder);

    // What the buttons do. duplicate: the copy made with the current view;
    // "" or why not. saveAs: the same, then the copy is the folder to go on
    // in (returned), "" when refused (status() says why).
    std::string duplicate(const GardenSession& session, const SessionRecorder& recorder, const std::string& to);
    std::string saveAs(const GardenSession& session, const SessionRecorder& recorder, const std::string& to);

    // The recent sessions as read when the panel was made (the one open first).
    const std::vector<std::string>& recent() const { return recent_; }
    // Once a session is open in the window: first in the list and its file.
    void opened(const std::string& dir);
    const std::string& status() const { return status_; }
    // The folder field's text (what typing into it sets).
    void setFolder(const std::string& folder);
    void setStatus(std::string text, bool error);

private:
    std::string recentPath_;
    std::vector<std::string> recent_;
    char folder_[512] = {};
    std::string status_;
    bool error_ = false;
};

}  // namespace hg::garden
