// What each render pass costs (issue 24): one scene (the lawn and nine
// carved, voxelized sculptures) at 1280 x 720 rendered with each effect on
// alone and with the presets, against the low preset measured in the same
// run. Frame time is wall time to glFinish (on llvmpipe that is the
// software GPU's work); the GPU columns are the renderer's timer queries.
// The last rows give the nine blocks the built-in materials' procedural
// detail (issue 24: marble, wood, bronze...), the clay view and the
// wireframe overlay, at the low and high presets.
//
//   xvfb-run -a ./build/release/bench/bench_look [--json FILE] [--filter NAME] [--repeat N]
#include <epoxy/gl.h>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "../bench_common.h"
#include "frep/eval/model.h"
#include "frep/language/parser.h"
#include "garden/render/garden_ground.h"
#include "garden/render/gl_context.h"
#include "garden/render/material_look.h"
#include "garden/scene/materials.h"
#include "garden/render/offscreen_target.h"
#include "garden/render/renderer.h"
#include "polygonizer/export/export_mesher.h"
#include "voxel/sampler.h"

namespace {

using namespace hg;
using namespace hg::garden;

constexpr int kWidth = 1280, kHeight = 720;
constexpr int kFrames = 6;

poly::Mesh carvedBlock() {
    const std::string source =
        "slotted(x[3], a[1]) {\n"
        "  block = (0.5 - x[1]) & (0.5 + x[1]) & (0.6 - x[2]) & (0.6 + x[2]) & (0.5 - x[3]) & (0.5 + x[3]);\n"
        "  ball = 0.45 - sqrt(x[1]^2 + (x[2] - 0.6)^2 + x[3]^2);\n"
        "  slot = (a[1] - x[1]) & (a[1] + x[1]) & (x[2] - 0.3);\n"
        "  slotted = (block | ball) \\ slot;\n"
        "}\n";
    frep::ParseResult r = frep::parseProgram(source, "carved.hf");
    if (!r.ok()) return {};
    auto program = std::make_shared<const frep::Program>(std::move(*r.program));
    frep::Model model(program, program->defaultBody(), {0.05});
    voxel::VolumeRequest request;
    request.resolution = 64;
    voxel::VoxelizeResult v = voxel::voxelize(model, request);
    return v.volume ? poly::meshVolume(*v.volume) : poly::Mesh{};
}

// What the nine blocks wear.
enum class Look { Plain, Materials, Clay, Wireframe };

struct Row {
    std::string name;
    RenderQuality quality;
    Look look = Look::Plain;
    // The shadow map kept while nothing it shows changes (Renderer::
    // setShadowReuse): off in every row but one, which measure the pass.
    bool keepShadows = false;
    // The garden's ground and air (gardenGround: stripes, blades, the grid
    // near the eye, the meadow, haze) instead of the plain grid.
    bool gardenLawn = false;
    // A still view (Renderer::setPictureReuse): after the first frame every
    // one is kept, the held output copied instead of drawn.
    bool keepPicture = false;
};

RenderQuality low() { return qualityOf(QualityPreset::Low); }

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, args)) return 2;
    WindowOptions wo;
    wo.width = 64;
    wo.height = 64;
    wo.visible = false;
    wo.vsync = false;
    GlWindow window(wo);
    OffscreenTarget target(kWidth, kHeight);
    Renderer renderer;
    const poly::Mesh block = carvedBlock();
    if (block.empty()) {
        std::fprintf(stderr, "bench_look: the sculpture did not mesh\n");
        return 1;
    }
    renderer.upload(1, 1, block);

    View view;
    view.view = glm::lookAt(glm::vec3(0.5f, 2.6f, 7.5f), glm::vec3(0, 0.6f, 0), glm::vec3(0, 1, 0));
    view.projection = glm::perspective(glm::radians(50.0f), float(kWidth) / float(kHeight), 0.05f, 500.0f);
    view.eye = glm::vec3(0.5f, 2.6f, 7.5f);
    view.viewport = {kWidth, kHeight};
    view.lights = {DirectionalLight{{0.4f, 1.0f, 0.3f}, glm::vec3(1.0f, 0.95f, 0.86f)},
                   DirectionalLight{{-0.5f, 0.4f, -0.6f}, glm::vec3(0.25f)}};
    view.ambient = glm::vec3(0.2f);
    GroundStyle ground;
    ground.halfExtent = 20.0f;
    const GroundStyle lawn = gardenGround({0.16f, 0.30f, 0.10f}, {40.0f, 40.0f});  // the default garden's
    const RenderMaterial stone{{0.76f, 0.62f, 0.44f}, 0.1f, 8.0f};

    std::vector<Row> rows;
    rows.push_back({"low (all off)", low()});
    RenderQuality q = low();
    q.msaaSamples = 4;
    rows.push_back({"+ MSAA 4x", q});
    q = low();
    q.shadows = true;
    rows.push_back({"+ shadows 2048", q});
    q = low();
    q.ambientOcclusion = true;
    q.aoSamples = 16;
    rows.push_back({"+ AO 16, full", q});
    q.aoHalfResolution = true;
    rows.push_back({"+ AO 16, half", q});
    q.aoSamples = 8;
    rows.push_back({"+ AO 8, half", q});
    rows.push_back({"medium", qualityOf(QualityPreset::Medium)});
    rows.push_back({"high", qualityOf(QualityPreset::High)});
    // High as it was until 28 November: the peer for the change.
    q = qualityOf(QualityPreset::High);
    q.aoHalfResolution = false;
    rows.push_back({"high, AO full (before 28 Nov)", q});
    // A still garden (or the headset's second eye): the map drawn once, kept.
    rows.push_back({"high, shadow map kept", qualityOf(QualityPreset::High), Look::Plain, true});
    // A still view: its picture kept, the peers "low (all off)" and "high".
    rows.push_back({"low, still view kept", low(), Look::Plain, false, false, true});
    rows.push_back({"high, still view kept", qualityOf(QualityPreset::High), Look::Plain, false, false, true});
    // The automatic mode's last rungs: fewer scene pixels, stretched
    // bilinearly by the composite (four resolves per output pixel).
    q = low();
    q.renderScale = 0.75f;
    rows.push_back({"low, scale 0.75", q});
    q.renderScale = 0.5f;
    rows.push_back({"low, scale 0.5", q});
    q.smoothUpscale = false;
    rows.push_back({"low, scale 0.5, nearest", q});
    rows.push_back({"low + materials", low(), Look::Materials});
    rows.push_back({"high + materials", qualityOf(QualityPreset::High), Look::Materials});
    rows.push_back({"high + clay view", qualityOf(QualityPreset::High), Look::Clay});
    rows.push_back({"high + wireframe", qualityOf(QualityPreset::High), Look::Wireframe});
    // What the garden's lawn and haze cost over the plain ground: the peers
    // are "low (all off)" and "high".
    rows.push_back({"low + the garden's lawn and haze", low(), Look::Plain, false, true});
    rows.push_back({"high + the garden's lawn and haze", qualityOf(QualityPreset::High), Look::Plain, false, true});
    // The built-ins but plain, in turn over the blocks; the pattern a tenth
    // of a block (1.2 m tall), as the garden view sets it.
    std::vector<RenderMaterial> kinds;
    for (const Material& m : builtinMaterials())
        if (m.kind != MaterialKind::Plain) kinds.push_back(renderMaterial(m, detailScaleFor(1.2)));
    ViewLook clay, wire;
    clay.clay = true;
    wire.wireframe = true;

    std::printf("Software rendering (Mesa llvmpipe) unless the GL renderer below says otherwise: %s\n\n",
                GlWindow::glVersionString().c_str());
    std::printf("| quality | ms / frame | x low | GPU shadow ms | GPU scene ms | GPU AO ms | GPU post ms |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
    nlohmann::json out = nlohmann::json::array();
    double lowMs = 0.0;
    for (const Row& row : rows) {
        if (!args.matches(row.name) && row.name != "low (all off)") continue;
        renderer.setQuality(row.quality);
        renderer.setShadowReuse(row.keepShadows);
        renderer.setPictureReuse(row.keepPicture);
        RenderStats stats;
        auto frame = [&] {
            target.bind();
            View v = view;
            v.hazeDistance = row.gardenLawn ? kGardenHazeDistance : 0.0f;
            renderer.beginFrame(v);
            renderer.drawGround(row.gardenLawn ? lawn : ground);
            for (int i = 0; i < 9; ++i) {
                const glm::vec3 at(float(i % 3 - 1) * 2.2f, 0.6f, float(i / 3 - 1) * 2.2f);
                const RenderMaterial m = row.look == Look::Materials   ? kinds[std::size_t(i) % kinds.size()]
                                         : row.look == Look::Clay      ? lookedAt(stone, clay)
                                         : row.look == Look::Wireframe ? lookedAt(stone, wire)
                                                                       : stone;
                renderer.drawChunk(1, glm::translate(glm::mat4(1.0f), at), m);
            }
            stats = renderer.endFrame();
            glFinish();
        };
        for (int i = 0; i < 3; ++i) frame();  // targets allocated, timer results in
        const double seconds = bench::bestOf(args.repeat, [&] {
            for (int i = 0; i < kFrames; ++i) frame();
        });
        const double ms = seconds * 1000.0 / kFrames;
        if (row.name == "low (all off)") lowMs = ms;
        auto gpu = [](float v) { return v < 0.0f ? std::string("-") : std::to_string(v).substr(0, 5); };
        std::printf("| %s | %.1f | %.2f | %s | %s | %s | %s |\n", row.name.c_str(), ms, ms / lowMs,
                    gpu(stats.gpuShadowMs).c_str(), gpu(stats.gpuSceneMs).c_str(), gpu(stats.gpuOcclusionMs).c_str(),
                    gpu(stats.gpuPostMs).c_str());
        out.push_back({{"name", row.name}, {"ms_per_frame", ms}, {"ratio_to_low", ms / lowMs},
                       {"gpu_shadow_ms", stats.gpuShadowMs}, {"gpu_scene_ms", stats.gpuSceneMs},
                       {"gpu_occlusion_ms", stats.gpuOcclusionMs}, {"gpu_post_ms", stats.gpuPostMs}});
    }
    if (!args.jsonPath.empty()) std::ofstream(args.jsonPath) << out.dump(2) << "\n";
    return 0;
}
