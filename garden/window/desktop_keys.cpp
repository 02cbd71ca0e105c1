#include "garden/window/desktop_keys.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>

#include "garden/app/garden_session.h"
#include "garden/app/tool_intents.h"
#include "garden/action/action_sink.h"
#include "garden/render/key_table.h"

namespace hg::garden {

bool addKeyPress(DesktopKeys& keys, int key, int mods) {
    const std::optional<KeyCommand> c = keyCommand(key, mods);
    if (!c) return false;
    using K = ToolSettings::Kind;
    switch (*c) {
        case KeyCommand::ToolNone: keys.tool = K::None; return true;
        case KeyCommand::ToolCarve: keys.tool = K::Carve; return true;
        case KeyCommand::ToolAdd: keys.tool = K::Add; return true;
        case KeyCommand::ToolMelt: keys.tool = K::Melt; return true;
        case KeyCommand::ToolPerturb: keys.tool = K::Perturb; return true;
        case KeyCommand::ToolImpacts: keys.tool = K::Impacts; return true;
        case KeyCommand::ToolMove: keys.tool = K::Move; return true;
        case KeyCommand::ToolSketch: keys.tool = K::Sketch; return true;
        case KeyCommand::ToolSmooth: keys.tool = K::Smooth; return true;
        case KeyCommand::ToolInflate: keys.tool = K::Inflate; return true;
        case KeyCommand::Smaller: --keys.sizeSteps; return true;
        case KeyCommand::Larger: ++keys.sizeSteps; return true;
        case KeyCommand::Reverse: keys.reverse = !keys.reverse; return true;
        case KeyCommand::Mirror: keys.mirror = !keys.mirror; return true;
        case KeyCommand::Undo: keys.undo = true; return true;
        case KeyCommand::Redo: keys.redo = true; return true;
        case KeyCommand::UndoSelected: keys.undoSelected = true; return true;
        case KeyCommand::History: keys.history = true; return true;
        case KeyCommand::Fly: keys.fly = true; return true;
        case KeyCommand::Orbit: keys.orbit = true; return true;
        case KeyCommand::Detail: keys.detail = true; return true;
        case KeyCommand::Headset: keys.headset = true; return true;
        case KeyCommand::Screenshot: keys.screenshot = true; return true;
        case KeyCommand::Escape: keys.escape = true; return true;
        case KeyCommand::FrameGarden: keys.frameGarden = true; return true;
        case KeyCommand::Help: keys.help = true; return true;
        case KeyCommand::Stats: keys.stats = true; return true;
        case KeyCommand::ClayView: keys.clayView = !keys.clayView; return true;
        case KeyCommand::Wireframe: keys.wireframe = !keys.wireframe; return true;
        // Held keys are polled (heldKey), not pressed.
        case KeyCommand::Forward: case KeyCommand::Back: case KeyCommand::Left: case KeyCommand::Right:
        case KeyCommand::Down: case KeyCommand::Up: case KeyCommand::Turn: return false;
    }
    return false;
}

EscapeDoes escapeDoes(bool popupOpen, bool helpOpen, bool unsaved) {
    if (popupOpen) return EscapeDoes::ClosePopup;
    if (helpOpen) return EscapeDoes::CloseHelp;
    return unsaved ? EscapeDoes::AskToQuit : EscapeDoes::Quit;
}

bool popupOpen() { return ImGui::GetCurrentContext() && ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId); }

void closePopups() {
    // ImGui closes its pop-ups on Esc only with keyboard navigation, which
    // would take the garden's keys.
    if (popupOpen()) ImGui::ClosePopupToLevel(0, true);
}

bool unsavedWork(const GardenSession& session) {
    if (const JournalSink* j = session.journal()) return !j->saveStatus().saved();
    return session.actionsRecorded() > 0;
}

std::string unsavedWhat(const GardenSession& session) {
    if (const JournalSink* j = session.journal()) {
        const SaveStatus st = j->saveStatus();
        return st.headline() + (st.reason.empty() ? "" : "\n" + st.reason);
    }
    const std::size_t n = session.actionsRecorded();
    return std::to_string(n) + (n == 1 ? " action" : " actions") +
           " made in this run will be lost: this garden is not open in a session folder (hypergarden --session DIR "
           "keeps every action).";
}

ToolIntents desktopIntents(const DesktopKeys& keys, float& wheel, const GardenSession& session, double dt,
                           DesktopCarry& carry) {
    ToolIntents intents;
    if (keys.tool) intents.tool = toolChoiceOf(*keys.tool);
    intents.reverse = keys.reverse;
    if (keys.mirror) intents.mirror = MirrorIntent::Toggle;
    if (keys.sizeSteps != 0) intents.size = std::pow(kToolSizeStep, keys.sizeSteps);
    carry.sinceScaleStep += dt;
    const ToolSettings::Kind kind = keys.tool ? *keys.tool : session.tool().kind;
    if (kind == ToolSettings::Kind::Move && session.selected() >= 0) {
        if (wheel != 0.0f) intents.selectionScale = std::pow(kToolSizeStep, static_cast<double>(wheel));
        if (wheel != 0.0f || keys.sizeSteps != 0) carry.sinceScaleStep = 0.0;
        wheel = 0.0f;
        intents.held = carry.sinceScaleStep < kScaleBurstSeconds;
    }
    return intents;
}

Hands desktopHands(DesktopInput in, const DesktopKeys& keys, const GardenSession& session, const glm::mat4& projection,
                   double dt, DesktopCarry& carry) {
    const ToolIntents intents = desktopIntents(keys, in.wheel, session, dt, carry);
    in.undo = keys.undo;
    in.redo = keys.redo;
    in.flyToggle = keys.fly;
    in.orbitToggle = keys.orbit;
    Hands hands = mapDesktop(in, session.view(), projection, DesktopMapping{}, carry.speed);
    hands.intents = intents;
    carry.speed = hands.speedScale;
    return hands;
}

}  // namespace hg::garden
