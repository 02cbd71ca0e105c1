#include "xr/hand_panel_ui.h"

#include <optional>

#include "garden/app/garden_session.h"
#include "garden/render/morph_triangle.h"
#include "garden/render/panels.h"
#include "garden/render/tool_panel.h"
#include "xr/hand_panel.h"

#include <imgui.h>

#include <algorithm>
#include <iterator>

namespace hg::xr {

namespace {

using Kind = garden::ToolSettings::Kind;

// Two rows of six buttons across the top (the tools, undo, redo), a row
// of page buttons, then the page.
constexpr int kButtonColumns = 6;
constexpr float kCellX = static_cast<float>(kPanelPixelsX) / kButtonColumns, kCellY = 40.0f, kButtonInset = 4.0f;
constexpr float kTop = 4.0f;
constexpr float kPageCellX = kPanelPixelsX / 4.0f, kPageCellY = 30.0f;
constexpr float kPagesY = kTop + 2.0f * kCellY;
constexpr float kBodyY = kPagesY + kPageCellY + 4.0f;
constexpr float kMorphX = 300.0f, kMorphSide = 120.0f;
// ImGui's built-in font (ProggyClean) is 13 pixels high: the morph
// triangle's labels take a line above and below it. Frames are padded to
// 21 pixels, a row of them is 25: taller targets for a ray than the
// desktop's.
constexpr float kFontLine = 13.0f;
constexpr float kFramePadX = 6.0f, kFramePadY = 4.0f, kSpacingX = 8.0f, kSpacingY = 4.0f, kGrabMin = 12.0f;
constexpr float kFrame = kFontLine + 2.0f * kFramePadY;
constexpr float kRow = kFrame + kSpacingY;
constexpr float kTextRow = kFontLine + kSpacingY;
constexpr float kToggleStep = 130.0f;
constexpr float kUndoSelectedWidth = 220.0f;
constexpr garden::ToolWidgetLook kLook{220.0f, false, 104.0f};

constexpr const char* kLabels[] = {"morph", "carve",  "add",    "soft carve", "perturb", "impacts",
                                   "move",  "sketch", "smooth", "inflate",    "undo",    "redo"};
static_assert(std::size(kLabels) == static_cast<std::size_t>(PanelButton::Count));
constexpr const char* kPageLabels[] = {"tool", "sculpture", "settings", "history"};
static_assert(std::size(kPageLabels) == static_cast<std::size_t>(PanelPage::Count));
constexpr const char* kSnapLabels[] = {"15 deg", "30 deg", "45 deg", "90 deg"};
static_assert(std::size(kSnapLabels) == std::size(kSnapAngles));

glm::vec2 buttonTopLeft(PanelButton b) {
    const int i = static_cast<int>(b);
    return glm::vec2(static_cast<float>(i % kButtonColumns) * kCellX + kButtonInset,
                     kTop + static_cast<float>(i / kButtonColumns) * kCellY);
}
const glm::vec2 kButtonSize(kCellX - 2.0f * kButtonInset, kCellY - 2.0f * kButtonInset);
const glm::vec2 kPageButtonSize(kPageCellX - 2.0f * kButtonInset, kPageCellY - 2.0f * kButtonInset);

// The top of a page's row of frames.
float rowTop(int row) { return kBodyY + static_cast<float>(row) * kRow; }

// Board pixels to board point.
glm::vec2 board(const glm::vec2& pixels) { return pixels / glm::vec2(kPanelPixelsX, kPanelPixelsY); }

// The centre of a frame `width` wide at `x` in a row whose top is `top`.
glm::vec2 frameCenter(float x, float top, float width) { return board(glm::vec2(x + 0.5f * width, top + 0.5f * kFrame)); }

// The seated height slider's place: the settings page's fourth row.
constexpr int kSeatedOffsetRow = 3;

Kind toolOf(PanelButton b) {
    switch (b) {
        case PanelButton::Carve: return Kind::Carve;
        case PanelButton::Add: return Kind::Add;
        case PanelButton::Melt: return Kind::Melt;
        case PanelButton::Perturb: return Kind::Perturb;
        case PanelButton::Impacts: return Kind::Impacts;
        case PanelButton::Move: return Kind::Move;
        case PanelButton::Sketch: return Kind::Sketch;
        case PanelButton::Smooth: return Kind::Smooth;
        case PanelButton::Inflate: return Kind::Inflate;
        default: return Kind::None;
    }
}

// A button lit while `chosen`.
bool litButton(const char* label, const glm::vec2& size, bool chosen) {
    if (chosen) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyle().Colors[ImGuiCol_ButtonActive]);
    const bool pressed = ImGui::Button(label, ImVec2(size.x, size.y));
    if (chosen) ImGui::PopStyleColor();
    return pressed;
}

}  // namespace

glm::vec2 panelButtonCenter(PanelButton b) { return board(buttonTopLeft(b) + 0.5f * kButtonSize); }

const char* panelButtonLabel(PanelButton b) {
    const int i = static_cast<int>(b);
    return i >= 0 && i < static_cast<int>(std::size(kLabels)) ? kLabels[i] : "";
}

glm::vec2 panelMorphPoint(const glm::vec3& weights) {
    const garden::MorphTriangleLayout l = garden::morphTriangleLayout(glm::vec2(kMorphX, kBodyY), kMorphSide, kFontLine);
    return board(garden::triangleToScreen(l, garden::trianglePoint(weights)));
}

glm::vec2 panelPageCenter(PanelPage p) {
    return board(glm::vec2(static_cast<float>(p) * kPageCellX + 0.5f * kPageCellX, kPagesY + 0.5f * kPageCellY));
}

glm::vec2 panelToggleCenter(PanelToggle t) {
    switch (t) {
        case PanelToggle::LeftHanded: return frameCenter(kButtonInset, rowTop(0), kFrame);
        case PanelToggle::Seated: return frameCenter(kButtonInset + kToggleStep, rowTop(0), kFrame);
        case PanelToggle::SmoothTurn: return frameCenter(kButtonInset, rowTop(1), kFrame);
        // Below the sculpture buttons and the selection's name.
        case PanelToggle::Mirror: return frameCenter(kButtonInset, rowTop(1) + kTextRow, kFrame);
    }
    return {};
}

glm::vec2 panelChoiceCenter(PanelChoice c, int option) {
    // The rows of the parameters before the choice (tool_panel.cpp's order).
    const int row = c == PanelChoice::ImpactSpread ? 3 : c == PanelChoice::SnapAngle ? 2 : 0;
    const float x = kButtonInset + static_cast<float>(option) * (kLook.choiceWidth + kSpacingX);
    return frameCenter(x, rowTop(row), kLook.choiceWidth);
}

glm::vec2 panelActionCenter(PanelAction a) {
    switch (a) {
        case PanelAction::PreviousSculpture: return frameCenter(kButtonInset, rowTop(0), kLook.choiceWidth);
        case PanelAction::NextSculpture:
            return frameCenter(kButtonInset + kLook.choiceWidth + kSpacingX, rowTop(0), kLook.choiceWidth);
        // Below the name and the mirror plane.
        case PanelAction::DiscardEdits: return frameCenter(kButtonInset, rowTop(2) + kTextRow, kLook.choiceWidth);
        case PanelAction::UndoSelected: return frameCenter(kButtonInset, rowTop(0), kUndoSelectedWidth);
    }
    return {};
}

glm::vec2 panelSeatedOffsetPoint(double metres) {
    // ImGui's slider: the grab's centre runs from half a grab (and its
    // 2-pixel padding) inside one end to the same inside the other.
    const float grabPadding = 2.0f, t = static_cast<float>(metres / kMaxSeatedHeightOffset);
    const float from = kButtonInset + grabPadding + 0.5f * kGrabMin;
    const float span = kLook.fieldWidth - 2.0f * grabPadding - kGrabMin;
    return board(glm::vec2(from + t * span, rowTop(kSeatedOffsetRow) + 0.5f * kFrame));
}

HandPanelUi::HandPanelUi() : board_(kPanelPixelsX, kPanelPixelsY) {
    garden::UiBoard::Current current(board_);
    ImGuiStyle& style = ImGui::GetStyle();
    style.Colors[ImGuiCol_WindowBg] = ImVec4(0.12f, 0.10f, 0.20f, 1.0f);  // opaque: read on any sky
    style.FramePadding = ImVec2(kFramePadX, kFramePadY);
    style.ItemSpacing = ImVec2(kSpacingX, kSpacingY);
    style.GrabMinSize = kGrabMin;
}

bool HandPanelUi::update(garden::GardenSession& session, const HandPanel& panel, const std::string& profile,
                         XrUserSettings& user, float dt) {
    garden::UiBoard::Current current(board_);
    const std::optional<glm::vec2> uv = panel.hovered();
    board_.newFrame(uv ? std::optional<glm::vec2>(*uv * glm::vec2(kPanelPixelsX, kPanelPixelsY)) : std::nullopt,
                    panel.pressing(), dt);
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(io.DisplaySize);
    ImGui::Begin("hand panel", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                            ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollWithMouse);
    garden::ToolSettings& t = session.tool();
    for (int i = 0; i < static_cast<int>(PanelButton::Count); ++i) {
        const auto b = static_cast<PanelButton>(i);
        const glm::vec2 p = buttonTopLeft(b);
        ImGui::SetCursorPos(ImVec2(p.x, p.y));
        if (!litButton(kLabels[i], kButtonSize, b < PanelButton::Undo && t.kind == toolOf(b))) continue;
        if (b == PanelButton::Undo) session.undo();
        else if (b == PanelButton::Redo) session.redo();
        else {
            selectTool(t, toolOf(b));
            page_ = PanelPage::Tool;  // the tool's parameters
        }
    }
    for (int i = 0; i < static_cast<int>(PanelPage::Count); ++i) {
        const auto page = static_cast<PanelPage>(i);
        ImGui::SetCursorPos(ImVec2(static_cast<float>(i) * kPageCellX + kButtonInset, kPagesY + kButtonInset));
        if (litButton(kPageLabels[i], kPageButtonSize, page == page_)) page_ = page;
    }

    bool changed = false;
    switch (page_) {
        case PanelPage::Tool: toolPage(session); break;
        case PanelPage::Sculpture: sculpturePage(session); break;
        case PanelPage::Settings: changed = settingsPage(profile, user); break;
        case PanelPage::History: historyPage(session); break;
        case PanelPage::Count: break;
    }
    ImGui::End();
    // Over the bottom of the board, where the tool hand's user looks: work
    // that is not on disk.
    garden::drawSaveBanner(session, {0.0f, io.DisplaySize.y * 0.62f}, io.DisplaySize.x);
    board_.render();
    return changed;
}

void HandPanelUi::toolPage(garden::GardenSession& session) {
    garden::ToolSettings& t = session.tool();
    ImGui::SetCursorPos(ImVec2(kButtonInset, kBodyY));
    ImGui::BeginGroup();
    garden::toolParameters(t, kLook);
    if (t.kind == Kind::None) ImGui::TextDisabled("the trigger picks the blend\non the ground triangle,\nor here");
    else if (t.kind == Kind::Move)
        ImGui::TextDisabled("the trigger on a sculpture\nselects and drags it,\non its ring turns it;\ntool stick up, down: its scale");
    else if (t.kind == Kind::Sketch) {
        // The gesture button is the other hand's trigger (xr/controllers.cpp).
        ImGui::TextDisabled("other trigger held: draw a gesture\n(V new, U join, arch cut, Z model;\ncircle to shrink or grow it)");
        if (!session.gestureMessage().empty()) ImGui::TextWrapped("%s", session.gestureMessage().c_str());
        if (!session.sketchMessage().empty()) ImGui::TextWrapped("%s", session.sketchMessage().c_str());
    } else ImGui::TextDisabled("tool stick: size, strength");
    ImGui::EndGroup();
    if (t.kind != Kind::None) return;

    ImGui::SetCursorPos(ImVec2(kMorphX, kBodyY));
    if (session.hasMorph()) {
        // Drawn from the session's weights each frame: a pick on the ground
        // shows here at once (garden/render/morph_panel.cpp).
        glm::vec2 point = garden::morphSelectorPoint(session);
        const garden::MorphSpec& m = *session.morphSpec();  // the active morph's (selecting a result picks it)
        const char* labels[3] = {m.sources[0].c_str(), m.sources[1].c_str(), m.sources[2].c_str()};
        if (garden::morphTriangleWidget(labels, point, kMorphSide)) {
            const glm::vec3 b = garden::triangleWeights(point);
            session.setMorphBarycentric({b.x, b.y, b.z});
        }
    } else {
        ImGui::TextDisabled("no morph in this garden");
    }
}

void HandPanelUi::sculpturePage(garden::GardenSession& session) {
    // The move tool selects what the tool hand points at; the buttons step
    // through the garden's sculptures too.
    const int count = static_cast<int>(session.sculptures().size());
    const glm::vec2 size(kLook.choiceWidth, kFrame);
    ImGui::SetCursorPos(ImVec2(kButtonInset, rowTop(0)));
    ImGui::BeginGroup();
    if (ImGui::Button("< previous", ImVec2(size.x, size.y)) && count > 0)
        session.select(session.selected() <= 0 ? count - 1 : session.selected() - 1);
    ImGui::SameLine();
    if (ImGui::Button("next >", ImVec2(size.x, size.y)) && count > 0) session.select((session.selected() + 1) % count);
    garden::selectionSection(session, kLook);
    ImGui::EndGroup();
}

// The desktop's history panel (H) in the headset (issue 23): the global
// undo and redo are the buttons above; here the selected sculpture's last
// action alone, and the list of what was done.
void HandPanelUi::historyPage(garden::GardenSession& session) {
    const int selected = session.selected();
    ImGui::SetCursorPos(ImVec2(kButtonInset, rowTop(0)));
    ImGui::BeginDisabled(selected < 0);
    const std::string own = selected >= 0
                                ? "undo on " + session.sculptures()[static_cast<std::size_t>(selected)].name
                                : std::string("undo on the selection");
    if (ImGui::Button(own.c_str(), ImVec2(kUndoSelectedWidth, kFrame))) session.undoSculpture(selected);
    ImGui::EndDisabled();
    ImGui::SetCursorPos(ImVec2(kButtonInset, rowTop(1)));
    ImGui::BeginGroup();
    garden::historyList(session);
    ImGui::EndGroup();
}

bool HandPanelUi::settingsPage(const std::string& profile, XrUserSettings& user) {
    bool changed = false;
    ImGui::SetCursorPos(ImVec2(kButtonInset, rowTop(0)));
    changed |= ImGui::Checkbox("left-handed", &user.leftHanded);
    ImGui::SetCursorPos(ImVec2(kButtonInset + kToggleStep, rowTop(0)));
    changed |= ImGui::Checkbox("seated", &user.seated);
    ImGui::SetCursorPos(ImVec2(kButtonInset, rowTop(1)));
    changed |= ImGui::Checkbox("smooth turning", &user.smoothTurn);

    ImGui::SetCursorPos(ImVec2(kButtonInset, rowTop(2)));
    const auto snap = std::find(std::begin(kSnapAngles), std::end(kSnapAngles), user.snapDegrees);
    int chosen = static_cast<int>(snap - std::begin(kSnapAngles));
    ImGui::BeginDisabled(user.smoothTurn);
    if (garden::chooseOne("snap", chosen, kSnapLabels, static_cast<int>(std::size(kSnapLabels)), kLook)) {
        user.snapDegrees = kSnapAngles[chosen];
        changed = true;
    }
    ImGui::EndDisabled();

    ImGui::SetCursorPos(ImVec2(kButtonInset, rowTop(kSeatedOffsetRow)));
    ImGui::SetNextItemWidth(kLook.fieldWidth);
    const double lo = 0.0, hi = kMaxSeatedHeightOffset;
    // Written when let go, not at every step of a drag.
    ImGui::SliderScalar("seated raise (m)", ImGuiDataType_Double, &user.seatedHeightOffset, &lo, &hi, "%.2f",
                        ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::IsItemDeactivatedAfterEdit();

    ImGui::SetCursorPos(ImVec2(kButtonInset, rowTop(kSeatedOffsetRow + 1)));
    ImGui::TextDisabled("%s", profile.empty() ? "no interaction profile yet" : profile.c_str());
    return changed;
}

void HandPanelUi::draw(const HandPanel& panel, const glm::mat4& viewProjection) const {
    if (panel.shown()) board_.draw(panel.corners(), viewProjection);
}

}  // namespace hg::xr
