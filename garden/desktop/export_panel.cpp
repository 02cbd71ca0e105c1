#include "garden/desktop/export_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <system_error>

#include "garden/app/garden_session.h"
#include "garden/export/export_file.h"

namespace hg::garden {

namespace {

constexpr const char* kFormats[] = {".hf", ".stl", ".obj", ".glb", ".vdb"};
constexpr const char* kFormatNames[] = {"HyperFun (.hf, exact)", "STL (.stl, mm)", "OBJ (.obj, m)", "glTF (.glb, m)",
                                        "VDB level set (.vdb)"};

std::string safeName(const std::string& name) {
    std::string out;
    for (char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
    return out.empty() ? "sculpture" : out;
}

}  // namespace

struct ExportPanel::Work {
    ExportJob job;
    // The worker reports into it; the bar reads fraction(), Cancel cancels it.
    io::NullProgress progress;
    std::future<std::string> result;
    ExportFileReport report;
};

ExportPanel::ExportPanel(std::string folder) : folder_(std::move(folder)) {}

ExportPanel::~ExportPanel() {
    if (work_ && work_->result.valid()) work_->result.wait();
}

void ExportPanel::setFolder(const std::string& folder) {
    const std::size_t n = std::min(folder.size(), sizeof folderField_ - 1);
    folder.copy(folderField_, n);
    folderField_[n] = '\0';
}

std::string ExportPanel::exportFolder() const {
    if (folderField_[0] != '\0') return folderField_;
    return (std::filesystem::path(folder_.empty() ? "." : folder_) / "exports").string();
}

void ExportPanel::cancel() {
    if (busy()) work_->progress.cancel();
}

bool ExportPanel::busy() const {
    return work_ && work_->result.valid() &&
           work_->result.wait_for(std::chrono::seconds(0)) != std::future_status::ready;
}

const std::string& ExportPanel::status() {
    if (work_ && work_->result.valid() && !busy()) {
        const std::string why = work_->result.get();
        status_ = why.empty() ? work_->report.summary : work_->report.cancelled ? "export " + why : "error: " + why;
        if (!why.empty()) lastPath_.clear();
        work_.reset();
    }
    return status_;
}

bool ExportPanel::start(const GardenSession& session, int index, const std::string& extension, int resolution) {
    if (busy()) {
        status_ = "an export is under way";
        return false;
    }
    status();  // collect the previous one
    shownFor_ = index;  // what the status line will be about
    if (index < 0 || static_cast<std::size_t>(index) >= session.sculptures().size()) {
        status_ = "error: select a sculpture to export";
        return false;
    }
    const std::filesystem::path dir = exportFolder();
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        status_ = "error: cannot make " + dir.string() + ": " + ec.message();
        return false;
    }
    const std::time_t t = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&t));
    const std::string file = fileName_.empty()
                                 ? safeName(session.sculptures()[static_cast<std::size_t>(index)].name) + "-" + stamp
                                 : safeName(fileName_);
    const std::string path = (dir / (file + extension)).string();
    auto work = std::make_unique<Work>();
    ExportFileOptions options;
    options.resolution = resolution;
    // The text is taken now, on the session's thread; the file is written
    // (and a mesh made) on a worker.
    if (std::string why = prepareExport(session, index, path, options, work->job, work->report); !why.empty()) {
        status_ = "error: " + why;
        return false;
    }
    Work* w = work.get();
    w->result = std::async(std::launch::async, [w] { return writeExport(w->job, w->report, &w->progress); });
    work_ = std::move(work);
    lastPath_ = path;
    status_ = "exporting to " + path;
    return true;
}

void ExportPanel::draw(const GardenSession& session) {
    const int selected = session.selected();
    // What the status line says belongs to the sculpture it was about: a
    // new selection starts clean (an export under way keeps its line).
    if (selected != shownFor_ && !busy()) {
        status();
        status_.clear();
        shownFor_ = selected;
    }
    if (!ImGui::CollapsingHeader("Export")) return;
    ImGui::Combo("format", &format_, kFormatNames, IM_ARRAYSIZE(kFormatNames));
    if (format_ == 0 && selected >= 0 && session.sculptures()[static_cast<std::size_t>(selected)].gridOnly())
        ImGui::TextWrapped("a scanned volume or a mesh cannot be written as HyperFun (it cannot read them): "
                           "pick a mesh or the VDB level set, made from its grid");
    if (format_ != 0) {
        ImGui::InputInt("resolution (0: the grid's)", &resolution_, 64, 256);
        resolution_ = std::max(0, std::min(resolution_, 4096));
    }
    if (ImGui::InputTextWithHint("file name", "NAME-TIME (the sculpture's name and the time)", nameField_,
                                 sizeof nameField_))
        fileName_ = nameField_;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("written into the folder below; letters, digits, - and _ are kept, the rest become _");
    const std::string defaultFolder = (std::filesystem::path(folder_.empty() ? "." : folder_) / "exports").string();
    ImGui::InputTextWithHint("folder", defaultFolder.c_str(), folderField_, sizeof folderField_);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the folder the file goes into (made when missing); empty: %s", defaultFolder.c_str());
    const bool can = selected >= 0 && !busy();
    if (!can) ImGui::BeginDisabled();
    if (ImGui::Button("Export the selected sculpture")) start(session, selected, kFormats[format_], resolution_);
    if (!can) ImGui::EndDisabled();
    if (selected < 0) ImGui::TextDisabled("select a sculpture in the list above");
    if (busy()) {
        ImGui::ProgressBar(static_cast<float>(work_->progress.fraction()));
        if (work_->progress.cancelled()) ImGui::TextDisabled("cancelling...");
        else if (ImGui::Button("Cancel")) cancel();
    }
    const std::string& s = status();
    if (!s.empty()) ImGui::TextWrapped("%s", s.c_str());
}

}  // namespace hg::garden
