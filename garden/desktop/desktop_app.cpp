#include "garden/desktop/desktop_app.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>

#include "garden/app/garden_session.h"
#include "garden/app/tool_defaults.h"
#include "garden/window/desktop_keys.h"
#include "garden/desktop/add_panel.h"
#include "garden/desktop/desktop_settings.h"
#include "garden/desktop/export_panel.h"
#include "garden/window/garden_view.h"
#include "garden/window/garden_window.h"
#include "garden/desktop/panel_layout.h"
#include "garden/desktop/recent_sessions.h"
#include "garden/desktop/session_panel.h"
#include "garden/desktop/view_framing.h"
#include "garden/hands/desktop_hands.h"
#include "garden/render/garden_ground.h"
#include "garden/render/gl_context.h"
#include "garden/render/key_table.h"
#include "garden/render/overlay.h"
#include "garden/render/panels.h"
#include "garden/render/quality_governor.h"
#include "garden/render/screenshot.h"
#include "garden/render/tool_gizmo.h"
#include "garden/session/open_session.h"
#include "garden/session/session_view.h"

namespace hg::garden {

namespace {

// What F12 did, shown at the bottom of the window for a few seconds.
struct Notice {
    std::string text;
    bool error = false;
    std::chrono::steady_clock::time_point until{};
};

void drawNotice(const Notice& n, glm::ivec2 fb) {
    if (n.text.empty() || std::chrono::steady_clock::now() > n.until) return;
    ImGui::SetNextWindowPos(ImVec2(0.5f * static_cast<float>(fb.x), static_cast<float>(fb.y) - 10.0f), ImGuiCond_Always,
                            ImVec2(0.5f, 1.0f));
    ImGui::Begin("##notice", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
    if (n.error) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.35f, 1.0f), "%s", n.text.c_str());
    else ImGui::TextUnformatted(n.text.c_str());
    ImGui::End();
}

std::string timestampedName(const std::string& dir) {
    const std::time_t t = std::time(nullptr);
    char name[64];
    std::strftime(name, sizeof name, "hypergarden-%Y%m%d-%H%M%S.png", std::localtime(&t));
    return (std::filesystem::path(dir) / name).string();
}

// The side panel: the garden, what is missing, the morph selector, the
// clay view and wireframe switches.
// `headset`: the Headset button is shown (true when pressed), with the
// last headset message under it.
bool gardenPanel(GardenSession& session, ViewLook& look, bool headset, const std::string& headsetMessage,
                 AddPanel& addPanel) {
    // Top right: the stats panel takes the top left.
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - 10.0f, 10.0f), ImGuiCond_FirstUseEver, ImVec2(1.0f, 0.0f));
    ImGui::Begin("Garden", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::Text("%s", session.garden().name.empty() ? session.garden().file.c_str() : session.garden().name.c_str());
    const char* mode[] = {"walk", "fly", "orbit"};
    ImGui::Text("%s at (%.1f, %.1f, %.1f)", mode[static_cast<int>(session.navigator().mode())],
                static_cast<double>(session.navigator().eye().x), static_cast<double>(session.navigator().eye().y),
                static_cast<double>(session.navigator().eye().z));
    // Select a sculpture to orbit it (O).
    if (ImGui::BeginListBox("##sculptures", ImVec2(300, 6 * ImGui::GetTextLineHeightWithSpacing()))) {
        for (std::size_t i = 0; i < session.sculptures().size(); ++i) {
            const Sculpture& s = session.sculptures()[i];
            if (s.removed) continue;
            if (s.loading) {
                ImGui::TextDisabled("%s (loading)", s.name.c_str());
                continue;
            }
            if (s.missing()) {
                ImGui::TextColored(ImVec4(1, 0.35f, 0.3f, 1), "%s (missing)", s.name.c_str());
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.error.c_str());
                continue;
            }
            if (ImGui::Selectable(s.name.c_str(), session.selected() == static_cast<int>(i)))
                session.select(session.selected() == static_cast<int>(i) ? -1 : static_cast<int>(i));
            if (!s.sourceProblem.empty()) {
                // Its file as it is now is not shown: the last good one is.
                ImGui::SameLine();
                ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "(file not read again)");
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.sourceProblem.c_str());
            }
        }
        ImGui::EndListBox();
    }
    if (const std::size_t n = session.sculpturesLoading())
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "loading %zu sculpture%s, nearest first", n, n == 1 ? "" : "s");
    ImGui::TextDisabled("O orbits the selection, G puts the detail sphere where the mouse points");
    drawMorphSection(session);
    bool lod = session.settings().lod;
    if (ImGui::Checkbox("level of detail", &lod)) session.settings().lod = lod;
    ImGui::Checkbox("clay view (C)", &look.clay);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("every sculpture in one neutral matte material, to judge its form");
    ImGui::SameLine();
    ImGui::BeginDisabled(!look.clay);
    ImGui::Checkbox("cavity", &look.cavity);
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("in the clay view, grooves darkened and ridges lightened by the surface's curvature");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::Checkbox("wireframe (X)", &look.wireframe);
    addPanel.draw(session);
    bool enter = false;
    if (headset) {
        enter = ImGui::Button("Headset (F9)");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("this garden in the OpenXR headset; back here when its session ends");
        if (!headsetMessage.empty()) ImGui::TextWrapped("%s", headsetMessage.c_str());
    }
    ImGui::End();
    return enter;
}

// The window as the frame's view sink: uploads through the garden view,
// draws with the loop's own function (it needs the loop's state: the
// mouse's ray, the keys, the panels).
class WindowView final : public ViewSink {
public:
    WindowView(GardenView& view, std::function<ViewDraw(GardenSession&)> draw) : view_(view), draw_(std::move(draw)) {}
    ViewUpload upload(GardenSession& session, double allowanceMs) override { return view_.upload(session, allowanceMs); }
    ViewDraw render(GardenSession& session) override { return draw_(session); }

private:
    GardenView& view_;
    std::function<ViewDraw(GardenSession&)> draw_;
};

std::string desktopTitle(const DesktopOptions& options) { return "Hypergarden - " + options.garden; }

// The headset takes the garden as it stands: what the hands were doing is
// finished first (journalled), and the desktop gets back its own view,
// frame budget and window when the headset session ends.
void enterHeadset(GardenSession& session, GardenWindow& window, const DesktopOptions& options, std::string& message) {
    session.endStroke();
    session.endLiveMove();
    const Navigator desktopView = session.navigator();
    const double budgetMs = session.scheduler().settings().budgetMs;
    message.clear();
    const HeadsetReturn r = options.headset(session, window, message);
    if (!message.empty()) std::cerr << message << "\n";
    session.navigator() = desktopView;
    session.scheduler().setBudgetMs(budgetMs);
    window.window().makeCurrent();
    window.window().setTitle(desktopTitle(options));
    window.window().setVsync(options.vsync);
    window.events() = WindowEvents{};
    if (r == HeadsetReturn::Quit) window.window().setShouldClose(true);
}

// A session opens where it was left (its view.json), remembered among the
// recent sessions; else, and without a session, at the garden's start. The
// tools start sized to the sculpture in view.
void startView(OpenedSession& opened, const std::string& dir, SessionPanel& panel) {
    if (opened.recorder) {
        panel.opened(dir);
        std::string warning;
        std::optional<ToolSettings> tool;
        std::optional<std::string> panels;
        readSessionView(dir, opened.session->navigator(), warning, &tool, &panels);
        if (!warning.empty()) std::cerr << "warning: " << warning << "\n";
        if (panels) restorePanelLayout(*panels);
        // The tool as it was left, its sizes too.
        if (tool) {
            opened.session->tool() = *tool;
            return;
        }
    }
    sizeToolsToView(*opened.session);
}

}  // namespace

std::string screenshotFolder(const DesktopOptions& options) {
    std::filesystem::path dir = options.screenshotDir;
    if (dir.empty()) {
        const char* home = std::getenv("HOME");
        dir = !options.session.empty() ? std::filesystem::path(options.session) / "screenshots"
              : home && *home        ? std::filesystem::path(home) / "Pictures" / "hypergarden"
                                     : std::filesystem::path(".");
    }
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);  // a failure shows when the file is written
    return dir.string();
}

int runDesktopGarden(const DesktopOptions& options) {
    std::optional<GardenLoad> load;
    if (options.session.empty()) {
        load = loadGarden(options.garden);
        if (!load->ok()) {
            std::cerr << "error: " << load->error << "\n";
            return 2;
        }
    }
    try {
        WindowOptions wo;
        wo.width = options.width;
        wo.height = options.height;
        wo.vsync = options.vsync;
        wo.title = desktopTitle(options);
        GardenWindow window(wo);

        SessionSettings settings;
        settings.scheduler.budgetMs = options.budgetMs;
        settings.memoryBudgetBytes = options.memoryBudgetBytes;
        settings.viewportHeight = window.window().framebufferSize().y;
        // The window opens at once; sculptures arrive nearest first and the
        // Garden panel says how many are still coming.
        settings.progressiveLoading = true;
        settings.workOffFrameThread = true;  // vsync paces the frames; the workers mesh and blend meanwhile
        settings.spreadEdits = true;           // a big edit lands over a few frames, none held
        OpenedSession opened = openLoadedOrSession(
            std::move(load), {options.session, options.garden, options.gardenGiven, "hypergarden (desktop)"}, settings);
        if (!opened.error.empty()) {
            std::cerr << "error: " << opened.error << "\n";
            return opened.exitStatus;
        }
        DesktopOptions here = options;  // here.session: the folder open now
        SessionPanel sessionPanel(options.recentSessionsPath ? *options.recentSessionsPath : recentSessionsPath());
        for (;;) {
            for (const std::string& m : openedMessages(opened)) std::cerr << m << "\n";
            startView(opened, here.session, sessionPanel);
            reportSaveChangesOnStderr(opened);
            DesktopSessionLink link{opened.recorder.get(), &sessionPanel, ""};
            const int status = runDesktopOn(*opened.session, window, here, &link);
            // The view goes with the session, for its next opening.
            if (opened.recorder)
                if (const std::string panels = panelLayout(), why = writeSessionView(here.session, opened.session->navigator(),
                                                                                      &opened.session->tool(), &panels);
                    !why.empty())
                    std::cerr << "warning: the view is not kept: " << why << "\n";
            if (link.goTo.empty() || status != 0) {
                std::vector<std::string> last;
                const int saved = closeSession(opened, last);
                for (const std::string& line : last) std::cerr << line << "\n";
                return status != 0 ? status : saved;
            }
            // Another folder: opened before this one closes, so that a
            // refusal leaves the user where they were.
            OpenedSession next = openSession({link.goTo, here.garden, false, "hypergarden (desktop)"}, settings);
            if (!next.error.empty()) {
                std::cerr << "error: " << next.error << "\n";
                sessionPanel.setStatus("cannot open " + link.goTo + ": " + next.error, true);
                continue;
            }
            std::vector<std::string> last;
            closeSession(opened, last);
            for (const std::string& line : last) std::cerr << line << "\n";
            opened = std::move(next);
            here.session = link.goTo;
        }
    } catch (const GlError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}

void showAsDesktop(GardenWindow& window, const DesktopOptions& options) {
    window.window().setTitle(desktopTitle(options));
    window.window().setSize(glm::ivec2(options.width, options.height));
    window.window().setVsync(options.vsync);
}

DesktopEntry desktopAfterHeadset(DesktopOptions options) {
    return [options](GardenSession& session, GardenWindow& window) {
        showAsDesktop(window, options);
        return runDesktopOn(session, window, options);
    };
}

int runDesktopOn(GardenSession& session, GardenWindow& gardenWindow, const DesktopOptions& options,
                 DesktopSessionLink* link) {
    GlWindow& window = gardenWindow.window();
    Overlay& overlay = *gardenWindow.overlay();
    bool showHelp = false;  // the key list (F1)
    bool showHistory = false;  // the history panel (H)
    // The first-run overlay, until the user dismisses it (then remembered).
    const std::string settingsPath = options.settingsPath ? *options.settingsPath : desktopSettingsPath();
    std::string settingsWarning;
    DesktopUserSettings userSettings = loadDesktopSettings(settingsPath, settingsWarning);
    if (!settingsWarning.empty()) std::cerr << "warning: " << settingsWarning << "\n";
    bool firstRun = !userSettings.firstRunDone;
    const auto firstRunDismissed = [&] {
        firstRun = false;
        userSettings.firstRunDone = true;
        if (const std::string why = saveDesktopSettings(settingsPath, userSettings); !why.empty())
            std::cerr << "warning: the first-run overlay will show again: " << why << "\n";
    };
    bool askQuit = false, quitConfirmed = false;  // Esc or the close button with work not saved
    Renderer& renderer = gardenWindow.renderer();
    // --quality auto: the renderer's preset as the ceiling, then stepped
    // down and up by the GPU's measured time against the monitor's period.
    std::optional<QualityGovernor> governor;
    // The rung in use, and what a still view of it sharpens to.
    const auto useTheGovernorsQuality = [&] {
        renderer.setQuality(governor->quality());
        renderer.setStillQualities(governor->stillQualities());
    };
    if (options.autoQuality) {
        const GLFWvidmode* mode = glfwGetVideoMode(glfwGetPrimaryMonitor());
        const double hz = mode && mode->refreshRate > 0 ? mode->refreshRate : 60.0;
        governor.emplace(rendererPreset(GlWindow::glVersionString()), 1000.0 / hz);
        useTheGovernorsQuality();
    } else {
        renderer.setQuality(options.quality);
    }
    // A still view shows the picture held, not drawn again, and sharpens
    // when the automatic mode is below the ceiling (docs/rendering.md, "A
    // still view").
    renderer.setPictureReuse(true);
    GardenView& view = gardenWindow.view();
    view.setImpostorDistance(options.impostorDistance);
    WindowEvents& events = gardenWindow.events();
    events = WindowEvents{};
    // Exports go next to the session, or into the working folder without one.
    ExportPanel exportPanel(options.session);
    MemoryWatch memoryWatch(std::chrono::milliseconds(2000));  // the stats panel's memory lines
    AddPanel addPanel;
    Notice notice;
    std::string headsetMessage;

    DesktopCarry carry;  // the walking speed, the wheel burst
    glm::ivec2 fb(1);
    const float fovY = static_cast<float>(session.settings().fovY);
    std::optional<Pose> aim;  // the mouse's ray, unless a panel has the mouse
    DesktopKeys pressed;      // this frame's keys, unless a panel has the keyboard
    bool headsetButton = false;
    // The window's view: the garden, the tool where the mouse points, a
    // screenshot when asked (F12), then the panels over it.
    WindowView views(view, [&](GardenSession&) {
        view.render(session, fb, fovY);
        drawToolGizmos(renderer, session, aim);
        const RenderStats r = renderer.endFrame();
        if (pressed.screenshot) {
            const std::string path = timestampedName(screenshotFolder(options));
            const std::string why = writeFramebufferPng(path, fb.x, fb.y);
            std::cerr << (why.empty() ? "screenshot: " + path : "error: " + why) << "\n";
            notice = {why.empty() ? "screenshot saved: " + path : "no screenshot: " + why, !why.empty(),
                      std::chrono::steady_clock::now() + std::chrono::seconds(5)};
        }
        overlay.newFrame();
        headsetButton = gardenPanel(session, view.look(), static_cast<bool>(options.headset), headsetMessage, addPanel);
        ImGui::Begin("Garden");  // the same window: its Export section
        exportPanel.draw(session);
        if (link && link->panel) link->goTo = link->panel->draw(session, link->recorder);
        ImGui::End();
        drawToolPanel(session);
        drawStatsPanel(session.scheduler().history(), pressed.stats,
                       [&]() -> const MemoryReport& { return memoryWatch.read(session); }, &renderer.arena());
        drawHistoryPanel(session, showHistory);
        drawHelpPanel(showHelp, {0.5f * static_cast<float>(fb.x), static_cast<float>(fb.y)});
        if (drawFirstRunPanel(firstRun)) firstRunDismissed();
        if (drawQuitQuestion(askQuit, unsavedWhat(session))) {
            quitConfirmed = true;
            window.setShouldClose(true);
        }
        askQuit = false;
        // Above everything, centred: work that is not on disk.
        const float bannerWidth = std::min(640.0f, static_cast<float>(fb.x) - 20.0f);
        drawNotice(notice, fb);
        drawSaveBanner(session, {0.5f * (static_cast<float>(fb.x) - bannerWidth), 10.0f}, bannerWidth);
        overlay.render();
        return viewDrawOf(r);
    });
    // The mouse's buttons and moves come as events (pointer_events.h); this
    // is where they left it at the end of the last frame.
    PointerState pointer;
    const auto cursorNow = [&] {
        glm::dvec2 c(0.0);
        glfwGetCursorPos(window.handle(), &c.x, &c.y);
        pointer = PointerState{};
        pointer.position = glm::vec2(c);
    };
    cursorNow();
    auto last = std::chrono::steady_clock::now();
    // Sources edited on disk are looked at once a second (their files' times).
    auto sourcesLookedAt = last;
    // The window's close button, like Esc, asks first when work is not saved.
    const auto closing = [&] {
        if (!window.shouldClose()) return false;
        if (quitConfirmed || !unsavedWork(session)) return true;
        window.setShouldClose(false);
        askQuit = true;
        return false;
    };
    const auto leaving = [&] { return link && !link->goTo.empty(); };
    for (int frame = 0; !leaving() && !closing() && (options.frames == 0 || frame < options.frames); ++frame) {
        pollEvents();
        const auto now = std::chrono::steady_clock::now();
        const double dt = std::min(0.1, std::chrono::duration<double>(now - last).count());
        last = now;
        fb = window.framebufferSize();
        // Levels for the pixels the scene is drawn at (the automatic
        // quality's render and detail scales), not the window's.
        session.settings().viewportHeight = detailPixels(std::max(fb.y, 1), renderer.quality());

        // The window's keys and mouse become this frame's hands; what they
        // ask of the garden directly (reset the view, the detail sphere) are
        // the frame's commands.
        FrameInput input;
        input.dt = dt;
        input.commands = [&](GardenSession&, Hands& hands) {
            if (now - sourcesLookedAt >= std::chrono::seconds(1)) {
                sourcesLookedAt = now;
                for (const GardenSession::SourceReload& r : session.reloadChangedSources()) {
                    const std::string text = r.problem.empty() ? "read '" + r.sculpture + "' again from its changed file"
                                                               : "'" + r.sculpture + "' kept as it was: " + r.problem;
                    std::cerr << (r.problem.empty() ? "note: " : "warning: ") << text << "\n";
                    notice = {text, !r.problem.empty(), now + std::chrono::seconds(r.problem.empty() ? 4 : 8)};
                }
            }
            DesktopInput in;
            GLFWwindow* w = window.handle();
            const bool keys = !overlay.wantsKeyboard(), mouse = !overlay.wantsMouse();
            // Held keys, as the key table binds them.
            const auto held = [&](KeyCommand c) {
                if (!keys) return false;
                for (const int k : keysOf(c))
                    if (glfwGetKey(w, k) == GLFW_PRESS) return true;
                return false;
            };
            in.forward = held(KeyCommand::Forward);
            in.back = held(KeyCommand::Back);
            in.left = held(KeyCommand::Left);
            in.right = held(KeyCommand::Right);
            in.up = held(KeyCommand::Up);
            in.down = held(KeyCommand::Down);
            const PointerFrame p = foldPointerEvents(events.pointer, pointer);
            // A release lost to the window (focus taken mid-drag) leaves no button stuck.
            pointer.toolDown = pointer.toolDown && glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
            pointer.lookDown = pointer.lookDown && glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
            pointer.gestureDown = pointer.gestureDown && glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
            const glm::ivec2 ws = window.size();
            // Mouse in framebuffer pixels (HiDPI: window and framebuffer differ).
            const glm::vec2 toFb(static_cast<float>(fb.x) / static_cast<float>(std::max(ws.x, 1)),
                                 static_cast<float>(fb.y) / static_cast<float>(std::max(ws.y, 1)));
            applyPointer(in, p, toFb, mouse);
            // Keys ImGui wants (typing in a field) are not the garden's.
            pressed = keys ? events.keys : DesktopKeys{};
            in.wheel = mouse ? events.wheel : 0.0f;
            in.turn = held(KeyCommand::Turn);
            in.viewport = glm::vec2(fb);
            const glm::mat4 projection = gardenProjection(fovY, fb);
            hands = desktopHands(in, pressed, session, projection, dt, carry);
            // The tool where the mouse points, unless it points at a panel.
            aim = mouse ? std::optional<Pose>(hands.tool.aim) : std::nullopt;
            if (pressed.escape) {
                switch (escapeDoes(popupOpen(), showHelp || firstRun, unsavedWork(session))) {
                    case EscapeDoes::ClosePopup: closePopups(); break;
                    case EscapeDoes::CloseHelp:
                        if (firstRun) firstRunDismissed();
                        showHelp = false;
                        break;
                    case EscapeDoes::AskToQuit: askQuit = true; break;
                    case EscapeDoes::Quit:
                        quitConfirmed = true;
                        window.setShouldClose(true);
                        break;
                }
            }
            if (pressed.frameGarden)
                frameGarden(session, fovY, static_cast<float>(fb.x) / static_cast<float>(std::max(fb.y, 1)));
            if (pressed.help) showHelp = !showHelp;
            if (pressed.history) showHistory = !showHistory;
            if (pressed.clayView) view.look().clay = !view.look().clay;
            if (pressed.wireframe) view.look().wireframe = !view.look().wireframe;
            if (pressed.undoSelected && session.selected() >= 0) session.undoSculpture(session.selected());
            if (pressed.detail) {
                // Where the mouse ray meets the ground, a metre up; again: removed.
                if (session.detail()) session.setDetail(std::nullopt);
                else if (const auto hit = hands.tool.aim.groundHit(session.garden().ground.height))
                    session.setDetail(poly::Sphere{{hit->x, hit->y + 1.0, hit->z}, 1.0});
            }
            events = WindowEvents{};
            return true;
        };
        session.frame(input, views);
        if (governor && governor->observe(session.stats().gpuMs)) useTheGovernorsQuality();
        const bool lastFrame = options.frames > 0 && frame + 1 == options.frames;
        if (lastFrame && !options.exitScreenshot.empty()) {
            const std::string why = writeFramebufferPng(options.exitScreenshot, fb.x, fb.y);
            if (!why.empty()) {
                std::cerr << "error: " << why << "\n";
                return 1;
            }
        }
        window.swapBuffers();
        if (link && link->recorder && options.goToSession)
            if (std::string to = options.goToSession(frame); !to.empty()) link->goTo = std::move(to);
        const bool toHeadset = headsetButton || pressed.headset || (options.onFrame && options.onFrame(session, frame));
        if (toHeadset && options.headset) {
            enterHeadset(session, gardenWindow, options, headsetMessage);
            cursorNow();
            last = std::chrono::steady_clock::now();
        }
    }
    // Closing the window ends what the hands were doing: a stroke or a
    // drag under way becomes a finished action, journalled like any; and
    // an edit whose grid update was spread over frames is made whole, for
    // whoever reads the grids next (the headset, a snapshot, the caller).
    session.endStroke();
    session.endLiveMove();
    session.settleEdits();
    return 0;
}

}  // namespace hg::garden
