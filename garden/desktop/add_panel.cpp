#include "garden/desktop/add_panel.h"

#include <algorithm>

#include <imgui.h>

#include "garden/app/garden_session.h"

namespace hg::garden {

namespace {

const char* const kFileTooltip =
    "A HyperFun file (.hf): its my_model body (else the first); a file edited later is read again.\n"
    "A mesh (.stl, .obj, .ply): turned into a level set (OpenVDB's mesh-to-volume); an open mesh becomes a thin shell.\n"
    "An OpenVDB volume (.vdb): a level set's zero, or a fog volume's middle value.\n"
    "It stands on the ground 3 m ahead, 1.5 m tall. A mesh or a volume is copied into the session's imports/\n"
    "folder, so the session reopens without the original. It is sculpted and exported as a mesh like any other;\n"
    "its HyperFun export is refused (HyperFun cannot read a mesh or a volume). Ctrl+Z takes it away.";

}  // namespace

std::string AddPanel::add(GardenSession& session, const std::string& path) {
    if (path.empty()) return status_ = "name a file first: HyperFun (.hf), a mesh (.stl, .obj, .ply) or a volume (.vdb)";
    Placement p;
    p.position = session.placeInView(3.0);
    p.scale = 0.0;  // sized to the garden
    const std::string why = session.addSculptureFile(path, "", p, resolution_);
    if (why.empty()) {
        const int added = static_cast<int>(session.sculptures().size()) - 1;
        session.select(added);
        status_ = "added '" + session.sculptures()[static_cast<std::size_t>(added)].name + "' (Ctrl+Z takes it away)";
    } else {
        status_ = why;
    }
    return why;
}

void AddPanel::draw(GardenSession& session) {
    if (!ImGui::CollapsingHeader("Add a sculpture")) return;
    ImGui::InputTextWithHint("file", "model.hf, .stl, .obj, .ply or .vdb", path_, sizeof path_);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", kFileTooltip);
    ImGui::InputInt("resolution", &resolution_, 32, 128);
    resolution_ = std::clamp(resolution_, 16, 1024);
    if (ImGui::Button("Add")) add(session, path_);
    if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
}

}  // namespace hg::garden
