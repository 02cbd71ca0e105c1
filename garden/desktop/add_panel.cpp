#include "garden/desktop/add_panel.h"

#include <algorithm>

#include <imgui.h>

#include "garden/app/garden_session.h"

namespace hg::garden {

std::string AddPanel::add(GardenSession& session, const std::string& path) {
    if (path.empty()) return status_ = "name a HyperFun file (.hf) first";
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
    ImGui::InputTextWithHint("file", "path/to/model.hf", path_, sizeof path_);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("a HyperFun file; its my_model body (else the first) stands 3 m ahead, 1.5 m tall");
    ImGui::InputInt("resolution", &resolution_, 32, 128);
    resolution_ = std::clamp(resolution_, 16, 1024);
    if (ImGui::Button("Add")) add(session, path_);
    if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
}

}  // namespace hg::garden
