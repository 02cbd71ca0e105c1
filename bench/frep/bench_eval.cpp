// `hypergarden eval` as a process, the way a user or a script runs it: the
// wall time of start-up with no points, and of 100,000 points on standard
// input for each HyperFun program with a reference table (the conformance
// suite and the corpus, the corpus sphere among them), on the program's
// path (tape, or the interpreter where it does not compile) and with
// --interpreter. With --reference PATH, an external HyperFun interpreter
// (built by the developer outside the repository, for example around
// pmur002/hyperfun's HF_parse and HF_calc) runs on the same inputs in the
// same run, as `PATH FILE.hf A1 < points`, printing one line per point; the
// table then gives its time, the speed ratio and whether the outputs agree
// line for line (a failure is any line starting "error", or "nan"). Best of
// --repeat runs; prints a Markdown table, --json FILE writes the rows too.
//
//   ./build/release/bench/bench_eval [--json out.json] [--filter NAME] [--repeat N]
//                                    [--points N] [--reference PATH]
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "frep/eval/model.h"
#include "frep/language/parser.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;

struct Args {
    std::string jsonPath, filter, reference;
    int repeat = 3;
    size_t points = 100000;
};

bool parseArgs(int argc, char** argv, Args& a) {
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--json" && i + 1 < argc) a.jsonPath = argv[++i];
        else if (arg == "--filter" && i + 1 < argc) a.filter = argv[++i];
        else if (arg == "--repeat" && i + 1 < argc) a.repeat = std::max(1, std::atoi(argv[++i]));
        else if (arg == "--points" && i + 1 < argc) a.points = static_cast<size_t>(std::max(1, std::atoi(argv[++i])));
        else if (arg == "--reference" && i + 1 < argc) a.reference = argv[++i];
        else {
            std::fprintf(stderr,
                         "usage: %s [--json FILE] [--filter NAME] [--repeat N] [--points N] [--reference PATH]\n",
                         argv[0]);
            return false;
        }
    }
    return true;
}

// Runs argv with stdin from `in` and stdout to `out`; seconds of wall time,
// or a negative number when it could not run or exited non-zero.
double timeProcess(const std::vector<std::string>& args, const std::string& in, const std::string& out) {
    std::vector<char*> argv;
    for (const auto& s : args) argv.push_back(const_cast<char*>(s.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, in.c_str(), O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    const auto t0 = std::chrono::steady_clock::now();
    pid_t pid = 0;
    int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) return -1;
    int status = 0;
    waitpid(pid, &status, 0);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? s : -1;
}

double bestOf(int repeat, const std::vector<std::string>& args, const std::string& in, const std::string& out) {
    double best = -1;
    for (int i = 0; i < repeat; ++i) {
        double s = timeProcess(args, in, out);
        if (s < 0) return -1;
        best = best < 0 ? s : std::min(best, s);
    }
    return best;
}

std::vector<std::string> readLines(const std::string& path) {
    std::vector<std::string> lines;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        bool failure = line.rfind("error", 0) == 0 || line.find("nan") != std::string::npos;
        lines.push_back(failure ? "error" : line);
    }
    return lines;
}

// Lines that differ (a missing line counts), or -1 when the counts differ.
long differences(const std::string& a, const std::string& b) {
    auto la = readLines(a), lb = readLines(b);
    if (la.size() != lb.size()) return -1;
    long n = 0;
    for (size_t i = 0; i < la.size(); ++i) n += la[i] != lb[i];
    return n;
}

struct Program {
    std::string name;
    fs::path file;
    std::string a1;  // as the table spells it
    double lo[3] = {1e30, 1e30, 1e30}, hi[3] = {-1e30, -1e30, -1e30};
};

// The programs with a table; the points' box and the first row's a1.
std::vector<Program> programs() {
    std::vector<Program> out;
    const fs::path root = fs::path(HG_TEST_DATA_DIR) / "hyperfun";
    for (const char* sub : {"conformance", "corpus"}) {
        std::vector<fs::path> tables;
        for (const auto& e : fs::directory_iterator(root / sub))
            if (e.path().extension() == ".tsv") tables.push_back(e.path());
        std::sort(tables.begin(), tables.end());
        for (const auto& tsv : tables) {
            Program p;
            p.name = tsv.stem().string();
            p.file = tsv;
            p.file.replace_extension(".hf");
            std::ifstream in(tsv);
            std::string line;
            std::getline(in, line);
            while (std::getline(in, line)) {
                std::istringstream s(line);
                std::string f[4];
                for (auto& v : f) std::getline(s, v, '\t');
                if (p.a1.empty()) p.a1 = f[3];
                for (int k = 0; k < 3; ++k) {
                    double v = std::strtod(f[k].c_str(), nullptr);
                    p.lo[k] = std::min(p.lo[k], v);
                    p.hi[k] = std::max(p.hi[k], v);
                }
            }
            out.push_back(p);
        }
    }
    return out;
}

// n points uniform in the box of the table's points, widened by a tenth.
void writePoints(const Program& p, size_t n, const std::string& path) {
    std::mt19937 rng(12345);
    std::ofstream out(path);
    char buf[96];
    for (size_t i = 0; i < n; ++i) {
        double v[3];
        for (int k = 0; k < 3; ++k) {
            double pad = 0.1 * (p.hi[k] - p.lo[k]) + 1e-3;
            v[k] = std::uniform_real_distribution<double>(p.lo[k] - pad, p.hi[k] + pad)(rng);
        }
        std::snprintf(buf, sizeof buf, "%.6g %.6g %.6g\n", v[0], v[1], v[2]);
        out << buf;
    }
}

std::string evalPath(const Program& p) {
    hg::frep::ParseResult r = hg::frep::parseFile(p.file.string());
    if (!r.ok()) return "?";
    auto program = std::make_shared<const hg::frep::Program>(std::move(*r.program));
    hg::frep::Model model(program, program->defaultBody(), {std::strtod(p.a1.c_str(), nullptr)});
    return model.compiled() ? "tape" : "interpreter";
}

struct Row {
    std::string name, path;
    double eval = -1, interp = -1, reference = -1;
    long interpDiffer = -2, refDiffer = -2;  // lines differing from eval's (-2: not compared)
};

std::string agreement(long differ) {
    return differ == -2 ? "-" : differ < 0 ? "line counts differ" : differ == 0 ? "same" : std::to_string(differ) + " differ";
}

std::string ms(double s) {
    if (s < 0) return "-";
    char b[32];
    std::snprintf(b, sizeof b, "%.1f", s * 1e3);
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    Args args;
    if (!parseArgs(argc, argv, args)) return 2;
    const std::string exe = HG_HYPERGARDEN_EXE;
    const std::string full = (fs::path(exe).parent_path() / "hypergarden-full").string();
    const fs::path tmp = fs::temp_directory_path() / ("hg_bench_eval_" + std::to_string(getpid()));
    fs::create_directories(tmp);
    const std::string pts = (tmp / "points.txt").string(), none = "/dev/null";
    const std::string ours = (tmp / "ours.txt").string(), theirs = (tmp / "reference.txt").string();
    const bool withRef = !args.reference.empty();

    std::vector<Row> rows;
    auto all = programs();
    // Start-up: a point-free run of the sphere, many times (it is short);
    // and the same in the executable that links everything (OpenVDB, GL),
    // which is what eval's start-up cost before it had its own.
    const int startRepeat = std::max(args.repeat, 20);
    for (const Program& p : all) {
        if (p.name != "sphere") continue;
        Row r;
        r.name = "start-up, no points (sphere)";
        r.path = "hypergarden";
        r.eval = bestOf(startRepeat, {exe, "eval", p.file.string()}, none, ours);
        if (withRef) r.reference = bestOf(startRepeat, {args.reference, p.file.string(), p.a1}, none, theirs);
        rows.push_back(r);
        r.name = "start-up, no points (sphere)";
        r.path = "hypergarden-full";
        r.eval = bestOf(startRepeat, {full, "eval", p.file.string()}, none, ours);
        rows.push_back(r);
    }
    for (const Program& p : all) {
        if (!args.filter.empty() && p.name.find(args.filter) == std::string::npos) continue;
        writePoints(p, args.points, pts);
        Row r;
        r.name = p.name;
        r.path = evalPath(p);
        r.eval = bestOf(args.repeat, {exe, "eval", p.file.string(), "--a", p.a1}, pts, ours);
        r.interp = bestOf(args.repeat, {exe, "eval", "--interpreter", p.file.string(), "--a", p.a1}, pts, theirs);
        r.interpDiffer = differences(ours, theirs);
        if (withRef) {
            r.reference = bestOf(args.repeat, {args.reference, p.file.string(), p.a1}, pts, theirs);
            r.refDiffer = differences(ours, theirs);
        }
        rows.push_back(r);
        std::fprintf(stderr, "%s done\n", p.name.c_str());
    }
    fs::remove_all(tmp);

    std::printf("| program | path | eval ms | eval --interpreter ms | reference ms | eval speed / reference's |"
                " --interpreter output | reference output |\n");
    std::printf("|---|---|---:|---:|---:|---:|---|---|\n");
    double worst = 1e30;
    std::string worstName;
    nlohmann::json json = nlohmann::json::array();
    for (const Row& r : rows) {
        std::string ratio = "-";
        if (r.reference > 0 && r.eval > 0) {
            char b[32];
            std::snprintf(b, sizeof b, "%.2fx", r.reference / r.eval);
            ratio = b;
            if (r.refDiffer != -2 && r.reference / r.eval < worst) {
                worst = r.reference / r.eval;
                worstName = r.name;
            }
        }
        std::printf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", r.name.c_str(), r.path.c_str(), ms(r.eval).c_str(),
                    ms(r.interp).c_str(), ms(r.reference).c_str(), ratio.c_str(), agreement(r.interpDiffer).c_str(),
                    agreement(r.refDiffer).c_str());
        json.push_back({{"program", r.name}, {"path", r.path}, {"eval_ms", r.eval * 1e3},
                        {"interpreter_ms", r.interp * 1e3}, {"reference_ms", r.reference * 1e3},
                        {"interpreter_differing_lines", r.interpDiffer}, {"reference_differing_lines", r.refDiffer}});
    }
    std::printf("\n%zu points per program, best of %d runs (start-up: %d).\n", args.points, args.repeat, startRepeat);
    if (withRef && worst < 1e30)
        std::printf("Slowest against the reference: %s, %.2fx the reference's speed.\n", worstName.c_str(), worst);
    if (!args.jsonPath.empty()) std::ofstream(args.jsonPath) << json.dump(2) << "\n";
    return 0;
}
