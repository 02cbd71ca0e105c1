// The tool panel (panels.h) and the widgets it shares with the hand panel
// (tool_panel.h): ImGui calls only, on the session's ToolSettings and its
// sculpting API.
#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_gizmos.h"
#include "garden/export/part_export.h"
#include "garden/render/panels.h"
#include "garden/render/tool_panel.h"
#include "garden/scene/materials.h"

namespace hg::garden {
namespace {

using Kind = ToolSettings::Kind;

// The tools in key order: key 0 is none, 1..9 the rest.
constexpr Kind kTools[] = {Kind::None,    Kind::Carve, Kind::Add,    Kind::Melt,   Kind::Perturb,
                           Kind::Impacts, Kind::Move,  Kind::Sketch, Kind::Smooth, Kind::Inflate};
constexpr const char* kToolLabels[] = {"morph (0)",   "carve (1)", "add (2)",    "soft carve (3)", "perturb (4)",
                                       "impacts (5)", "move (6)",  "sketch (7)", "smooth (8)",     "inflate (9)"};
constexpr const char* kToolTips[] = {
    "no tool: the left button picks the blend of the three key sculptures on the ground triangle",
    "carve: remove material along the stroke (R: add instead)",
    "add: build material along the stroke (R: carve instead)",
    "soft carve: a carve with a rounded edge along the stroke (the journal's \"melt\")",
    "perturb: push the surface out with a bump (R: pull it in)",
    "impacts: age the surface with a series of hits fired at it",
    "move: select a sculpture, drag it on the ground, turn it on its ring, [ ] to scale",
    "sketch: hold the button on a sculpture and draw an outline; on release it is inflated and joined to the "
    "sculpture (R: cut from it)",
    "smooth: blends the surface under the stroke towards a smooth fit of it (bumps and noise go, the form stays)",
    "inflate: pushes the surface out along the stroke, by up to the strength in voxels (R: deflate, in)"};
constexpr ToolWidgetLook kDesktopLook{};

// The label with the desktop's keys, or without them.
const char* keyed(const char* withKeys, const char* plain, const ToolWidgetLook& look) {
    return look.keyHints ? withKeys : plain;
}

// A slider on a double; logarithmic for sizes.
bool sliderDouble(const char* label, double& value, double lo, double hi, const char* format, const ToolWidgetLook& look,
                  bool logarithmic = false) {
    ImGui::SetNextItemWidth(look.fieldWidth);
    return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format,
                               ImGuiSliderFlags_AlwaysClamp | (logarithmic ? ImGuiSliderFlags_Logarithmic : 0));
}

template <class E, std::size_t N>
bool chooseEnum(const char* label, E& value, const char* const (&names)[N], const ToolWidgetLook& look) {
    int i = static_cast<int>(value);
    if (!chooseOne(label, i, names, static_cast<int>(N), look)) return false;
    value = static_cast<E>(i);
    return true;
}

bool strokeParameters(ToolSettings& t, const ToolWidgetLook& look) {
    bool changed = sliderDouble(keyed("radius (m)  [ ]", "radius (m)", look), t.radius, kMinToolSize, kMaxToolSize, "%.3f", look, true);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the stroke's radius in metres of the garden");
    if (t.kind == Kind::Melt) {
        changed |= sliderDouble("softness (voxels)", t.softness, 0.25, 16.0, "%.2f", look, true);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("how wide the soft carve's rounded edge is, in voxels");
    }
    if (t.kind == Kind::Smooth) {
        changed |= sliderDouble("strength", t.smoothStrength, kMinSmoothStrength, kMaxSmoothStrength, "%.2f", look);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("how far one stroke blends towards the smooth fit: 1 all the way at the path\n"
                              "(times the trigger's pressure on the headset)");
    }
    if (t.kind == Kind::Inflate) {
        changed |= sliderDouble("strength (voxels)", t.inflateStrength, kMinInflateStrength, kMaxInflateStrength, "%.2f",
                                look, true);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("how far one stroke moves the surface at its path, in voxels (under the grid's band)\n"
                              "(times the trigger's pressure on the headset)");
    }
    if (t.kind == Kind::Smooth || t.kind == Kind::Inflate) {
        constexpr const char* falloffs[] = {"smooth", "linear", "sharp", "constant"};
        chooseEnum("falloff", t.falloff, falloffs, look);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("how the stroke's weight falls from its path to its radius: smooth (an S curve), "
                              "linear, sharp (only near the path), constant (full to a voxel from the edge)");
    }
    return changed;
}

bool perturbParameters(ToolSettings& t, const ToolWidgetLook& look) {
    constexpr const char* shapes[] = {"ellipsoid", "torus"};
    bool changed = chooseEnum("shape", t.shape, shapes, look);
    // The radii per axis in one row: dragged a millimetre a pixel, or typed
    // (Ctrl+click); times the scale, each within the tools' size bounds.
    const double lo = kMinToolSize / t.perturbScale, hi = kMaxToolSize / t.perturbScale;
    ImGui::SetNextItemWidth(look.fieldWidth);
    if (t.shape == QuadricShape::Ellipsoid) {
        changed |= ImGui::DragScalarN("radii x y z (m)", ImGuiDataType_Double, t.radii.data(), 3, 0.001f, &lo, &hi, "%.3f",
                            ImGuiSliderFlags_AlwaysClamp);
    } else {
        changed |= ImGui::DragScalarN("ring R, tube r (m)", ImGuiDataType_Double, t.radii.data(), 2, 0.001f, &lo, &hi, "%.3f",
                            ImGuiSliderFlags_AlwaysClamp);
        if (t.radii[1] >= t.radii[0]) ImGui::TextColored(ImVec4(1, 0.5f, 0.3f, 1), "the tube must be thinner than the ring");
    }
    changed |= sliderDouble("strength (voxels)", t.strength, kMinPerturbStrength, kMaxPerturbStrength, "%.2f", look, true);
    changed |= sliderDouble(keyed("scale  [ ]", "scale", look), t.perturbScale, kMinPerturbScale, kMaxPerturbScale, "%.2f", look, true);
    const bool pulls = t.perturbStrength() > 0;
    ImGui::TextDisabled("%s", pulls ? keyed("pulls (R: pushes)", "pulls", look) : keyed("pushes (R: pulls)", "pushes", look));
    return changed;
}

bool impactParameters(ToolSettings& t, const ToolWidgetLook& look) {
    constexpr const char* shapes[] = {"sphere", "V chisel", "square punch"};
    constexpr const char* spreads[] = {"uniform disc", "gaussian", "cone"};
    chooseEnum("impact", t.impactShape, shapes, look);
    bool changed = sliderDouble(keyed("size (m)  [ ]", "size (m)", look), t.impactSize, kMinImpactSize, kMaxImpactSize, "%.3f", look, true);
    changed |= sliderDouble("compaction (cm3)", t.compactionCm3, kMinCompactionCm3, kMaxCompactionCm3, "%.2f", look, true);
    chooseEnum("spread", t.spread, spreads, look);
    if (t.spread == ImpactSpread::Cone) sliderDouble("half-angle (deg)", t.spreadSize, 0.5, 60.0, "%.1f", look);
    else
        sliderDouble(t.spread == ImpactSpread::Gaussian ? "sigma (m)" : "disc radius (m)", t.spreadSize, 0.001, 2.0, "%.3f",
                     look, true);
    ImGui::SetNextItemWidth(look.fieldWidth);
    ImGui::SliderInt("count", &t.impactCount, 1, 500, "%d", ImGuiSliderFlags_Logarithmic);
    // Without a keyboard the seed is stepped; InputScalar draws - and +.
    const std::uint64_t step = 1;
    ImGui::SetNextItemWidth(look.fieldWidth);
    ImGui::InputScalar("seed", ImGuiDataType_U64, &t.seed, look.choiceWidth > 0.0f ? &step : nullptr);
    return changed;
}

// The garden file's named materials, then the built-ins it does not
// redefine (garden/scene/materials.h): what the selection may be given.
std::vector<Material> materialChoices(const Garden& garden) {
    std::vector<Material> all = garden.materials;
    for (const Material& b : builtinMaterials())
        if (std::none_of(all.begin(), all.end(), [&](const Material& m) { return m.name == b.name; })) all.push_back(b);
    return all;
}

void materialChoice(GardenSession& session, int selected, const ToolWidgetLook& look) {
    const Material& current = session.sculptures()[static_cast<std::size_t>(selected)].material;
    const std::vector<Material> choices = materialChoices(session.garden());
    const std::string shown = current.name.empty() ? "its own (" + materialKindName(current.kind) + ")" : current.name;
    ImGui::SetNextItemWidth(look.fieldWidth);
    if (ImGui::BeginCombo("material", shown.c_str())) {
        for (const Material& m : choices) {
            const bool chosen = m == current;
            if (ImGui::Selectable(m.name.c_str(), chosen) && !chosen) session.setMaterial(selected, m);
            if (chosen) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the selected sculpture's material (undoable, saved with the session)");
}

}  // namespace

bool chooseOne(const char* label, int& index, const char* const names[], int count, const ToolWidgetLook& look) {
    if (look.choiceWidth <= 0.0f) {
        ImGui::SetNextItemWidth(look.fieldWidth);
        return ImGui::Combo(label, &index, names, count);
    }
    bool changed = false;
    ImGui::PushID(label);
    for (int i = 0; i < count; ++i) {
        if (i > 0) ImGui::SameLine();
        const bool chosen = i == index;
        if (chosen) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyle().Colors[ImGuiCol_ButtonActive]);
        if (ImGui::Button(names[i], ImVec2(look.choiceWidth, 0.0f)) && !chosen) {
            index = i;
            changed = true;
        }
        if (chosen) ImGui::PopStyleColor();
    }
    ImGui::PopID();
    ImGui::SameLine();
    ImGui::TextUnformatted(label);
    return changed;
}

void toolParameters(ToolSettings& t, const ToolWidgetLook& look) {
    bool changed = false;
    switch (t.kind) {
        case Kind::Carve:
        case Kind::Add:
        case Kind::Melt:
        case Kind::Smooth:
        case Kind::Inflate: changed = strokeParameters(t, look); break;
        case Kind::Perturb: changed = perturbParameters(t, look); break;
        case Kind::Impacts: changed = impactParameters(t, look); break;
        case Kind::Sketch: {
            static const char* const kUses[] = {"auto", "new", "join", "cut", "model"};
            chooseEnum("makes", t.sketchUse, kUses, look);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("what the next outline makes (the gestures choose it too: V new, U join, arch cut, "
                                  "Z model):\nauto: joined to the sculpture it starts on, a new one when begun in "
                                  "the air\nmodel: a deformable model to shrink onto a sculpture, making a selection");
            break;
        }
        case Kind::Move:
        case Kind::None: break;
    }
    // Whatever was typed or dragged stays within the bounds the keys, the
    // wheel and the headset's stick keep too (garden/sculpt/tool_settings.h).
    if (changed) clampToolSettings(t);
    // Soft carve, smooth and impacts have no reverse.
    if (t.kind == Kind::Carve || t.kind == Kind::Add || t.kind == Kind::Perturb || t.kind == Kind::Sketch ||
        t.kind == Kind::Inflate)
        ImGui::Checkbox(keyed("reverse (R)", "reverse", look), &t.reverse);
}

// The sculpture's deformable models and selection (issue 22): the active
// model deformed by buttons as by circling gestures, the selection on or
// off, and the selected part extracted as a sculpture of its own.
void selectionOfModel(GardenSession& session, int selected, const ToolWidgetLook& look) {
    const Sculpture& s = session.sculptures()[static_cast<std::size_t>(selected)];
    const auto models = session.models();
    const auto active = std::find_if(models.begin(), models.end(), [&](const GardenSession::ModelView& m) {
        return m.name == session.activeModel() && m.sculpture == selected;
    });
    if (active != models.end()) {
        ImGui::Text("model '%s': %d iterations%s", active->name.c_str(), active->iterations,
                    active->settled ? ", settled" : "");
        const int step = static_cast<int>(GardenSession::kDeformIterationsPerTurn);
        if (ImGui::Button("shrink")) session.deformModel(active->name, true, step);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("shrink-wrap the model onto the sculpture (as circling clockwise)");
        ImGui::SameLine();
        if (ImGui::Button("grow")) session.deformModel(active->name, false, step);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("blow the model up to the surface (as circling counter-clockwise)");
    }
    // Why the last extraction failed, for the sculpture it was tried on.
    static std::string extractProblem;
    static std::string extractProblemOf;
    if (!s.selection) return;
    ImGui::Text("selection: '%s' (%zu balls)", s.selectionModel.c_str(), s.selection->balls.size());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("edits of this sculpture act only inside the selection");
    if (ImGui::Button("clear selection", ImVec2(look.choiceWidth, 0.0f))) session.selectWithModel(s.name, "");
    ImGui::SameLine();
    if (ImGui::Button("extract")) {
        extractProblem = extractPart(session, s.name, s.selectionModel, "");
        extractProblemOf = s.name;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the part inside the selection as a new sculpture beside this one");
    if (!extractProblem.empty() && extractProblemOf == s.name)
        ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", extractProblem.c_str());
}

void selectionSection(GardenSession& session, const ToolWidgetLook& look) {
    const int selected = session.selected();
    if (selected < 0) {
        ImGui::TextDisabled(look.keyHints
                                ? "no sculpture selected:\nclick one with the move tool,\nor pick it in the Garden panel"
                                : "no sculpture selected");
        return;
    }
    const Sculpture& s = session.sculptures()[static_cast<std::size_t>(selected)];
    ImGui::Text("%s%s", s.name.c_str(),
                s.morphResult() ? " (the morph result)" : s.scanned() ? " (a scanned volume)" : "");
    if (s.missing()) return;
    bool mirror = s.mirror.has_value();
    if (ImGui::Checkbox(keyed("mirror plane (M)", "mirror plane", look), &mirror))
        session.setMirror(selected, mirror ? std::optional<MirrorPlane>(centralMirror(s)) : std::nullopt);
    // The button first: where it is does not depend on the count.
    const std::size_t edits = session.editCount(selected);
    ImGui::BeginDisabled(edits == 0);
    if (ImGui::Button("discard edits", ImVec2(look.choiceWidth, 0.0f))) session.discardEdits(selected);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(s.morphResult() ? "back to the pure blend; undo (Ctrl+Z) puts the edits back"
                                          : "back to the unedited sculpture; undo (Ctrl+Z) puts the edits back");
    ImGui::SameLine();
    ImGui::Text("%zu edit%s", edits, edits == 1 ? "" : "s");
    selectionOfModel(session, selected, look);
    materialChoice(session, selected, look);
    ImGui::TextDisabled("at (%.2f, %.2f, %.2f) m\nturned %.0f deg, scale %.3g", s.placement.position[0],
                        s.placement.position[1], s.placement.position[2], s.placement.yawDegrees, s.placement.scale);
}

void drawToolPanel(GardenSession& session) {
    // A bar along the bottom left, below the stats and garden panels: the
    // tools, the tool's parameters, the selection. Kept there as it grows
    // and shrinks with the tool.
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(10.0f, io.DisplaySize.y - 10.0f), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::Begin("Tool", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
    ToolSettings& t = session.tool();
    if (ImGui::BeginTable("##tool", 3, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        for (std::size_t i = 0; i < std::size(kTools); ++i) {
            if (ImGui::RadioButton(kToolLabels[i], t.kind == kTools[i])) selectTool(t, kTools[i]);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kToolTips[i]);
        }

        ImGui::TableSetColumnIndex(1);
        toolParameters(t, kDesktopLook);
        if (t.kind == Kind::Move)
            ImGui::TextDisabled("click: select\ndrag: move on the ground\nShift+drag, or drag the ring: turn\n"
                                "[ ] or the wheel: scale");
        else if (t.kind == Kind::None)
            ImGui::TextDisabled("the left button picks the blend\non the ground triangle");
        else if (t.kind == Kind::Sketch) {
            ImGui::TextDisabled("hold the button on a sculpture\nand draw round; let go: %s", t.reverse ? "cut" : "joined");
            ImGui::TextDisabled("middle button: draw a gesture");
            if (!session.gestureMessage().empty())
                ImGui::TextColored(ImVec4(0.6f, 0.85f, 1.0f, 1.0f), "%s", session.gestureMessage().c_str());
            if (!session.sketchMessage().empty())
                ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", session.sketchMessage().c_str());
        } else if (!session.toolMessage().empty()) {
            ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", session.toolMessage().c_str());
        }

        ImGui::TableSetColumnIndex(2);
        selectionSection(session, kDesktopLook);
        ImGui::Spacing();
        if (ImGui::Button("undo (Ctrl+Z)")) session.undo();
        ImGui::SameLine();
        if (ImGui::Button("redo (Ctrl+Shift+Z)")) session.redo();
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace hg::garden
