// Export meshing benchmark: poly::meshVolume (one level, welded triangles
// with gradient normals) against OpenVDB's tools::volumeToMesh on the same
// grid (isovalue 0, adaptivity 0: shared points, quads, no normals), at
// 128^3 and 256^3, for our sculptures and an analytic sphere and torus;
// then `hypergarden mesh` end to end on the union of 64 spheres
// (end_to_end.cpp). Prints Markdown tables; --json FILE writes the rows too
// ({"export_mesher": [...], "end_to_end": [...]}).
//
//   ./build/release/bench/bench_poly [--json out.json] [--filter NAME] [--repeat N]
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../bench_common.h"
#include "end_to_end.h"

#include "frep/language/parser.h"
#include "polygonizer/export/export_mesher.h"
#include "voxel/sampler.h"
#include "voxel/volume_vdb.h"

namespace {

using namespace hg;
using bench::bestOf;
namespace fs = std::filesystem;

struct Source {
    std::string name;
    std::string text;  // program text, or "" with a file
    fs::path file;
};

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, args)) return 2;
    const std::string& jsonPath = args.jsonPath;
    const std::string& filter = args.filter;
    const int repeat = args.repeat;
    std::vector<Source> sources = {
        {"sphere", "q(x[3], a[1]) { q = 0.64 - (x[1]^2 + x[2]^2 + x[3]^2); }", {}},
        {"torus", "q(x[3], a[1]) { array c[3]; c = [0, 0, 0]; q = hfTorusY(x, c, 0.6, 0.2); }", {}},
    };
    for (const char* n : {"key_dryad", "key_orant", "key_knot", "path_boulder"})
        sources.push_back({n, "", fs::path(HG_SOURCE_DIR) / "content" / "hyperfun" / (std::string(n) + ".hf")});

    nlohmann::json rows = nlohmann::json::array();
    std::printf("| model | res | triangles (ours) | vertices (ours) | ours (ms) | volumeToMesh (ms) | polygons (OpenVDB) "
                "| points (OpenVDB) | volumeToMesh / ours |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Source& s : sources) {
        if (!filter.empty() && s.name.find(filter) == std::string::npos) continue;
        frep::ParseResult r = s.text.empty() ? frep::parseFile(s.file.string()) : frep::parseProgram(s.text, s.name);
        if (!r.ok()) continue;
        auto program = std::make_shared<const frep::Program>(std::move(*r.program));
        frep::Model model(program, program->defaultBody());
        for (int res : {128, 256}) {
            voxel::VolumeRequest req;
            req.resolution = res;
            voxel::VoxelizeResult v = voxel::voxelize(model, req);
            if (!v.volume) continue;
            poly::Mesh mesh;
            double ours = bestOf(repeat, [&] { mesh = poly::meshVolume(*v.volume); });
            std::vector<openvdb::Vec3s> points;
            std::vector<openvdb::Vec3I> tris;
            std::vector<openvdb::Vec4I> quads;
            double theirs = bestOf(repeat, [&] {
                points.clear(); tris.clear(); quads.clear();
                openvdb::tools::volumeToMesh(voxel::vdb(*v.volume), points, tris, quads, 0.0, 0.0, false);
            });
            std::size_t polys = tris.size() + 2 * quads.size();
            std::printf("| %s | %d^3 | %zu | %zu | %.1f | %.1f | %zu | %zu | %.2fx |\n", s.name.c_str(), res,
                        mesh.triangleCount(), mesh.vertexCount(), ours * 1e3, theirs * 1e3, polys, points.size(),
                        theirs / ours);
            std::fflush(stdout);
            rows.push_back({{"model", s.name}, {"res", res}, {"triangles", mesh.triangleCount()},
                            {"vertices", mesh.vertexCount()}, {"ours_ms", ours * 1e3},
                            {"volume_to_mesh_ms", theirs * 1e3}, {"openvdb_triangles", polys},
                            {"openvdb_points", points.size()}});
        }
    }
    nlohmann::json endToEnd = bench::benchMeshEndToEnd(args);
    if (!jsonPath.empty())
        std::ofstream(jsonPath) << nlohmann::json{{"export_mesher", rows}, {"end_to_end", endToEnd}}.dump(2) << "\n";
    return 0;
}
