// Subcommands of the `hypergarden` executable. Each returns the process
// exit status: 0 on success, 1 when the input has errors, 2 on bad usage.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hg::garden::cli {

struct ModelOptions {
    std::string file;
    std::string body;                 // "" : my_model, else the first body
    std::vector<double> parameters;   // a[1], a[2], ...
};

struct EvalOptions {
    ModelOptions model;
    std::vector<double> point;        // empty: read points from standard input
    bool interpreter = false;         // force the scalar interpreter
};

struct VoxelizeOptions {
    ModelOptions model;
    int resolution = 0;
    float band = 3.0f;
    std::vector<double> box;          // empty: estimate; else x0,y0,z0,x1,y1,z1
    bool dense = false;               // unclamped source cache, every voxel
    bool levelset = false;            // OpenVDB level-set convention
    bool stats = false;
    std::string output;
    int threads = 0;                  // 0: all cores
    double memoryLimitMiB = 0.0;      // 0: 80% of available memory
};

struct MeshOptions {
    ModelOptions model;               // a .hf file, or one of our .vdb grids
    int resolution = 0;               // required for .hf
    std::vector<double> box;
    std::string output;
    bool ascii = false;
    // Millimetres per model unit: model units as metres by default, as a
    // garden places a file without a scale and as `export` writes it, so
    // the same file meshed by `mesh` and by `export` is the same size.
    double mmPerUnit = 1000.0;
};

struct ReplayCommandOptions {
    std::string script;
    bool headless = false;
    int width = 0, height = 0;        // --offscreen WxH (0: the script's viewport)
    int screenshotEvery = 0;
    std::string screenshotDir = ".";
    std::string statsPath;
    std::uint64_t morphSamples = 1000000;  // per frame; 0: the scheduler's time budget
    std::size_t remeshChunks = 16;         // per frame; 0: the scheduler's time budget
    int resolution = 0;               // every sculpture and the morph at this resolution (0: the garden's)
    bool noLod = false;               // every chunk at level 0
    std::string session;              // play into this session folder ("" : none)
    std::string quality = "high";     // --quality low|medium|high (offscreen rendering)
    float impostorDistance = 30.0f;   // --impostor-distance: far sculptures as cards beyond it (0: never)
};

struct GardenOptions {
    std::string model;                // a .hf file opened as a garden of that one sculpture ("" : none)
    std::size_t extraArgs = 0;        // more words after it (an error)
    std::string garden;               // the garden file
    bool gardenGiven = false;         // named on the command line (not the default)
    int width = 1280, height = 720;
    bool noVsync = false;
    double budgetMs = 11.1;
    std::size_t memoryBudgetMiB = 1024;  // what the sculptures may hold; far grids go to disk beyond it (0: no budget)
    int frames = 0;                   // stop after N frames (0: until the window closes)
    std::string exitScreenshot;       // with frames: a PNG of the last frame
    std::string screenshotDir;        // "": the session's screenshots/, else ~/Pictures/hypergarden
    std::string session;              // open (or create) this session folder ("" : none)
    std::string quality = "auto";     // --quality auto|low|medium|high
    float impostorDistance = 30.0f;   // --impostor-distance: far sculptures as cards beyond it (0: never)
    bool xr = false;                  // in a headset through OpenXR (docs/xr.md)
    std::string xrScript;             // with xr: a replay script's commands at their frames
    bool leftHanded = false;          // with xr: the left hand holds the tool
    bool seated = false;              // with xr: seated use, heights raised
    bool smoothTurn = false;          // with xr: smooth turning instead of snap turns
};

struct SessionCommandOptions {
    std::string dir;
    bool verify = false;
    bool json = false;
    std::size_t cutAt = 0;  // cut the journal at this record (from 1); 0: no
};
int runSessionCommand(const SessionCommandOptions& options);

struct ExportOptions {
    std::string input;                // a session folder or a garden file (.json)
    std::string sculpture;            // its name in the garden
    std::string output;               // .hf (.stl, .vdb, .obj, .glb: the mesh formats)
    int resolution = 0;               // mesh formats: voxels along the longest side (0: the grid's)
    double mmPerUnit = 0.0;           // STL: millimetres per model unit (0: 1000 x the placement's metres per unit)
    double simplifyError = 0.0;       // mesh formats: meshoptimizer's error bound, model units (0: none)
    bool ascii = false;               // STL: ASCII instead of binary
    std::vector<double> box;          // mesh formats: a model box instead of the sculpture's
    double memoryLimitMiB = 0.0;      // mesh formats: 0: 80% of available memory
};
int runExport(const ExportOptions& options);

struct TurntableCommandOptions {
    std::string input;                // a session folder or a garden file (.json)
    std::string sculpture;            // its name in the garden
    std::string output;               // the folder the frames go to (made when missing)
    int frames = 36;
    std::string size = "800x800";     // WIDTHxHEIGHT
    std::string quality = "high";     // low|medium|high
    double elevationDeg = 20.0;
    double distance = 0.0;            // metres; 0: framed to the sculpture
};
int runTurntable(const TurntableCommandOptions& options);

// "1280x720" -> 1280, 720, each 16 to 8192 pixels; false (nothing printed)
// for anything else.
constexpr int kMinImageSide = 16, kMaxImageSide = 8192;
bool parseImageSize(const std::string& text, int& width, int& height);

struct GestureCommandOptions {
    std::string file;                 // strokes (.json, docs/gestures.md)
    std::string weights;              // "" : content/gestures/weights.json
    bool json = false;
    double threshold = -1.0;          // < 0: the weights file's
};
int runGestureCommand(const GestureCommandOptions& options);

// `hypergarden keys [--markdown]`: the window's keys and mouse, from the
// table the window binds (garden/render/key_table.h).
int runKeysCommand(bool markdown);

// "0.5,1,-2" -> {0.5, 1, -2}; false when an item is not a number.
bool parseNumberList(const std::string& text, std::vector<double>& out);

int runCheck(const ModelOptions& options);
int runEval(const EvalOptions& options);
int runVoxelize(const VoxelizeOptions& options);
int runMesh(const MeshOptions& options);
int runReplay(const ReplayCommandOptions& options);
int runGarden(const GardenOptions& options);

// `hypergarden garden add GARDEN.json FILE.hf`: the model added to the garden file.
struct GardenAddOptions {
    std::string garden;
    std::string file;
    std::string name;
    std::string body;
    int resolution = 128;
    double size = 1.5;
};
int runGardenAdd(const GardenAddOptions& options);

}  // namespace hg::garden::cli
