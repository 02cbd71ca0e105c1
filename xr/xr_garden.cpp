#include "xr/xr_garden.h"

// The garden's headers before the XR and X11 ones (xr/headset.h keeps X11 out).
#include "garden/app/garden_session.h"
#include "garden/window/garden_view.h"
#include "garden/window/garden_window.h"
#include "garden/render/garden_ground.h"
#include "garden/render/gl_context.h"
#include "garden/render/image_target.h"
#include "garden/render/offscreen_target.h"
#include "garden/render/overlay.h"
#include "garden/render/panels.h"
#include "garden/render/quality_governor.h"
#include "garden/render/tool_gizmo.h"
#include "garden/replay/replay_runner.h"
#include "garden/replay/replay_script.h"
#include "garden/scene/json_reader.h"
#include "garden/session/open_session.h"
#include "xr/controllers.h"
#include "xr/hand_panel.h"
#include "xr/hand_panel_ui.h"
#include "xr/headset.h"
#include "xr/mirror_fit.h"
#include "xr/stage_rig.h"
#include "xr/tool_stick.h"
#include "xr/turning.h"
#include "xr/walking.h"
#include "xr/world_grab.h"
#include "xr/xr_result.h"
#include "xr/xr_settings.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include <glm/gtc/matrix_transform.hpp>

namespace hg::xr {

namespace {

constexpr float kNearZ = garden::kGardenNearPlane, kFarZ = garden::kGardenFarPlane;
// The tool hand's ray into the air, stage metres (the world's at scale 1).
constexpr float kToolRayLength = 1.5f;
constexpr int kMirrorWidth = 640, kMirrorHeight = 640;
constexpr const char* kMirrorTitle = "Hypergarden - headset mirror (left eye)";

glm::mat4 projectionOf(const XrFovf& f) {
    return glm::frustum(std::tan(f.angleLeft) * kNearZ, std::tan(f.angleRight) * kNearZ, std::tan(f.angleDown) * kNearZ,
                        std::tan(f.angleUp) * kNearZ, kNearZ, kFarZ);
}

garden::Pose poseOf(const XrPosef& p, float floorOffset) {
    garden::Pose g;
    g.position = glm::vec3(p.position.x, p.position.y + floorOffset, p.position.z);
    g.orientation = glm::quat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
    return g;
}

// One run: everything that lives from the first frame to the last.
class XrRun final : public garden::ViewSink {
public:
    XrRun(const XrOptions& o, garden::GardenSession& s, Headset& h, garden::GardenWindow& w,
          const std::optional<garden::ReplayScript>& script, bool desktopButton)
        : options_(o), session_(s), headset_(h), gardenWindow_(w), window_(w.window()), renderer_(w.renderer()),
          view_(w.view()), script_(script), desktopButton_(desktopButton) {
        settingsPath_ = options_.settingsFile.empty() ? xrSettingsPath() : options_.settingsFile;
        std::string warning;
        user_ = loadXrSettings(settingsPath_, warning);
        if (!warning.empty()) std::cerr << "warning: " << warning << "\n";
        if (options_.leftHanded) user_.leftHanded = *options_.leftHanded;
        if (options_.seated) user_.seated = *options_.seated;
        if (options_.smoothTurn) user_.smoothTurn = *options_.smoothTurn;
        applyTurning();
        if (options_.quality) renderer_.setQuality(*options_.quality);
        view_.setImpostorDistance(options_.impostorDistance);
        if (options_.mirror) overlay_ = w.overlay();
        gardenWindow_.events() = garden::WindowEvents{};
        controllers_ = std::make_unique<Controllers>(headset_.instance(), user_.leftHanded);
        headset_.createSession(window_.handle());
        controllers_->attach(headset_.session());
        info_.space = headset_.spaceName();
        runtimeName_ = headset_.runtimeName();
        info_.depthSubmitted = headset_.depthSubmitted();
        // Level selection for the eye's own pixels, as the desktop does for
        // its framebuffer (Monado's null compositor: 128 x 128 per eye).
        if (headset_.eyeSize()[1] > 0) session_.settings().viewportHeight = headset_.eyeSize()[1];
        // The headset's height is the user's: the navigator flies, so a
        // grab may lift or lower the world.
        startEye_ = session_.navigator().eye();
        startYaw_ = session_.navigator().yaw();
        session_.navigator().setPose(startEye_, startYaw_, 0.0f);
        session_.navigator().setMode(garden::NavigationMode::Fly);
        if (script_) {
            int start = 0;
            for (const garden::ReplayStep& st : script_->steps) {
                stepStarts_.push_back(start);
                start += st.frames;
            }
        }
    }

    // Controllers go before the session they were attached to.
    ~XrRun() override { controllers_.reset(); }

    int loop() {
        bool exitAsked = false;
        const auto askExit = [&] {
            if (!exitAsked && headset_.running()) {
                headset_.requestExit();
                exitAsked = true;
            }
        };
        while (!headset_.done()) {
            garden::pollEvents();
            if (window_.shouldClose()) askExit();
            // F9 in the mirror: the headset session ends, the desktop follows.
            if (desktopButton_ && gardenWindow_.events().keys.headset) desktopAsked_ = true;
            gardenWindow_.events() = garden::WindowEvents{};
            if (desktopAsked_) askExit();
            if (headset_.pollEvents()) {
                controllers_->refreshProfile();
                info_.interactionProfile = controllers_->interactionProfile();
            }
            if (headset_.done()) break;
            if (!headset_.running() && (window_.shouldClose() || desktopAsked_)) {
                info_.endReason = desktopAsked_ ? "the desktop was asked for" : "the mirror window was closed";
                return 0;  // the session is not running: nothing to end
            }
            if (!headset_.running()) {
                // IDLE or READY: nothing to draw until the runtime says.
                std::this_thread::sleep_for(std::chrono::milliseconds(5));
                continue;
            }
            frame();
            if (options_.frames > 0 && info_.framesSubmitted >= options_.frames) askExit();
            if (desktopButton_ && options_.askDesktop && options_.askDesktop(info_.framesSubmitted)) desktopAsked_ = true;
            if (script_ && scriptFrame_ >= script_->totalFrames()) askExit();
            if (!error_.empty()) return 1;
        }
        info_.lost = headset_.lost();
        info_.endReason = headset_.doneReason();
        return 0;
    }

    XrRunInfo info() const {
        XrRunInfo i = info_;
        i.worldScale = scale_;
        i.quality = renderer_.quality();
        i.qualityBudgetMs = governor_ ? governor_->budgetMs() : 0.0;
        return i;
    }
    const std::string& error() const { return error_; }
    // The user asked for the desktop (F9, the mirror's button).
    bool desktopAsked() const { return desktopAsked_; }

private:
    // Added to tracked heights: the floor at 0, raised for a seated user.
    float heightOffset() const {
        return headset_.floorOffset() + (user_.seated ? static_cast<float>(user_.seatedHeightOffset) : 0.0f);
    }

    // The navigator holds where the stage stands in the world and its turn;
    // the scale is ours.
    StageRig rig() const {
        const garden::Navigator& n = session_.navigator();
        StageRig r;
        r.origin = n.eye() - glm::vec3(0.0f, garden::NavigationSettings{}.eyeHeight, 0.0f);
        r.yaw = n.yaw();
        r.scale = scale_;
        return r;
    }
    void setRig(const StageRig& r) {
        session_.navigator().setPose(r.origin + glm::vec3(0.0f, garden::NavigationSettings{}.eyeHeight, 0.0f), r.yaw, 0.0f);
        scale_ = r.scale;
    }

    void runScriptCommands() {
        for (std::size_t i = 0; i < stepStarts_.size(); ++i) {
            if (stepStarts_[i] != scriptFrame_) continue;
            for (std::size_t c = 0; c < script_->steps[i].commands.size(); ++c) {
                // Screenshots are skipped: the headset's frames are the runtime's to show.
                const std::string why = garden::runReplayCommand(script_->steps[i].commands[c], session_);
                if (!why.empty() && error_.empty())
                    error_ = script_->file + ": $.steps[" + std::to_string(i) + "].commands[" + std::to_string(c) + "]: " + why;
            }
        }
    }

    void frame() {
        const HeadsetFrame f = headset_.beginFrame();
        const double periodMs = static_cast<double>(f.state.predictedDisplayPeriod) / 1e6;
        // The budget is the display's period, not the predicted one: Monado
        // paces an app slower than the display to a multiple of it (the
        // predicted period grows with the app's frame time, and its first
        // frame's is a 16 ms placeholder), and a budget that followed would
        // let a slow app stay slow. The display's refresh rate when the
        // runtime says it, else the smallest period seen.
        if (periodMs > 0.0 && (minPeriodMs_ <= 0.0 || periodMs < minPeriodMs_)) minPeriodMs_ = periodMs;
        const float hz = headset_.displayRefreshRate();
        const double budgetMs = hz > 0.0f ? 1000.0 / static_cast<double>(hz) : minPeriodMs_;
        if (budgetMs > 0.0) session_.scheduler().setBudgetMs(budgetMs);
        if (options_.autoQuality && budgetMs > 0.0) steerQuality(budgetMs);
        // Levels for the eye's pixels at the render and detail scales, as on the desktop.
        if (headset_.eyeSize()[1] > 0)
            session_.settings().viewportHeight = garden::detailPixels(headset_.eyeSize()[1], renderer_.quality());
        const bool focused = headset_.focused();
        const double dt = periodMs > 0.0 ? periodMs / 1000.0 : 1.0 / 90.0;
        garden::FrameInput input;
        input.dt = dt;
        // The controllers become the frame's hands (in the world), after
        // the script's commands, the world grab, the recentring and the
        // hand panel have had them.
        input.commands = [&](garden::GardenSession&, garden::Hands& world) {
            const garden::Hands stage =
                controllers_->read(headset_.space(), f.state.predictedDisplayTime, heightOffset(), focused);
            if (focused) {
                ++info_.focusedFrames;
                if (script_) runScriptCommands();
                ++scriptFrame_;
            }
            // The world grab moves the rig; then the hands go into the world.
            const auto squeezing = [](const garden::HandState& h) {
                return h.tracked && h.squeeze > 0.5f ? std::optional<glm::vec3>(h.grip.position) : std::nullopt;
            };
            setRig(grab_.update(rig(), squeezing(stage.navigation), squeezing(stage.tool)));
            // The navigation hand's menu button recenters: where the head is
            // now becomes the garden's start, looking its way.
            const bool menu = stage.navigation.pressed(garden::kButtonMenu);
            if (menu && !menuHeld_ && f.viewsValid) {
                garden::Pose head = poseOf(f.views[0].pose, heightOffset());
                head.position = 0.5f * (head.position + poseOf(f.views[1].pose, heightOffset()).position);
                setRig(rig().recentered(head, startEye_, garden::NavigationSettings{}.eyeHeight, startYaw_));
            }
            menuHeld_ = menu;
            world = rig().toWorld(stage);
            world.look.x = turning_.apply(world, dt);
            // The stick walks where the head looks (orbiting keeps its own axes).
            if (f.viewsValid && session_.navigator().mode() != garden::NavigationMode::Orbit)
                world.navigation.thumbstick = headRelativeStick(world.navigation.thumbstick, poseOf(f.views[0].pose, 0.0f));
            panel_.place(world.navigation, scale_);
            panel_.update(world.tool);
            // Every frame, shown or not, so ImGui knows the panel's window
            // before the first pull on it.
            if (panelUi_.update(session_, panel_, info_.interactionProfile, user_, static_cast<float>(periodMs / 1000.0)))
                keepSettings();
            if (panel_.ownsTrigger()) world.tool.trigger = 0.0f;  // the trigger is the panel's
            // The tool stick reshapes the tool (with the move tool, scales
            // the selection) as intents the session applies; the navigator
            // must not fly with it.
            world.intents = stickIntents(world.tool.thumbstick, dt);
            world.tool.thumbstick = glm::vec2(0.0f);
            toolHand_ = world.tool;
            wasStroking_ = session_.stroking();
            return true;
        };
        eyes_ = &f;
        const garden::FrameStats& stats = session_.frame(input, *this);
        eyes_ = nullptr;
        // Both eyes' GPU time (one endFrame after both), measured a few
        // frames late by the renderer's timer queries.
        if (governor_)
            if (const auto q = governor_->observe(stats.gpuMs)) {
                renderer_.setQuality(*q);
                info_.qualityChanges = static_cast<int>(governor_->changes());
            }
        if (focused && options_.onFrame) options_.onFrame(stats, scriptFrame_ - 1);
        ++info_.framesSubmitted;
        if (options_.mirror) window_.swapBuffers();
    }

    // The frame's views (garden/app/view_sink.h): both eyes, then the frame
    // handed to the runtime.
    garden::ViewUpload upload(garden::GardenSession& session, double allowanceMs) override {
        return view_.upload(session, allowanceMs);
    }
    garden::ViewDraw render(garden::GardenSession&) override {
        const HeadsetFrame& f = *eyes_;
        // A stroke begun this frame: the tool hand feels it.
        if (!wasStroking_ && session_.stroking() && headset_.focused()) controllers_->pulseToolHand();
        const bool render = f.state.shouldRender && f.viewsValid;
        // The tool hand aims (not at the panel) with a tool in hand: where
        // its ray meets a sculpture, found once for both eyes.
        const bool aiming = render && toolHand_.tracked && !panel_.hovered() &&
                            session_.tool().kind != garden::ToolSettings::Kind::None;
        std::optional<glm::vec3> toolHit;
        if (aiming)
            if (const auto hit = session_.toolHit(toolHand_.aim)) toolHit = hit->second;
        garden::ViewDraw drawn;
        if (render) {
            const StageRig r = rig();
            for (int eye = 0; eye < 2; ++eye) {
                const EyeImages images = headset_.acquireEye(eye);
                garden::ImageTarget& target = targets_[static_cast<std::size_t>(eye)];
                target.bind(images.color, images.depth, glm::ivec2(images.width, images.height));
                const XrView& v = f.views[static_cast<std::size_t>(eye)];
                const garden::Pose eyePose = poseOf(v.pose, heightOffset());
                view_.render(session_, glm::ivec2(images.width, images.height), r.viewOf(eyePose), projectionOf(v.fov),
                             r.toWorld(eyePose.position));
                drawTool(toolHand_, aiming, toolHit);
                // The eye's picture is rendered before the panel goes over it.
                renderer_.finishView();
                drawPanel(toolHand_, projectionOf(v.fov) * r.viewOf(eyePose));
                if (eye == 0 && options_.mirror) mirror(target, images);
                garden::OffscreenTarget::unbind();
                headset_.releaseEye(eye);
            }
            if (overlay_) drawPanels();
            drawn = garden::viewDrawOf(renderer_.endFrame());
            ++info_.framesRendered;
        }
        headset_.endFrame(f, render, kNearZ, kFarZ);
        return drawn;
    }

    // The tool in the tool hand, as the desktop draws it where the mouse
    // points: while `aiming`, its ray to `hit` (else a while into the air)
    // and its gizmo (live size and shape) at `hit`; the selection's mirror
    // plane and move gizmo as on the desktop.
    void drawTool(const garden::HandState& tool, bool aiming, const std::optional<glm::vec3>& hit) {
        garden::drawToolGizmos(renderer_, session_, aiming ? std::optional<garden::Pose>(tool.aim) : std::nullopt, hit);
        if (!aiming) return;
        const glm::vec3 end = hit ? *hit : tool.aim.position + tool.aim.forward() * (kToolRayLength * scale_);
        renderer_.drawLines({tool.aim.position, end}, garden::toolColor(session_.tool()), garden::LineMode::Segments, true);
    }

    // The panel's board and the tool hand's ray onto it, over the scene.
    void drawPanel(const garden::HandState& tool, const glm::mat4& viewProjection) {
        if (!panel_.shown()) return;
        panelUi_.draw(panel_, viewProjection);
        if (panel_.hovered() && tool.tracked)
            renderer_.drawLines({tool.aim.position, panel_.at(*panel_.hovered())}, glm::vec4(1.0f),
                                garden::LineMode::Segments, false);
    }

    // The panel changed a setting (hand, seated, turning): in effect from the next
    // frame, and kept for the next run (the flags given this run included).
    void keepSettings() {
        controllers_->setLeftHanded(user_.leftHanded);
        applyTurning();
        const std::string why = saveXrSettings(settingsPath_, user_);
        if (!why.empty()) std::cerr << "warning: the headset settings are not kept: " << why << "\n";
    }

    void applyTurning() { turning_.set(user_.smoothTurn, glm::radians(static_cast<float>(user_.snapDegrees))); }

    // Over the mirror: what the headset runs, and the frame statistics.
    void drawPanels() {
        garden::OffscreenTarget::unbind();
        overlay_->newFrame();
        // Bottom right, clear of the frame statistics (top left) however
        // long the runtime's and the profile's names are (Monado's are).
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        ImGui::SetNextWindowPos(ImVec2(display.x - 10.0f, display.y - 10.0f), ImGuiCond_FirstUseEver, ImVec2(1.0f, 1.0f));
        ImGui::Begin("Headset", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::Text("%s", runtimeName_.c_str());
        ImGui::Text("space %s, world x%.2f", info_.space.c_str(), 1.0 / static_cast<double>(scale_));
        ImGui::Text("%s", info_.interactionProfile.empty() ? "no interaction profile yet" : info_.interactionProfile.c_str());
        ImGui::Text("tool radius %.3f m", session_.tool().radius);
        if (desktopButton_ && ImGui::Button("Desktop (F9)")) desktopAsked_ = true;
        ImGui::End();
        garden::drawStatsPanel(session_.scheduler().history(), false,
                               [this]() -> const garden::MemoryReport& { return memoryWatch_.read(session_); },
                               &renderer_.arena());
        overlay_->render();
    }

    // The left eye, scaled into the mirror window with its aspect kept
    // (eyes need not be square), black bars around it.
    void mirror(const garden::ImageTarget& target, const EyeImages& images) {
        const MirrorRect r = fitMirror(glm::ivec2(images.width, images.height), window_.framebufferSize());
        target.showIn(garden::kWindowFramebuffer, r.offset, r.size);
    }

    // The automatic quality, made at the first frame whose display period
    // is known and then judged against the period as it changes.
    void steerQuality(double budgetMs) {
        if (!governor_) {
            governor_.emplace(options_.autoCeiling.value_or(garden::rendererPreset(garden::GlWindow::glVersionString())),
                              budgetMs);
            renderer_.setQuality(governor_->quality());
        } else if (budgetMs != governor_->budgetMs()) {
            governor_->setBudgetMs(budgetMs);
        }
    }

    const XrOptions& options_;
    std::optional<garden::QualityGovernor> governor_;
    garden::GardenSession& session_;
    Headset& headset_;
    garden::GardenWindow& gardenWindow_;
    garden::GlWindow& window_;
    garden::Renderer& renderer_;
    garden::GardenView& view_;
    const std::optional<garden::ReplayScript>& script_;
    const bool desktopButton_;  // F9 and the mirror's button go to the desktop
    bool desktopAsked_ = false;
    std::vector<int> stepStarts_;
    int scriptFrame_ = 0;
    std::unique_ptr<Controllers> controllers_;
    garden::Overlay* overlay_ = nullptr;  // the mirror's panels (none when hidden)
    garden::MemoryWatch memoryWatch_{std::chrono::milliseconds(2000)};  // the stats panel's memory lines
    std::array<garden::ImageTarget, 2> targets_;
    WorldGrab grab_;
    HandPanel panel_;
    HandPanelUi panelUi_;
    std::string settingsPath_;
    XrUserSettings user_;
    Turning turning_;
    float scale_ = 1.0f;
    glm::vec3 startEye_{0.0f};
    float startYaw_ = 0.0f;
    bool menuHeld_ = false;
    // This frame's, for its views: the runtime's frame, the tool hand (world),
    // and whether a stroke was under way before the frame's input.
    const HeadsetFrame* eyes_ = nullptr;
    garden::HandState toolHand_;
    bool wasStroking_ = false;
    double minPeriodMs_ = 0.0;  // the smallest predicted display period seen
    XrRunInfo info_;
    std::string runtimeName_;
    std::string error_;
};

}  // namespace

namespace {

// Why no headset: the runtime is missing or failed (the message says which).
struct HeadsetUnavailable {
    int status;
    std::string message;
};

// The loader's own log would repeat our message in its words; the user may
// still ask for it (XR_LOADER_DEBUG=error).
std::unique_ptr<Headset> openHeadset(const std::string& desktopHint) {
    ::setenv("XR_LOADER_DEBUG", "none", 0);
    try {
        auto headset = std::make_unique<Headset>("Hypergarden");
        std::cerr << "OpenXR runtime: " << headset->runtimeName() << "\n";
        return headset;
    } catch (const NoRuntime& e) {
        throw HeadsetUnavailable{kExitNoRuntime, "error: no OpenXR runtime: " + std::string(e.what()) + "; " + desktopHint +
                                                     " (XR_LOADER_DEBUG=error shows the loader's own messages)"};
    } catch (const XrFailure& e) {
        throw HeadsetUnavailable{1, "error: OpenXR: " + std::string(e.what())};
    }
}

// One headset session on an open garden and window; the headset is closed
// (its swapchains with the window's context current) before returning.
int runHeadsetOn(const XrOptions& options, std::unique_ptr<Headset> headset, garden::GardenSession& session,
                 garden::GardenWindow& window, const std::optional<garden::ReplayScript>& script, bool desktopButton,
                 XrRunInfo& info, bool& desktopAsked, std::string& error) {
    int status = 0;
    session.settings().viewportHeight = 1024;  // until the swapchains say the eye's height
    try {
        XrRun run(options, session, *headset, window, script, desktopButton);
        status = run.loop();
        info = run.info();
        desktopAsked = run.desktopAsked();
        if (!run.error().empty()) error = "error: " + run.error();
    } catch (const XrFailure& e) {
        error = "error: OpenXR: " + std::string(e.what());
        status = 1;
    }
    // A stroke still held is finished, so the journal has it; an edit whose
    // grid update was spread over frames is made whole, for whoever reads
    // the grids next (the desktop, a snapshot, the caller).
    if (session.stroking()) session.endStroke();
    session.settleEdits();
    // The swapchains' textures belong to the window's context: the
    // session goes while it is current.
    window.window().makeCurrent();
    headset.reset();
    std::cerr << "xr: " << info.framesSubmitted << " frames (" << info.framesRendered << " drawn, " << info.focusedFrames
              << " focused), space " << info.space
              << (info.interactionProfile.empty() ? "" : ", " + info.interactionProfile)
              << (info.endReason.empty() ? "" : "; " + info.endReason) << "\n";
    return status;
}

}  // namespace

int runXrGarden(const XrOptions& options,
                const std::function<void(garden::GardenSession&, const XrRunInfo&)>& atEnd) {
    std::optional<garden::ReplayScript> script;
    std::string gardenFile = options.garden;
    if (!options.script.empty()) {
        try {
            script = garden::loadReplayScript(options.script);
        } catch (const garden::JsonError& e) {
            std::cerr << "error: " << options.script << ": " << e.what() << "\n";
            return 2;
        }
        if (gardenFile.empty()) gardenFile = script->garden;
    }
    std::optional<garden::GardenLoad> load;
    if (options.session.empty()) {
        load = garden::loadGarden(gardenFile);
        if (!load->ok()) {
            std::cerr << "error: " << load->error << "\n";
            return 2;
        }
    }
    // The runtime first: without one there is no window to open.
    std::unique_ptr<Headset> headset;
    try {
        headset = openHeadset("run hypergarden without --xr for the desktop garden");
    } catch (const HeadsetUnavailable& e) {
        std::cerr << e.message << "\n";
        return e.status;
    }
    try {
        garden::WindowOptions wo;
        wo.width = kMirrorWidth;
        wo.height = kMirrorHeight;
        wo.visible = options.mirror;
        wo.vsync = false;  // xrWaitFrame paces the frames
        wo.title = kMirrorTitle;
        garden::GardenWindow window(wo, options.mirror || static_cast<bool>(options.desktop));
        garden::SessionSettings settings;
        settings.memoryBudgetBytes = options.memoryBudgetBytes;
        settings.workOffFrameThread = true;  // xrWaitFrame paces the frames; the workers mesh and blend meanwhile
        settings.spreadEdits = true;           // a big edit lands over a few frames, none held
        garden::OpenedSession opened = garden::openLoadedOrSession(
            std::move(load), {options.session, gardenFile, options.gardenGiven, "hypergarden --xr"}, settings);
        if (!opened.error.empty()) {
            std::cerr << "error: " << opened.error << "\n";
            return opened.exitStatus;
        }
        for (const std::string& m : garden::openedMessages(opened)) std::cerr << m << "\n";
        garden::reportSaveChangesOnStderr(opened);
        garden::GardenSession& session = *opened.session;
        XrRunInfo info;
        bool desktopAsked = false;
        std::string error;
        int status = runHeadsetOn(options, std::move(headset), session, window, script, static_cast<bool>(options.desktop),
                                  info, desktopAsked, error);
        if (!error.empty()) std::cerr << error << "\n";
        if (status == 0 && desktopAsked && options.desktop && !window.window().shouldClose()) {
            // The user goes on at the desktop (its F9 comes back to the headset),
            // where the headset stood, walking (the headset flies).
            session.navigator().setMode(garden::NavigationMode::Walk);
            status = options.desktop(session, window);
        }
        if (atEnd) atEnd(session, info);
        std::vector<std::string> last;
        const int saved = garden::closeSession(opened, last);
        for (const std::string& line : last) std::cerr << line << "\n";
        return status != 0 ? status : saved;
    } catch (const garden::GlError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}

garden::HeadsetEntry headsetFromDesktop(XrOptions options, std::function<void(const XrRunInfo&)> ran) {
    return [options, ran](garden::GardenSession& session, garden::GardenWindow& window, std::string& message) {
        std::unique_ptr<Headset> headset;
        try {
            headset = openHeadset("the desktop goes on");
        } catch (const HeadsetUnavailable& e) {
            message = e.message;
            return garden::HeadsetReturn::Desktop;
        }
        window.window().setTitle(kMirrorTitle);
        window.window().setVsync(false);  // xrWaitFrame paces the frames
        XrRunInfo info;
        bool desktopAsked = false;
        const int status =
            runHeadsetOn(options, std::move(headset), session, window, std::nullopt, true, info, desktopAsked, message);
        if (status != 0 && message.empty()) message = "error: the headset session failed";
        if (ran) ran(info);
        return window.window().shouldClose() ? garden::HeadsetReturn::Quit : garden::HeadsetReturn::Desktop;
    };
}

}  // namespace hg::xr
