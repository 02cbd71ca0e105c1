// The desktop's "Add a sculpture" section (docs/design.md §10, bringing work
// in): a HyperFun file named in a text field becomes a new sculpture on the
// ground 3 m ahead of the viewer, sized to 1.5 m, selected; one AddAction,
// so it is journalled and undoable like an edit. Refusals (a file that does
// not open or parse) are shown with the parser's messages.
#pragma once

#include <string>

namespace hg::garden {

class GardenSession;

class AddPanel {
public:
    // ImGui calls for one frame, inside an open window.
    void draw(GardenSession& session);
    // What the button does: "" and the new sculpture selected, or why not.
    std::string add(GardenSession& session, const std::string& path);
    const std::string& status() const { return status_; }

private:
    char path_[512] = {};
    int resolution_ = 128;
    std::string status_;
};

}  // namespace hg::garden
