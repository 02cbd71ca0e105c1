// `hypergarden eval` as a user runs it: points read from standard input are
// answered with the reference's text (17 significant digits) on the tape and
// on the interpreter, runtime errors name their line and column, bad lines
// are reported in order, and a line is answered before the next is read.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <map>
#include <sstream>

#include "../cli_fixture.h"
#include "conformance_data.h"

namespace hg::frep {
namespace {

using test::CommandRun;
using test::runHypergarden;

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream s(text);
    std::string line;
    while (std::getline(s, line)) out.push_back(line);
    return out;
}

class EvalCli : public test::CliTest {
protected:
    void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }
};

TEST_F(EvalCli, PrintsTheReferencesTextOnEveryConformanceTable) {
    // Each table's largest group of rows sharing a1, its points as the
    // table spells them: every line must be the reference's own text.
    int tables = 0;
    for (const auto& tsv : test::tables()) {
        std::ifstream in(tsv);
        std::string row;
        std::getline(in, row);  // header
        std::map<std::string, std::vector<std::pair<std::string, std::string>>> byA;  // a1 -> (x y z, expected)
        while (std::getline(in, row)) {
            std::istringstream s(row);
            std::string f[5];
            for (auto& v : f) std::getline(s, v, '\t');
            byA[f[3]].push_back({f[0] + " " + f[1] + " " + f[2], f[4]});
        }
        auto group = byA.begin();
        for (auto it = byA.begin(); it != byA.end(); ++it)
            if (it->second.size() > group->second.size()) group = it;
        ASSERT_NE(group, byA.end()) << tsv;
        std::string points;
        for (const auto& [p, expected] : group->second) points += p + "\n";
        write("points.txt", points);
        auto hf = tsv;
        hf.replace_extension(".hf");
        for (const char* mode : {"", " --interpreter"}) {
            CommandRun r = runHypergarden("eval '" + hf.string() + "'" + mode + " --a " + group->first + " < " +
                                          path("points.txt"));
            ASSERT_EQ(r.status, 0) << tsv << mode << "\n" << r.output;
            auto got = lines(r.output);
            ASSERT_EQ(got.size(), group->second.size()) << tsv << mode;
            for (size_t i = 0; i < got.size(); ++i) {
                const std::string& want = group->second[i].second;
                if (want == "error") EXPECT_EQ(got[i].rfind("error: ", 0), 0u) << tsv << mode << " row " << i;
                else EXPECT_EQ(got[i], want) << tsv << mode << " row " << i << ": " << group->second[i].first;
            }
        }
        ++tables;
    }
    EXPECT_GE(tables, 38);
}

// Line 6: sqrt fails for x < 0; line 10: hfConvArc is NaN at its centre.
constexpr const char* kErrors =
    "m(x[3], a[1])\n"
    "{\n"
    "   array cen[3], rad[1], span[1], axis[3], turn[1], w[1];\n"
    "   cen = [0, 0, 0]; rad = [1]; span = [120]; axis = [0, 0, 1]; turn = [30]; w = [3];\n"
    "   if x[3] < 0 then\n"
    "      q = sqrt(x[1]);\n"
    "   else\n"
    "      q = 0;\n"
    "   endif;\n"
    "   m = q + hfConvArc(x, cen, rad, span, axis, turn, w, 0.5);\n"
    "}\n";

TEST_F(EvalCli, RuntimeErrorsNameTheirLineAndColumnOnBothPaths) {
    write("errors.hf", kErrors);
    write("points.txt", "1 0 -1\n-1 0 -1\n0 0 0\n\n0.5 0.5 0.5\n");
    const std::vector<std::string> want = {
        "0.50412238326883774",  // the reference's values, measured with pmur002/hyperfun
        "error: square root of a negative number at line 6, column 11",
        "error: computation produced NaN at line 10, column 12",
        "-0.44611280507924839",
    };
    for (const char* mode : {"", " --interpreter"}) {
        CommandRun r = runHypergarden("eval " + path("errors.hf") + mode + " < " + path("points.txt"));
        EXPECT_EQ(r.status, 0) << r.output;
        EXPECT_EQ(lines(r.output), want) << mode;
    }
    // One point on the command line: the same answer.
    CommandRun one = runHypergarden("eval " + path("errors.hf") + " 0 0 0");
    EXPECT_EQ(lines(one.output), std::vector<std::string>{want[2]});
}

// Many points of a long program of bounded pieces: evaluated in groups
// with the tape specialized to each group's box, the text is the same as
// with the full tape at every point (HG_NO_SPECIALIZE=1), failures and
// their locations included.
TEST_F(EvalCli, PointsEvaluatedByRegionGiveTheFullTapesText) {
    std::string body = "  f = max(min((0.8 - (x[1]^2 + x[2]^2 + x[3]^2)) * 40, 3), -3);\n";
    for (int i = 0; i < 120; ++i) {
        const double c = -0.9 + 0.015 * i;
        const std::string d = "((x[1] - " + std::to_string(c) + ")^2 + (x[2] - " + std::to_string(-c) + ")^2 + x[3]^2)";
        const std::string g = "max(min((0.004 - " + d + ") * 400, 3), -3)";
        body += i % 2 ? "  f = min(f, -" + g + ");\n" : "  f = max(f, " + g + ");\n";
    }
    // A failing piece far from everything else: sqrt of a negative number there.
    body += "  f = f + sqrt(x[1] - 5) * 0;\n";
    write("edited.hf", "edited(x[3], a[1]) {\n" + body + "  edited = f;\n}\n");
    std::string points;
    for (int i = 0; i < 6000; ++i) {
        const double t = i / 6000.0;
        char line[96];
        std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", -1.0 + 2.0 * t + 0.001 * (i % 7), 0.9 - 1.8 * t,
                      0.01 * (i % 13) - 0.06);
        points += line;
    }
    points += "6 0 0\n4 0 0\n";
    write("points.txt", points);
    const CommandRun region = runHypergarden("eval " + path("edited.hf") + " < " + path("points.txt"));
    const CommandRun full = runHypergarden("eval " + path("edited.hf") + " < " + path("points.txt") + " ", "HG_NO_SPECIALIZE=1");
    EXPECT_EQ(lines(region.output).size(), 6002u);
    EXPECT_EQ(region.output, full.output);
    EXPECT_EQ(region.status, full.status);
}

TEST_F(EvalCli, BadLinesAreReportedInOrderAndFailTheRun) {
    write("sphere.hf", "m(x[3], a[1]) { array c[3]; c = [0, 0, 0]; m = hfSphere(x, c, 1); }\n");
    // istream's rules: "1e" and hexadecimal are not numbers, trailing text
    // after the third number is ignored, CR LF line ends are fine.
    write("points.txt", "0 0 0\n1e 0 0\n0.5 0 0 extra\r\n0x1 0 0\n1 1 1");
    CommandRun r = runHypergarden("eval " + path("sphere.hf") + " < " + path("points.txt"));
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(lines(r.output), (std::vector<std::string>{
                                   "1",
                                   "<stdin>:2: error: expected three numbers \"x y z\", got \"1e 0 0\"",
                                   "0.75",
                                   "<stdin>:4: error: expected three numbers \"x y z\", got \"0x1 0 0\"",
                                   "-2",
                               }));
}

TEST_F(EvalCli, ValuesBeyondTheLimitAreTheReferences) {
    std::string chain = "m(x[3], a[1])\n{\n   f = x[1];\n";
    for (int i = 0; i < 150; ++i) chain += "   f = f \\ (x[2] - " + std::to_string(i % 7) + ");\n";
    write("chain.hf", chain + "   m = f;\n}\n");
    for (const char* mode : {"", " --interpreter"}) {
        CommandRun r = runHypergarden("eval " + path("chain.hf") + mode + " 5 5 5");
        EXPECT_EQ(r.output, "-7.6875879034757266e+45\n") << mode;  // pmur002/hyperfun's value
    }
}

// Waits up to 30 s (a guard against hanging, not a timing) for a line.
std::string readLine(int fd) {
    std::string line;
    char c;
    while (line.empty() || line.back() != '\n') {
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, 30000) <= 0 || ::read(fd, &c, 1) != 1) break;
        line += c;
    }
    return line;
}

TEST_F(EvalCli, AnswersEachLineBeforeReadingTheNextWithoutLoadingOpenVdb) {
#ifdef HG_HYPERGARDEN_EXE
    write("sphere.hf", "m(x[3], a[1]) { array c[3]; c = [0, 0, 0]; m = hfSphere(x, c, 1); }\n");
    int in[2], out[2];
    ASSERT_EQ(::pipe(in), 0);
    ASSERT_EQ(::pipe(out), 0);
    const std::string file = (dir / "sphere.hf").string();
    pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        ::dup2(in[0], 0);
        ::dup2(out[1], 1);
        ::close(in[1]);
        ::close(out[0]);
        ::execl(HG_HYPERGARDEN_EXE, HG_HYPERGARDEN_EXE, "eval", file.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(in[0]);
    ::close(out[1]);
    // A program at the other end of a pipe writes a point and waits.
    ASSERT_EQ(::write(in[1], "0 0 0\n", 6), 6);
    EXPECT_EQ(readLine(out[0]), "1\n");
    // Still running, waiting for its next line: eval and check never load
    // OpenVDB (it took ~40 ms of start-up), see cli/full_executable.h.
    std::ifstream maps("/proc/" + std::to_string(pid) + "/maps");
    std::string m((std::istreambuf_iterator<char>(maps)), std::istreambuf_iterator<char>());
    EXPECT_NE(m.find("hypergarden"), std::string::npos);
    EXPECT_EQ(m.find("libopenvdb"), std::string::npos);
    ASSERT_EQ(::write(in[1], "0.5 0 0\n", 8), 8);
    EXPECT_EQ(readLine(out[0]), "0.75\n");
    ::close(in[1]);
    EXPECT_EQ(readLine(out[0]), "");
    ::close(out[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
#endif
}

}  // namespace
}  // namespace hg::frep
