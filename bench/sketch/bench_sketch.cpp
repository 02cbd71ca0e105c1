// Sketch to sculpture (issue 22): the time from a raw path to a solid ready
// to evaluate, for outlines of 50, 200 and 1,000 samples (target: 200
// samples within one 11.1 ms frame). Each stage is timed on its own (best
// of --repeat runs): the outline from the raw path, the constrained
// Delaunay triangulation, the chordal axis, the pieces (inflate() runs the
// triangulation and axis again inside, so "inflate" is the whole of
// outline -> pieces), the HyperFun text, and parsing and compiling that
// text to a tape. Single-threaded. Prints a Markdown table; --json FILE
// writes the rows.
//
//   ./build/release/bench/bench_sketch [--json out.json] [--filter N] [--repeat N]
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/bench_common.h"
#include "garden/sketch/chordal_axis.h"
#include "garden/sketch/inflation.h"
#include "garden/sketch/inflation_text.h"
#include "garden/sketch/outline.h"
#include "garden/sketch/triangulation.h"

namespace {

using namespace hg::garden::sketch;

// A five-lobed blob about 0.7 m across drawn with 4 raw points per sample
// and a little tremor: lobes give junctions, sleeves and pruned ends.
std::vector<Vec2> blobPath(int samples) {
    std::vector<Vec2> p;
    const int count = 4 * samples;
    for (int i = 0; i < count; ++i) {
        const double a = 2.0 * 3.141592653589793 * i / count;
        const double r = 0.25 + 0.1 * std::sin(5.0 * a) + 0.002 * std::sin(97.0 * a);
        p.push_back(r * Vec2(std::cos(a), std::sin(a)));
    }
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    hg::bench::BenchArgs args;
    if (!hg::bench::parseBenchArgs(argc, argv, args)) return 2;
    const SketchPlane plane = planeFacing(Vec3(0.0, 1.0, 0.0), Vec3(0.0, 0.0, 1.0));
    nlohmann::json rows = nlohmann::json::array();
    std::printf("| samples | pieces | spokes | outline (ms) | CDT (ms) | axis (ms) | inflate (ms) | text (ms) | "
                "parse+compile (ms) | inflation total (ms) |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int samples : {50, 200, 1000}) {
        if (!args.matches(std::to_string(samples))) continue;
        const std::vector<Vec2> raw = blobPath(samples);
        OutlineOptions oo;
        oo.samples = samples;
        Outline outline;
        const double tOutline = hg::bench::bestOf(args.repeat, [&] { outline = makeOutline(raw, oo); });
        if (!outline.ok()) {
            std::fprintf(stderr, "%d samples: %s\n", samples, outline.error.c_str());
            return 1;
        }
        Triangulation tri;
        const double tCdt = hg::bench::bestOf(args.repeat, [&] { tri = triangulatePolygon(outline.points); });
        ChordalAxis axis;
        const double tAxis = hg::bench::bestOf(args.repeat, [&] { axis = chordalAxis(outline.points, tri); });
        Inflation inf;
        const double tInflate =
            hg::bench::bestOf(args.repeat, [&] { inf = inflate(outline.points, outline.spacing, plane); });
        if (!inf.ok()) {
            std::fprintf(stderr, "%d samples: %s\n", samples, inf.error.c_str());
            return 1;
        }
        std::string text;
        const double tText = hg::bench::bestOf(args.repeat, [&] { text = inflatedHyperFun(inf.solid); });
        std::string error;
        bool compiled = false;
        const double tCompile = hg::bench::bestOf(args.repeat, [&] { compiled = compileHyperFun(text, error).has_value(); });
        if (!compiled) {
            std::fprintf(stderr, "%d samples: %s\n", samples, error.c_str());
            return 1;
        }
        const double total = tInflate + tText + tCompile;
        std::printf("| %d | %zu | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", samples,
                    inf.solid.pieces.size(), inf.spokes, 1e3 * tOutline, 1e3 * tCdt, 1e3 * tAxis, 1e3 * tInflate,
                    1e3 * tText, 1e3 * tCompile, 1e3 * total);
        rows.push_back({{"samples", samples},
                        {"pieces", inf.solid.pieces.size()},
                        {"spokes", inf.spokes},
                        {"text_bytes", text.size()},
                        {"outline_ms", 1e3 * tOutline},
                        {"cdt_ms", 1e3 * tCdt},
                        {"axis_ms", 1e3 * tAxis},
                        {"inflate_ms", 1e3 * tInflate},
                        {"text_ms", 1e3 * tText},
                        {"compile_ms", 1e3 * tCompile},
                        {"inflation_total_ms", 1e3 * total}});
    }
    std::printf("\ninflation total = inflate + text + parse+compile (outline -> a compiled model); target: 200 samples "
                "within 11.1 ms\n");
    if (!args.jsonPath.empty()) std::ofstream(args.jsonPath) << rows.dump(2) << "\n";
    return 0;
}
