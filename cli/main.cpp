// hypergarden: the command line. With no subcommand it opens the desktop
// garden; subcommands check and evaluate HyperFun files, voxelize them, mesh
// them to STL, replay scripted sessions and export sculptures. Built twice:
// `hypergarden-full` runs everything, `hypergarden` (HG_CLI_KERNEL_ONLY)
// runs check and eval and hands the rest to hypergarden-full.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "cli/commands.h"
#include "frep/language/near_miss.h"
#ifdef HG_CLI_KERNEL_ONLY
#include "cli/full_executable.h"
#endif

namespace {

// "error: unknown option '--sesion' (did you mean '--session'?)" for the
// first word that looks like an option and is none of the program's; ""
// when every one is known (the error is then CLI11's own).
std::string unknownOption(const CLI::App& app, int argc, char** argv) {
    std::vector<std::string> known;
    std::vector<const CLI::App*> apps{&app};
    for (std::size_t i = 0; i < apps.size(); ++i) {
        for (const CLI::Option* o : apps[i]->get_options())
            for (const std::string& name : o->get_lnames()) known.push_back("--" + name);
        for (const CLI::App* s : apps[i]->get_subcommands([](const CLI::App*) { return true; })) apps.push_back(s);
    }
    for (int i = 1; i < argc; ++i) {
        std::string word = argv[i];
        if (word.rfind("--", 0) != 0 || word == "--") continue;
        word = word.substr(0, word.find('='));
        if (std::find(known.begin(), known.end(), word) != known.end()) continue;
        const std::string near = hg::frep::nearMiss(word, known);
        return "error: unknown option '" + word + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
               "\nRun with --help for the options.";
    }
    return "";
}

}  // namespace

int main(int argc, char** argv) {
    using namespace hg::garden::cli;
    CLI::App app{"Hypergarden: a real-time HyperFun sculpture garden"};
    app.require_subcommand(0, 1);
    GardenOptions gardenOpts;
    gardenOpts.garden = HG_DEFAULT_GARDEN;
    CLI::Option* gardenOption =
        app.add_option("--garden", gardenOpts.garden, "Garden file to open (default: content/gardens/default.json)");
    app.add_option("--width", gardenOpts.width, "Window width in pixels (default 1280)");
    app.add_option("--height", gardenOpts.height, "Window height in pixels (default 720)");
    app.add_flag("--no-vsync", gardenOpts.noVsync, "Do not wait for the display's refresh");
    app.add_option("--budget-ms", gardenOpts.budgetMs, "Frame budget in milliseconds (default 11.1, 90 Hz)");
    app.add_option("--memory-budget", gardenOpts.memoryBudgetMiB,
                   "MiB the sculptures may hold in memory; beyond it far sculptures' grids wait on disk until "
                   "you come near (default 1024; 0: no budget; docs/desktop.md)");
    app.add_option("--impostor-distance", gardenOpts.impostorDistance,
                   "Metres beyond which a sculpture is drawn as an impostor, a card of pictures made from it "
                   "(default 30; 0: never; docs/rendering.md)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--frames", gardenOpts.frames, "Close after this many frames (default: when the window closes)");
    app.add_option("--quality", gardenOpts.quality,
                   "Picture: auto (default: low on software rendering, else high), low, medium or high "
                   "(docs/rendering.md)")
        ->check(CLI::IsMember({"auto", "low", "medium", "high"}));
    app.add_option("--screenshot-dir", gardenOpts.screenshotDir, "Where F12 screenshots go (default: the session's screenshots/ folder, else ~/Pictures/hypergarden)");
    app.add_option("--exit-screenshot", gardenOpts.exitScreenshot, "With --frames: a PNG of the last frame, overlay included");
    app.add_option("--session", gardenOpts.session,
                   "Session folder: opened with every journalled action, or made from --garden when new; "
                   "every finished action is saved as it ends");
    app.add_flag("--xr", gardenOpts.xr, "Open the garden in a headset through OpenXR (docs/xr.md)");
    app.add_option("--script", gardenOpts.xrScript, "With --xr: run a replay script's commands at their frames");
    app.add_flag("--left-handed", gardenOpts.leftHanded, "With --xr: the left controller holds the tool");
    app.add_flag("--seated", gardenOpts.seated,
                 "With --xr: seated use (heights raised by the settings' offset, 0.5 m unless changed)");
    app.add_flag("--smooth-turn", gardenOpts.smoothTurn, "With --xr: turn smoothly instead of in snaps (for this run)");
    // A vector, so that a mistyped command and its arguments are one
    // mistake with a suggestion, not "argument not expected".
    std::vector<std::string> modelArgs;
    app.add_option("model", modelArgs, "A HyperFun file (.hf) to open as a garden of that one sculpture");

    ModelOptions checkOpts;
    auto* check = app.add_subcommand("check", "Parse a HyperFun file, list its bodies, evaluation path and model box");
    check->add_option("file", checkOpts.file, "HyperFun file (.hf)")->required();
    check->add_option("--body", checkOpts.body, "Body to check (default: my_model, else the first)");
    std::string checkA, evalA;
    check->add_option("--a", checkA, "Values of a[1], a[2], ... separated by commas");

    EvalOptions evalOpts;
    auto* eval = app.add_subcommand("eval", "Evaluate a body at a point, or at \"x y z\" lines read from stdin");
    eval->add_option("file", evalOpts.model.file, "HyperFun file (.hf)")->required();
    eval->add_option("--body", evalOpts.model.body, "Body to evaluate (default: my_model, else the first)");
    eval->add_option("--a", evalA, "Values of a[1], a[2], ... separated by commas");
    eval->add_option("point", evalOpts.point, "x y z")->expected(0, 3);
    eval->add_flag("--interpreter", evalOpts.interpreter, "Use the scalar interpreter even when the body compiles");

    VoxelizeOptions voxOpts;
    std::string voxA, voxBox;
    auto* vox = app.add_subcommand("voxelize", "Sample a body into an OpenVDB grid (.vdb)");
    vox->add_option("file", voxOpts.model.file, "HyperFun file (.hf)")->required();
    vox->add_option("--body", voxOpts.model.body, "Body to sample (default: my_model, else the first)");
    vox->add_option("--a", voxA, "Values of a[1], a[2], ... separated by commas");
    vox->add_option("--res", voxOpts.resolution, "Voxels along the model box's longest side")->required();
    vox->add_option("--band", voxOpts.band, "Half-width of the narrow band in voxels (default 3)");
    vox->add_option("--box", voxBox, "Model box x0,y0,z0,x1,y1,z1 (default: estimated, else found by sampling [-10, 10]^3)");
    vox->add_flag("--dense", voxOpts.dense, "Write the unclamped dense source cache (every voxel) instead");
    vox->add_option("-o,--output", voxOpts.output, "Output .vdb file")->required();
    vox->add_flag("--levelset", voxOpts.levelset, "Write an OpenVDB level set (negative inside, model units)");
    vox->add_flag("--stats", voxOpts.stats, "Print |grad| at the surface and the grid's layout");
    vox->add_option("--threads", voxOpts.threads, "Worker threads (default: all cores)");
    vox->add_option("--memory-limit", voxOpts.memoryLimitMiB, "MiB the grid may use (default: 80% of available)");

    MeshOptions meshOpts;
    std::string meshA, meshBox;
    auto* meshCmd = app.add_subcommand("mesh", "Mesh a sculpture (.hf or our .vdb) and write a watertight STL");
    meshCmd->add_option("file", meshOpts.model.file, "HyperFun file (.hf) or Hypergarden grid (.vdb)")->required();
    meshCmd->add_option("--body", meshOpts.model.body, "Body to mesh (default: my_model, else the first)");
    meshCmd->add_option("--a", meshA, "Values of a[1], a[2], ... separated by commas");
    meshCmd->add_option("--res", meshOpts.resolution, "Voxels along the model box's longest side (for .hf)");
    meshCmd->add_option("--box", meshBox, "Model box x0,y0,z0,x1,y1,z1 (default: as for voxelize)");
    meshCmd->add_option("-o,--output", meshOpts.output, "Output .stl file")->required();
    meshCmd->add_flag("--ascii", meshOpts.ascii, "Write ASCII STL instead of binary");
    meshCmd->add_option("--mm-per-unit", meshOpts.mmPerUnit, "Millimetres per model unit (default 1000: model units as metres, as export writes them)");

    ReplayCommandOptions replayOpts;
    std::string offscreen;
    auto* replay = app.add_subcommand("replay", "Play a scripted session (docs/replay-format.md)");
    replay->add_option("script", replayOpts.script, "Replay script (.json)")->required();
    replay->add_flag("--headless", replayOpts.headless, "No window and no GL: levels, morph and meshing only");
    replay->add_option("--offscreen", offscreen, "Render offscreen at WxH pixels (default: the script's viewport)");
    replay->add_option("--screenshot-every", replayOpts.screenshotEvery, "Also a screenshot every N frames");
    replay->add_option("--screenshot-dir", replayOpts.screenshotDir, "Where screenshots go (default: .)");
    replay->add_option("--stats", replayOpts.statsPath, "Write per-frame statistics (JSON)");
    replay->add_option("--morph-samples", replayOpts.morphSamples, "Morph samples per frame (default 1000000; 0: time budget)");
    replay->add_option("--remesh-chunks", replayOpts.remeshChunks, "Chunks remeshed per frame (default 16; 0: time budget)");
    replay->add_option("--res", replayOpts.resolution, "Every sculpture and the morph at this resolution");
    replay->add_flag("--no-lod", replayOpts.noLod, "Every chunk at full detail");
    replay->add_option("--quality", replayOpts.quality,
                       "Offscreen: low, medium, high (default) or auto (as the desktop: stepped by the GPU's time against "
                       "the script's budget_ms; docs/rendering.md)")
        ->check(CLI::IsMember({"low", "medium", "high", "auto"}));
    replay->add_option("--impostor-distance", replayOpts.impostorDistance,
                       "Offscreen: far sculptures as impostor cards beyond this many metres (default 30; 0: never)")
        ->check(CLI::NonNegativeNumber);
    replay->add_option("--session", replayOpts.session,
                       "Play into this session folder (made from the script's garden when new)");
    SessionCommandOptions sessionOpts;
    auto* sessionCmd = app.add_subcommand("session", "Say what a session folder holds; --verify rebuilds its grids");
    sessionCmd->add_option("dir", sessionOpts.dir, "Session folder")->required();
    sessionCmd->add_flag("--verify", sessionOpts.verify,
                         "Rebuild every grid from the journal and compare it with the snapshots (exit 1 where they differ)");
    sessionCmd->add_flag("--json", sessionOpts.json, "Print JSON instead of text");
    sessionCmd->add_option("--cut-at", sessionOpts.cutAt,
                           "Cut the journal at record N (it and those after it removed; the whole journal kept "
                           "beside it), so that a session stopped at an unplayable record can go on")
        ->check(CLI::PositiveNumber);

    ExportOptions exportOpts;
    std::string exportBox;
    auto* exportCmd = app.add_subcommand("export", "Write a sculpture of a session or garden as HyperFun (.hf) or a mesh");
    exportCmd->add_option("input", exportOpts.input, "Session folder, or garden file (.json)")->required();
    exportCmd->add_option("--sculpture", exportOpts.sculpture, "The sculpture's name in the garden")->required();
    exportCmd->add_option("-o,--output", exportOpts.output, "Output file: .hf (.stl, .vdb, .obj, .glb: meshes)")->required();
    exportCmd->add_option("--res", exportOpts.resolution, "Meshes: voxels along the model box's longest side");
    exportCmd->add_option("--mm-per-unit", exportOpts.mmPerUnit, "STL: millimetres per model unit (default: the sculpture's true size, 1000 x its metres per unit)");
    exportCmd->add_option("--simplify", exportOpts.simplifyError, "Meshes: simplify within ERROR model units (meshoptimizer), validated again");
    exportCmd->add_flag("--ascii", exportOpts.ascii, "STL: ASCII instead of binary");
    exportCmd->add_option("--box", exportBox, "Meshes: model box x0,y0,z0,x1,y1,z1 (default: the sculpture's)");
    exportCmd->add_option("--memory-limit", exportOpts.memoryLimitMiB, "Meshes: MiB the work may use (default: 80% of available)");

    GardenAddOptions addOpts;
    auto* gardenCmd = app.add_subcommand("garden", "Change a garden file");
    gardenCmd->require_subcommand(1);
    auto* gardenAdd = gardenCmd->add_subcommand("add", "Add a HyperFun file, a mesh (.stl, .obj, .ply) or an OpenVDB volume (.vdb) to a garden as a sculpture");
    gardenAdd->add_option("garden", addOpts.garden, "Garden file (.json)")->required();
    gardenAdd->add_option("file", addOpts.file, "HyperFun file (.hf), mesh (.stl, .obj, .ply) or OpenVDB volume (.vdb)")->required();
    gardenAdd->add_option("--name", addOpts.name, "The sculpture's name (default: the file's stem)");
    gardenAdd->add_option("--body", addOpts.body, "HyperFun: the body to use (default: my_model, else the first)");
    gardenAdd->add_option("--resolution", addOpts.resolution, "Voxels along the model box's longest side (default 128)")
        ->check(CLI::Range(4, 2048));
    gardenAdd->add_option("--size", addOpts.size, "Metres along the model box's longest side (default 1.5)")
        ->check(CLI::Range(0.01, 100.0));

    GestureCommandOptions gestureOpts;
    auto* gestureCmd = app.add_subcommand("gesture", "Classify the strokes of a file as gestures (docs/gestures.md)");
    gestureCmd->add_option("file", gestureOpts.file, "Strokes (.json): {\"strokes\": [{\"points\": [[x, y], ...], \"label\": ...}]}")
        ->required();
    gestureCmd->add_flag("--json", gestureOpts.json, "Print JSON instead of text");
    gestureCmd->add_option("--weights", gestureOpts.weights, "Weights file (default: content/gestures/weights.json)");
    gestureCmd->add_option("--threshold", gestureOpts.threshold, "Least confidence that counts (default: the weights file's)")
        ->check(CLI::Range(0.0, 1.0));

    TurntableCommandOptions turntableOpts;
    auto* turntableCmd = app.add_subcommand(
        "turntable", "Write PNG frames of one sculpture turning once, for sharing (docs/rendering.md)");
    turntableCmd->add_option("input", turntableOpts.input, "Session folder, or garden file (.json)")->required();
    turntableCmd->add_option("--sculpture", turntableOpts.sculpture, "The sculpture's name in the garden")->required();
    turntableCmd->add_option("-o,--output", turntableOpts.output, "Folder for the frames NAME-0000.png ... (made when missing)")
        ->required();
    turntableCmd->add_option("--frames", turntableOpts.frames, "Frames in the full turn (default 36)")
        ->check(CLI::Range(1, 3600));
    turntableCmd->add_option("--size", turntableOpts.size, "WIDTHxHEIGHT pixels (default 800x800)");
    turntableCmd->add_option("--quality", turntableOpts.quality, "low, medium or high (default; docs/rendering.md)")
        ->check(CLI::IsMember({"low", "medium", "high"}));
    turntableCmd->add_option("--elevation", turntableOpts.elevationDeg,
                             "Degrees the camera looks down at the sculpture's centre from (default 20)")
        ->check(CLI::Range(-80.0, 89.0));
    turntableCmd->add_option("--distance", turntableOpts.distance,
                             "Metres from the sculpture's centre to the camera (default: the sculpture framed)")
        ->check(CLI::PositiveNumber);

    bool keysMarkdown = false;
    auto* keysCmd = app.add_subcommand("keys", "List the garden window's keys and mouse (F1 shows them in the window)");
    keysCmd->add_flag("--markdown", keysMarkdown, "As the README's Markdown table");
    app.footer("In the window, F1 lists the keys and mouse; `hypergarden keys` prints them.");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (dynamic_cast<const CLI::ExtrasError*>(&e))
            if (const std::string unknown = unknownOption(app, argc, argv); !unknown.empty()) {
                std::cerr << unknown << '\n';
                return 2;
            }
        return app.exit(e);
    }
    gardenOpts.gardenGiven = gardenOption->count() > 0;
    if (!modelArgs.empty()) {
        gardenOpts.model = modelArgs[0];
        gardenOpts.extraArgs = modelArgs.size() - 1;
    }
    if (!parseNumberList(checkA, checkOpts.parameters) || !parseNumberList(evalA, evalOpts.model.parameters) ||
        !parseNumberList(voxA, voxOpts.model.parameters) || !parseNumberList(meshA, meshOpts.model.parameters)) {
        std::cerr << "error: --a expects numbers separated by commas, for example --a 0.5,1\n";
        return 2;
    }
    if (*check) return runCheck(checkOpts);
    if (*eval) return runEval(evalOpts);
#ifdef HG_CLI_KERNEL_ONLY
    // This executable holds the HyperFun kernel only, so that check and eval
    // start in a few milliseconds (see full_executable.h).
    return runFullExecutable(argv);
#else
    if (*replay) {
        if (!offscreen.empty()) {
            if (replayOpts.headless) {
                std::cerr << "error: --headless and --offscreen exclude each other\n";
                return 2;
            }
            if (!parseImageSize(offscreen, replayOpts.width, replayOpts.height)) {
                std::cerr << "error: --offscreen expects WIDTHxHEIGHT, each 16 to 8192 pixels, for example 1280x720\n";
                return 2;
            }
        }
        return runReplay(replayOpts);
    }
    if (app.get_subcommands().empty()) return runGarden(gardenOpts);
    if (*sessionCmd) return runSessionCommand(sessionOpts);
    if (*gardenCmd) return runGardenAdd(addOpts);
    if (*gestureCmd) return runGestureCommand(gestureOpts);
    if (*keysCmd) return runKeysCommand(keysMarkdown);
    if (*turntableCmd) return runTurntable(turntableOpts);
    if (*vox) {
        if (!parseNumberList(voxBox, voxOpts.box)) {
            std::cerr << "error: --box expects six numbers separated by commas: x0,y0,z0,x1,y1,z1\n";
            return 2;
        }
        return runVoxelize(voxOpts);
    }
    if (*exportCmd) {
        if (!parseNumberList(exportBox, exportOpts.box) || (!exportOpts.box.empty() && exportOpts.box.size() != 6)) {
            std::cerr << "error: --box expects six numbers separated by commas: x0,y0,z0,x1,y1,z1\n";
            return 2;
        }
        return runExport(exportOpts);
    }
    if (*meshCmd) {
        if (!parseNumberList(meshBox, meshOpts.box)) {
            std::cerr << "error: --box expects six numbers separated by commas: x0,y0,z0,x1,y1,z1\n";
            return 2;
        }
        return runMesh(meshOpts);
    }
    return 2;
#endif
}
