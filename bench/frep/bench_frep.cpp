// Evaluator benchmark: for the shared conformance programs and our own
// convolution figure, points per second of the scalar interpreter and of the
// float batch evaluator (Google Benchmark timings), their ratio, and for a
// 128^3 grid over the model box the fraction of 8^3 leaves the interval
// evaluator proves empty or full. Prints a Markdown table; --json FILE
// writes the rows too.
//
//   ./build/release/bench/bench_frep [--json out.json] [--filter NAME]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "frep/eval/bounds.h"
#include "frep/eval/eval_batch.h"
#include "frep/eval/eval_interval.h"
#include "frep/language/interpreter.h"
#include "frep/eval/model.h"
#include "frep/language/parser.h"

namespace {

using namespace hg::frep;
namespace fs = std::filesystem;

struct Subject {
    std::string name;
    std::shared_ptr<const Program> program;
    int body = 0;
    std::vector<double> a;
    std::unique_ptr<Model> model;
    Box3 box;
    std::vector<double> x, y, z;
    std::vector<float> xf, yf, zf;
    size_t astNodes = 0;
};

struct Row {
    std::string name;
    size_t nodes = 0, tapeSize = 0;
    std::string path;
    double interpPps = 0, batchPps = 0;
    double culled = -1;  // fraction of leaves proven empty or full
};

size_t countNodes(const Expr& e) {
    size_t n = 1;
    for (const auto& a : e.args) n += countNodes(*a);
    return n;
}
size_t countNodes(const std::vector<Stmt>& stmts) {
    size_t n = 0;
    for (const Stmt& s : stmts) {
        n += 1;
        for (const Expr* e : {s.index.get(), s.value.get(), s.condition.get()})
            if (e) n += countNodes(*e);
        n += countNodes(s.thenBody) + countNodes(s.elseBody);
    }
    return n;
}

// The first a1 of the table, so selector programs run a real case.
double firstA1(const fs::path& hf) {
    fs::path tsv = hf;
    tsv.replace_extension(".tsv");
    std::ifstream in(tsv);
    std::string line;
    std::getline(in, line);
    if (!std::getline(in, line)) return 1.0;
    double v[4] = {0, 0, 0, 1};
    std::sscanf(line.c_str(), "%lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3]);
    return v[3];
}

std::unique_ptr<Subject> load(const fs::path& file, std::vector<double> a) {
    ParseResult parsed = parseFile(file.string());
    if (!parsed.ok()) return nullptr;
    auto s = std::make_unique<Subject>();
    s->name = file.stem().string();
    s->program = std::make_shared<const Program>(std::move(*parsed.program));
    s->body = s->program->defaultBody();
    s->a = std::move(a);
    s->model = std::make_unique<Model>(s->program, s->body, s->a);
    const Body& b = s->program->bodies[static_cast<size_t>(s->body)];
    s->astNodes = countNodes(b.statements) + countNodes(*b.result);
    for (const Body& other : s->program->bodies)
        if (&other != &b) s->astNodes += countNodes(other.statements) + countNodes(*other.result);
    // Model box: interval estimate when it is bounded, else a 3-unit cube.
    for (int i = 0; i < 3; ++i) { s->box.lo[i] = -1.5; s->box.hi[i] = 1.5; }
    if (s->model->tape()) {
        BoundsEstimate est = estimateBounds(*s->model->tape());
        if (!est.empty && !est.unbounded) s->box = est.box;
    }
    std::mt19937 rng(12345);
    const size_t n = 4096;
    for (size_t i = 0; i < n; ++i) {
        double p[3];
        for (int k = 0; k < 3; ++k)
            p[k] = std::uniform_real_distribution<double>(s->box.lo[k], s->box.hi[k])(rng);
        s->x.push_back(p[0]); s->y.push_back(p[1]); s->z.push_back(p[2]);
    }
    s->xf.assign(s->x.begin(), s->x.end());
    s->yf.assign(s->y.begin(), s->y.end());
    s->zf.assign(s->z.begin(), s->z.end());
    return s;
}

double cullFraction(const Subject& s) {
    const Tape* tape = s.model->tape();
    if (!tape) return -1;
    IntervalEvaluator ev(*tape);
    const int leaves = 128 / 8;
    size_t proven = 0;
    double size[3];
    for (int k = 0; k < 3; ++k) size[k] = (s.box.hi[k] - s.box.lo[k]) / leaves;
    for (int i = 0; i < leaves; ++i)
        for (int j = 0; j < leaves; ++j)
            for (int k = 0; k < leaves; ++k) {
                Interval x(s.box.lo[0] + i * size[0], s.box.lo[0] + (i + 1) * size[0]);
                Interval y(s.box.lo[1] + j * size[1], s.box.lo[1] + (j + 1) * size[1]);
                Interval z(s.box.lo[2] + k * size[2], s.box.lo[2] + (k + 1) * size[2]);
                Interval f = ev.evaluate(x, y, z);
                if (f.hi < 0.0 || f.lo > 0.0) ++proven;
            }
    return static_cast<double>(proven) / (leaves * leaves * leaves);
}

class Collector : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> itemsPerSecond;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            auto it = r.counters.find("items_per_second");
            if (it != r.counters.end()) itemsPerSecond[r.benchmark_name()] = it->second;
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

}  // namespace

int main(int argc, char** argv) {
    std::string jsonPath, filter;
    std::vector<char*> rest{argv[0]};
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--json" && i + 1 < argc) jsonPath = argv[++i];
        else if (arg == "--filter" && i + 1 < argc) filter = argv[++i];
        else rest.push_back(argv[i]);
    }

    std::vector<std::unique_ptr<Subject>> subjects;
    fs::path shared = fs::path(HG_TEST_DATA_DIR) / "hyperfun" / "conformance";
    if (fs::is_directory(shared)) {
        std::vector<fs::path> files;
        for (const auto& e : fs::directory_iterator(shared))
            if (e.path().extension() == ".hf" && e.path().stem().extension() != ".bad") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const auto& f : files)
            if (auto s = load(f, {firstA1(f)})) subjects.push_back(std::move(s));
    } else {
        std::fprintf(stderr, "note: %s not found; only the bundled figure is measured\n", shared.c_str());
    }
    if (auto s = load(fs::path(HG_SOURCE_DIR) / "content" / "hyperfun" / "dancer.hf", {0.4}))
        subjects.push_back(std::move(s));
    if (!filter.empty())
        subjects.erase(std::remove_if(subjects.begin(), subjects.end(),
                                      [&](const auto& s) { return s->name.find(filter) == std::string::npos; }),
                       subjects.end());

    for (auto& sp : subjects) {
        Subject* s = sp.get();
        benchmark::RegisterBenchmark(("interpreter/" + s->name).c_str(), [s](benchmark::State& st) {
            Interpreter interp(*s->program, s->body, s->a);
            ErrorReport errs;
            for (auto _ : st) {
                double acc = 0;
                for (size_t i = 0; i < s->x.size(); ++i) acc += interp.evaluateSafe(s->x[i], s->y[i], s->z[i], errs);
                benchmark::DoNotOptimize(acc);
            }
            st.SetItemsProcessed(static_cast<int64_t>(st.iterations()) * static_cast<int64_t>(s->x.size()));
        })->Unit(benchmark::kMicrosecond);
        if (!s->model->tape()) continue;
        benchmark::RegisterBenchmark(("batch_float/" + s->name).c_str(), [s](benchmark::State& st) {
            BatchEvaluator<float> ev(*s->model->tape());
            std::vector<float> out(s->xf.size());
            ErrorReport errs;
            for (auto _ : st) {
                ev.evaluate(s->xf.data(), s->yf.data(), s->zf.data(), out.data(), out.size(), errs);
                benchmark::DoNotOptimize(out.data());
            }
            st.SetItemsProcessed(static_cast<int64_t>(st.iterations()) * static_cast<int64_t>(out.size()));
        })->Unit(benchmark::kMicrosecond);
    }
    int bargc = static_cast<int>(rest.size());
    benchmark::Initialize(&bargc, rest.data());
    Collector collector;
    benchmark::RunSpecifiedBenchmarks(&collector);
    benchmark::Shutdown();

    std::vector<Row> rows;
    for (auto& s : subjects) {
        Row r;
        r.name = s->name;
        r.nodes = s->astNodes;
        r.tapeSize = s->model->tape() ? s->model->tape()->size() : 0;
        r.path = s->model->compiled() ? "tape" : "interpreter";
        r.interpPps = collector.itemsPerSecond["interpreter/" + s->name];
        r.batchPps = collector.itemsPerSecond["batch_float/" + s->name];
        r.culled = cullFraction(*s);
        rows.push_back(r);
    }
    std::printf("\n| program | AST nodes | tape instrs | interpreter Mpts/s | batch float Mpts/s | speedup | 8^3 leaves proven empty/full (128^3) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
    for (const Row& r : rows) {
        std::printf("| %s | %zu | %zu | %.2f | ", r.name.c_str(), r.nodes, r.tapeSize, r.interpPps / 1e6);
        if (r.batchPps > 0) std::printf("%.2f | %.1fx | %.1f%% |\n", r.batchPps / 1e6, r.batchPps / r.interpPps, 100 * r.culled);
        else std::printf("(interpreter path) | - | - |\n");
    }
    if (!jsonPath.empty()) {
        std::ofstream out(jsonPath);
        out << "[\n";
        for (size_t i = 0; i < rows.size(); ++i) {
            const Row& r = rows[i];
            out << "  {\"program\": \"" << r.name << "\", \"ast_nodes\": " << r.nodes << ", \"tape_instructions\": "
                << r.tapeSize << ", \"path\": \"" << r.path << "\", \"interpreter_points_per_s\": " << r.interpPps
                << ", \"batch_float_points_per_s\": " << r.batchPps << ", \"leaves_proven_fraction\": " << r.culled
                << "}" << (i + 1 < rows.size() ? "," : "") << "\n";
        }
        out << "]\n";
    }
    return 0;
}
