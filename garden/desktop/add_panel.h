// The desktop's "Add a sculpture" section (docs/design.md §10, bringing work
// in; docs/desktop.md): a HyperFun file, a mesh (.stl, .obj, .ply) or an
// OpenVDB volume (.vdb) named in a text field becomes a new sculpture on the
// ground 3 m ahead of the viewer, sized to 1.5 m, selected; one AddAction,
// so it is journalled and undoable like an edit (a mesh or a volume is
// copied into the session folder first). Refusals (a file that does not
// open, parse or read) are shown with the reader's messages.
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
