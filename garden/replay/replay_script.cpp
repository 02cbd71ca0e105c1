#include "garden/replay/replay_script.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"
#include "garden/scene/to_glm.h"

namespace hg::garden {

namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;

// A pose: position, and either a direction to point along or yaw/pitch.
Pose readPose(const nlohmann::json& v, const std::string& path) {
    ObjectReader r(v, path, {"position", "direction"});
    Pose p;
    p.position = toGlm(readVec3(r.required("position"), r.pathOf("position")));
    if (const auto* d = r.optional("direction")) {
        glm::vec3 dir = toGlm(readVec3(*d, r.pathOf("direction")));
        if (glm::length(dir) == 0.0f) throw JsonError(r.pathOf("direction"), "a direction must not be zero");
        dir = glm::normalize(dir);
        const glm::vec3 up = std::fabs(dir.y) > 0.999f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
        p.orientation = glm::quatLookAt(dir, up);
    }
    r.finish();
    return p;
}

std::uint32_t readButtons(const nlohmann::json& v, const std::string& path) {
    if (!v.is_array()) throw JsonError(path, "expected an array of button names");
    std::uint32_t bits = 0;
    const std::vector<std::pair<std::string, HandButton>> names = {
        {"primary", kButtonPrimary}, {"secondary", kButtonSecondary}, {"menu", kButtonMenu}, {"gesture", kButtonGesture},
        {"thumbstick", kButtonThumbstick}, {"undo", kButtonUndo}, {"redo", kButtonRedo}};
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string name = readString(v[i], indexPath(path, i));
        bool found = false;
        for (const auto& [n, b] : names)
            if (n == name) {
                bits |= b;
                found = true;
            }
        if (!found) {
            std::vector<std::string> known;
            for (const auto& nb : names) known.push_back(nb.first);
            const std::string near = nearMiss(name, known);
            throw JsonError(indexPath(path, i), "unknown button '" + name + "'" +
                                                    (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                                                    "; expected primary, secondary, menu, thumbstick, undo or redo");
        }
    }
    return bits;
}

HandState readHand(const nlohmann::json& v, const std::string& path) {
    ObjectReader r(v, path, {"aim", "grip", "trigger", "squeeze", "thumbstick", "buttons"});
    HandState h;
    h.tracked = true;
    if (const auto* a = r.optional("aim")) h.aim = readPose(*a, r.pathOf("aim"));
    h.grip = h.aim;
    if (const auto* g = r.optional("grip")) h.grip = readPose(*g, r.pathOf("grip"));
    if (const auto* t = r.optional("trigger")) h.trigger = static_cast<float>(readNumber(*t, r.pathOf("trigger"), 0, 1));
    if (const auto* s = r.optional("squeeze")) h.squeeze = static_cast<float>(readNumber(*s, r.pathOf("squeeze"), 0, 1));
    if (const auto* s = r.optional("thumbstick")) {
        const auto xy = readVec2(*s, r.pathOf("thumbstick"));
        for (int i = 0; i < 2; ++i)
            if (std::fabs(xy[static_cast<std::size_t>(i)]) > 1.0)
                throw JsonError(indexPath(r.pathOf("thumbstick"), static_cast<std::size_t>(i)), "expected a number in [-1, 1]");
        h.thumbstick = glm::vec2(static_cast<float>(xy[0]), static_cast<float>(xy[1]));
    }
    if (const auto* b = r.optional("buttons")) h.buttons = readButtons(*b, r.pathOf("buttons"));
    r.finish();
    return h;
}

// A name from a list, or an error naming the nearest and every choice.
template <class T>
T readChoice(const nlohmann::json& v, const std::string& path, const std::vector<std::pair<std::string, T>>& names) {
    const std::string name = readString(v, path);
    std::vector<std::string> known;
    for (const auto& [n, t] : names) {
        if (n == name) return t;
        known.push_back(n);
    }
    std::string all;
    for (std::size_t i = 0; i < known.size(); ++i) all += (i == 0 ? "" : i + 1 == known.size() ? " or " : ", ") + known[i];
    const std::string near = nearMiss(name, known);
    throw JsonError(path, "unknown '" + name + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") + "; expected " + all);
}

// The step's tool intents, for the whole step (stepHands spreads them over its frames).
ToolIntents readIntents(const nlohmann::json& v, const std::string& path) {
    ObjectReader r(v, path, {"tool", "size", "strength", "reverse", "mirror", "selection_scale", "held"});
    ToolIntents in;
    if (const auto* t = r.optional("tool")) {
        // The names of toolKindName (garden/sculpt/tool_settings.h).
        in.tool = readChoice(*t, r.pathOf("tool"),
                             std::vector<std::pair<std::string, ToolChoice>>{
                                 {"none", ToolChoice::None}, {"carve", ToolChoice::Carve}, {"add", ToolChoice::Add},
                                 {"melt", ToolChoice::Melt}, {"perturb", ToolChoice::Perturb},
                                 {"impacts", ToolChoice::Impacts}, {"move", ToolChoice::Move},
                                 {"sketch", ToolChoice::Sketch}, {"smooth", ToolChoice::Smooth},
                                 {"inflate", ToolChoice::Inflate}});
    }
    constexpr double lo = 1e-3, hi = 1e3;  // factors for a whole step
    if (const auto* f = r.optional("size")) in.size = readNumber(*f, r.pathOf("size"), lo, hi);
    if (const auto* f = r.optional("strength")) in.strength = readNumber(*f, r.pathOf("strength"), lo, hi);
    if (const auto* f = r.optional("selection_scale")) in.selectionScale = readNumber(*f, r.pathOf("selection_scale"), lo, hi);
    if (const auto* b = r.optional("reverse")) in.reverse = readBool(*b, r.pathOf("reverse"));
    if (const auto* m = r.optional("mirror"))
        in.mirror = readChoice(*m, r.pathOf("mirror"),
                               std::vector<std::pair<std::string, MirrorIntent>>{
                                   {"toggle", MirrorIntent::Toggle}, {"on", MirrorIntent::On}, {"off", MirrorIntent::Off}});
    if (const auto* b = r.optional("held")) in.held = readBool(*b, r.pathOf("held"));
    r.finish();
    return in;
}

ReplayCommand readCommand(const nlohmann::json& v, const std::string& path) {
    if (!v.is_object() || v.size() != 1)
        throw JsonError(path, "expected an object with one command: morph, morph_weights, screenshot, detail, pose, select, "
                              "orbit, budget_ms, stroke, perturb, edit_perturbation, impacts, reapply_impacts, undo, redo, sculpt_tool, "
                              "action, sketch, add, deform, extract, gesture or export");
    ReplayCommand c;
    for (const char* key :
         {"stroke", "perturb", "edit_perturbation", "impacts", "reapply_impacts", "undo", "redo", "sculpt_tool", "action", "sketch", "add", "deform", "extract", "gesture"})
        if (v.contains(key)) {
            c.kind = ReplayCommand::Kind::Sculpt;
            c.sculpt = readSculptCommand(key, v.at(key), childPath(path, key));
            return c;
        }
    ObjectReader r(v, path, {"morph", "morph_weights", "screenshot", "detail", "pose", "select", "orbit", "budget_ms",
                             "stroke", "perturb", "edit_perturbation", "impacts", "reapply_impacts", "undo", "redo",
                             "sculpt_tool", "action", "sketch", "add", "deform", "extract", "gesture", "export"});
    if (const auto* m = r.optional("morph")) {
        c.kind = ReplayCommand::Kind::Morph;
        const auto xz = readVec2(*m, r.pathOf("morph"));
        c.pair = {xz[0], xz[1]};
    } else if (const auto* w = r.optional("morph_weights")) {
        c.kind = ReplayCommand::Kind::MorphWeights;
        c.vec = readVec3(*w, r.pathOf("morph_weights"));
        double sum = 0.0;
        for (std::size_t i = 0; i < 3; ++i) {
            if (c.vec[i] < 0.0) throw JsonError(indexPath(r.pathOf("morph_weights"), i), "a weight must not be negative");
            sum += c.vec[i];
        }
        if (sum <= 0.0) throw JsonError(r.pathOf("morph_weights"), "the weights must not all be zero");
    } else if (const auto* s = r.optional("screenshot")) {
        c.kind = ReplayCommand::Kind::Screenshot;
        c.text = readString(*s, r.pathOf("screenshot"));
    } else if (const auto* d = r.optional("detail")) {
        c.kind = ReplayCommand::Kind::Detail;
        ObjectReader dr(*d, r.pathOf("detail"), {"center", "radius"});
        c.vec = readVec3(dr.required("center"), dr.pathOf("center"));
        c.number = readNumber(dr.required("radius"), dr.pathOf("radius"), 0.0, 1000.0);
        dr.finish();
    } else if (const auto* p = r.optional("pose")) {
        c.kind = ReplayCommand::Kind::Pose;
        ObjectReader pr(*p, r.pathOf("pose"), {"position", "yaw", "pitch"});
        c.vec = readVec3(pr.required("position"), pr.pathOf("position"));
        c.pair[0] = pr.has("yaw") ? readNumber(pr.required("yaw"), pr.pathOf("yaw")) : 0.0;
        c.pair[1] = pr.has("pitch") ? readNumber(pr.required("pitch"), pr.pathOf("pitch"), -89.0, 89.0) : 0.0;
        pr.finish();
    } else if (const auto* sel = r.optional("select")) {
        c.kind = ReplayCommand::Kind::Select;
        c.text = readString(*sel, r.pathOf("select"), true);
    } else if (const auto* o = r.optional("orbit")) {
        c.kind = ReplayCommand::Kind::Orbit;
        c.flag = readBool(*o, r.pathOf("orbit"));
    } else if (const auto* b = r.optional("budget_ms")) {
        c.kind = ReplayCommand::Kind::Budget;
        c.number = readNumber(*b, r.pathOf("budget_ms"), 0.1, 1000.0);
    } else if (const auto* e = r.optional("export")) {
        c.kind = ReplayCommand::Kind::Export;
        ObjectReader er(*e, r.pathOf("export"), {"sculpture", "path", "res"});
        if (const auto* n = er.optional("sculpture")) c.text = readString(*n, er.pathOf("sculpture"));
        c.file = readString(er.required("path"), er.pathOf("path"));
        if (const auto* res = er.optional("res")) c.number = readInt(*res, er.pathOf("res"), 0, 4096);
        er.finish();
    }
    r.finish();
    return c;
}

ReplayStep readStep(const nlohmann::json& v, const std::string& path) {
    ObjectReader r(v, path, {"frames", "until_idle", "tool", "navigation", "look", "speed_scale", "intents", "commands"});
    ReplayStep s;
    if (const auto* f = r.optional("frames")) s.frames = readInt(*f, r.pathOf("frames"), 1, 1000000);
    if (const auto* u = r.optional("until_idle")) s.untilIdle = readBool(*u, r.pathOf("until_idle"));
    if (s.untilIdle && !r.has("frames")) s.frames = 10000;
    if (const auto* t = r.optional("tool")) s.hands.tool = readHand(*t, r.pathOf("tool"));
    if (const auto* n = r.optional("navigation")) s.hands.navigation = readHand(*n, r.pathOf("navigation"));
    if (const auto* l = r.optional("look")) {
        const auto yp = readVec2(*l, r.pathOf("look"));
        s.hands.look = glm::vec2(static_cast<float>(yp[0] * kDegrees), static_cast<float>(yp[1] * kDegrees));
    }
    if (const auto* sp = r.optional("speed_scale"))
        s.hands.speedScale = static_cast<float>(readNumber(*sp, r.pathOf("speed_scale"), 0.01, 100.0));
    if (const auto* in = r.optional("intents")) s.hands.intents = readIntents(*in, r.pathOf("intents"));
    if (const auto* c = r.optional("commands")) {
        if (!c->is_array()) throw JsonError(r.pathOf("commands"), "expected an array of commands");
        for (std::size_t i = 0; i < c->size(); ++i) s.commands.push_back(readCommand((*c)[i], indexPath(r.pathOf("commands"), i)));
    }
    r.finish();
    return s;
}

}  // namespace

Hands stepHands(const ReplayStep& step, int frame) {
    Hands h = step.hands;
    const ToolIntents& whole = step.hands.intents;
    ToolIntents& in = h.intents;
    if (frame > 0) {
        in.tool.reset();
        in.reverse = false;
        in.mirror = MirrorIntent::Keep;
    }
    const double share = 1.0 / static_cast<double>(std::max(step.frames, 1));
    in.size = std::pow(whole.size, share);
    in.strength = std::pow(whole.strength, share);
    in.selectionScale = std::pow(whole.selectionScale, share);
    return h;
}

int ReplayScript::totalFrames() const {
    int n = 0;
    for (const ReplayStep& s : steps) n += s.frames;
    return n;
}

ReplayScript parseReplayScript(const std::string& text, const std::string& file, const std::string& folder) {
    const nlohmann::json doc = parseStrictJson(text);
    ObjectReader r(doc, "$", {"garden", "timestep", "budget_ms", "viewport", "steps"});
    ReplayScript s;
    s.file = file;
    const std::string garden = readString(r.required("garden"), r.pathOf("garden"));
    const std::filesystem::path g(garden);
    s.garden = g.is_absolute() || folder.empty() ? garden : (std::filesystem::path(folder) / g).lexically_normal().string();
    if (const auto* t = r.optional("timestep")) s.timestep = readNumber(*t, r.pathOf("timestep"), 1e-4, 1.0);
    if (const auto* b = r.optional("budget_ms")) s.budgetMs = readNumber(*b, r.pathOf("budget_ms"), 0.1, 1000.0);
    if (const auto* v = r.optional("viewport")) {
        const auto wh = readVec2(*v, r.pathOf("viewport"));
        for (std::size_t i = 0; i < 2; ++i)
            if (wh[i] < 16 || wh[i] > 8192 || wh[i] != std::floor(wh[i]))
                throw JsonError(indexPath(r.pathOf("viewport"), i), "expected a whole number of pixels in [16, 8192]");
        s.viewport = {static_cast<int>(wh[0]), static_cast<int>(wh[1])};
    }
    const nlohmann::json& steps = r.required("steps");
    if (!steps.is_array() || steps.empty()) throw JsonError(r.pathOf("steps"), "expected a non-empty array of steps");
    for (std::size_t i = 0; i < steps.size(); ++i) s.steps.push_back(readStep(steps[i], indexPath(r.pathOf("steps"), i)));
    r.finish();
    // Files the script brings in are named relative to it, like its garden.
    for (ReplayStep& step : s.steps)
        for (ReplayCommand& c : step.commands)
            if (auto* add = std::get_if<AddCommand>(&c.sculpt); add && !folder.empty() &&
                                                              !std::filesystem::path(add->file).is_absolute())
                add->file = (std::filesystem::path(folder) / add->file).lexically_normal().string();
    return s;
}

ReplayScript loadReplayScript(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw JsonError("$", "cannot read the script file '" + path + "'");
    std::stringstream text;
    text << in.rdbuf();
    return parseReplayScript(text.str(), path, std::filesystem::path(path).parent_path().string());
}

}  // namespace hg::garden
