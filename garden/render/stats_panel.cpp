#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "garden/render/chunk_arena.h"
#include "garden/render/panels.h"

namespace hg::garden {
namespace {

float totalMsAt(void* data, int index) {
    const auto* frames = static_cast<const std::vector<FrameStats>*>(data);
    return static_cast<float>((*frames)[static_cast<std::size_t>(index)].totalMs);
}

const ImU32 kOverBudget = IM_COL32(230, 80, 60, 255);
const ImU32 kBudgetLine = IM_COL32(240, 200, 60, 220);
// Fixed, since the window fits its contents (no available width to fill).
constexpr float kGraphWidth = 300.0f;

void counterRow(const char* name, std::size_t value) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(name);
    ImGui::TableSetColumnIndex(1);
    ImGui::Text("%zu", value);
}

void frameGraph(const FrameHistory& history, double budgetMs) {
    const auto& frames = history.frames();
    double worst = 0.0, sum = 0.0;
    for (const FrameStats& f : frames) {
        worst = std::max(worst, f.totalMs);
        sum += f.totalMs;
    }
    // Room above the budget so the line sits inside the graph; taller spikes
    // raise the scale.
    const float top = static_cast<float>(std::max(1.5 * budgetMs, 1.1 * worst));
    char caption[64];
    std::snprintf(caption, sizeof caption, "avg %.2f  max %.2f ms", sum / static_cast<double>(frames.size()), worst);
    ImGui::PlotLines("##frame_ms", totalMsAt, const_cast<std::vector<FrameStats>*>(&frames),
                     static_cast<int>(frames.size()), 0, caption, 0.0f, top,
                     ImVec2(kGraphWidth, 80.0f));
    const ImVec2 lo = ImGui::GetItemRectMin();
    const ImVec2 hi = ImGui::GetItemRectMax();
    const float y = hi.y - (hi.y - lo.y) * static_cast<float>(budgetMs) / top;
    ImGui::GetWindowDrawList()->AddLine(ImVec2(lo.x, y), ImVec2(hi.x, y), kBudgetLine, 1.0f);
}

}  // namespace

void drawStatsPanel(const FrameHistory& history, bool toggle, const std::function<const MemoryReport&()>& memory,
                    const ChunkArena* gpuMeshes) {
    // Always fitted to its contents: they change from "no frames yet" to the
    // full panel, and a size fitted once would clip them.
    // Folded at first: numbers for whoever looks for them, not a new user's view.
    static bool folded = true;  // as last drawn (its title's arrow folds it too)
    if (toggle) ImGui::SetNextWindowCollapsed(!folded, ImGuiCond_Always);
    else ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    const bool shown = ImGui::Begin(kStatsPanelTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    folded = ImGui::IsWindowCollapsed();
    if (!shown) {
        ImGui::End();
        return;
    }
    const FrameStats* last = history.last();
    if (!last) {
        ImGui::TextUnformatted("no frames yet");
        ImGui::End();
        return;
    }
    const bool over = last->totalMs > last->budgetMs;
    if (over) ImGui::PushStyleColor(ImGuiCol_Text, kOverBudget);
    ImGui::Text("frame %llu: %.2f of %.2f ms", static_cast<unsigned long long>(last->frame), last->totalMs,
                last->budgetMs);
    if (over) ImGui::PopStyleColor();

    // Each stage as a bar filled by its share of the budget.
    for (int s = 0; s < kStageCount; ++s) {
        const double ms = last->stageMs[static_cast<std::size_t>(s)];
        char text[32];
        std::snprintf(text, sizeof text, "%.2f ms", ms);
        const float share = last->budgetMs > 0.0 ? static_cast<float>(ms / last->budgetMs) : 0.0f;
        ImGui::ProgressBar(std::min(share, 1.0f), ImVec2(160.0f, 0.0f), text);
        ImGui::SameLine();
        ImGui::TextUnformatted(stageName(static_cast<Stage>(s)));
    }
    // The GPU's own time (timer queries), beside the CPU's stages: a frame
    // may be cheap to submit and still slow to draw.
    if (last->gpuMs >= 0.0) {
        ImGui::Text("GPU %.2f ms", last->gpuMs);
        // Pass by pass, those that ran: which effect to switch off.
        const GpuPassMs& pass = last->gpuPassMs;
        std::string passes;
        for (const auto& [name, ms] : {std::pair<const char*, double>{"shadow", pass.shadow}, {"scene", pass.scene},
                                       {"occlusion", pass.occlusion}, {"post", pass.post}}) {
            if (ms < 0.0) continue;
            char text[48];
            std::snprintf(text, sizeof text, "%s%s %.2f", passes.empty() ? "" : ", ", name, ms);
            passes += text;
        }
        if (!passes.empty()) ImGui::TextDisabled("  %s", passes.c_str());
    } else
        ImGui::TextUnformatted("GPU time: not measured yet");

    if (ImGui::BeginTable("##counters", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
        counterRow("morph samples", last->morphSamples);
        counterRow("morph samples pending", last->morphPending);
        counterRow("chunks meshed", last->chunksMeshed);
        counterRow("chunks shown", last->chunksShown);
        counterRow("remesh pending", last->remeshPending);
        counterRow("upload bytes", last->uploadBytes);
        counterRow("uploads pending", last->uploadsPending);
        counterRow("triangles drawn", last->trianglesDrawn);
        counterRow("chunks drawn", last->chunksDrawn);
        counterRow("draw calls", last->drawCalls);
        counterRow("impostors drawn", last->impostorsDrawn);
        counterRow("sculptures hidden", last->sculpturesHidden);
        counterRow("shadow maps drawn", last->shadowMapsDrawn);
        counterRow("shadow maps kept", last->shadowMapsKept);
        counterRow("pictures kept", last->picturesKept);
        counterRow("pictures sharpened", last->picturesSharpened);
        ImGui::EndTable();
    }
    if (memory) {
        const MemoryReport& held = memory();
        // What the garden holds, by kind: the sculptures' grids first (the
        // most of it), then their coarser levels, meshes, edits' bases and
        // the morphs' source caches.
        auto mib = [](std::size_t b) { return static_cast<double>(b) / (1024.0 * 1024.0); };
        ImGui::Text("memory held: %.0f MiB for %zu sculptures", mib(held.total()), held.sculptures);
        ImGui::Text("grids %.0f, levels %.0f, meshes %.0f, edit bases %.0f, morph sources %.0f MiB", mib(held.grids),
                    mib(held.levels), mib(held.meshes), mib(held.editBases), mib(held.morphSources));
        // The budget (--memory-budget) and the far grids it keeps on disk.
        if (held.budget > 0 && held.total() > held.budget)
            ImGui::Text("budget %.0f MiB: %zu far grids on disk, the rest near enough to stay", mib(held.budget),
                        held.pagedOut);
        else if (held.budget > 0)
            ImGui::Text("budget %.0f MiB: %zu far grids on disk", mib(held.budget), held.pagedOut);
        else
            ImGui::TextUnformatted("no memory budget: every grid in memory");
        if (!held.pagingProblem.empty()) ImGui::TextWrapped("%s", held.pagingProblem.c_str());
    }
    if (gpuMeshes) {
        // The chunk meshes on the GPU: their buffers, and how much of them
        // is used (pages emptied in the background: docs/rendering.md).
        auto mib = [](std::size_t b) { return static_cast<double>(b) / (1024.0 * 1024.0); };
        const std::size_t pages = gpuMeshes->livePages();
        ImGui::Text("GPU meshes: %.0f MiB in %zu buffer pair%s, %.0f MiB used", mib(gpuMeshes->capacityBytes()), pages,
                    pages == 1 ? "" : "s", mib(gpuMeshes->usedBytes()));
    }
    frameGraph(history, last->budgetMs);
    ImGui::End();
}

}  // namespace hg::garden
