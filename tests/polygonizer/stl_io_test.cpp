// STL export for printing: binary and ASCII files read back to the same
// solid (scaled to millimetres), floats survive exactly, the binary layout
// is the standard little-endian one, awkward and broken files give clear
// errors, failed writes leave nothing behind, and ADMesh, an independent
// checker, finds nothing to repair in what we write.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "mesh_validation_reference.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"

namespace hg::poly {
namespace {

namespace fs = std::filesystem;

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("hg_stl_io_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(path)) names.push_back(e.path().filename().string());
        return names;
    }
};

// Axis-aligned cube, 8 shared vertices, 12 triangles counter-clockwise
// seen from outside (vertex k has x = bit 0, y = bit 1, z = bit 2).
Mesh cube(float x = 0, float y = 0, float z = 0, float size = 1) {
    Mesh m;
    for (int k = 0; k < 8; ++k) {
        m.positions.push_back(x + size * static_cast<float>(k & 1));
        m.positions.push_back(y + size * static_cast<float>((k >> 1) & 1));
        m.positions.push_back(z + size * static_cast<float>((k >> 2) & 1));
    }
    const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) m.indices.insert(m.indices.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
    return m;
}

Mesh concatenate(Mesh a, const Mesh& b) {
    const auto offset = static_cast<std::uint32_t>(a.vertexCount());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (std::uint32_t i : b.indices) a.indices.push_back(i + offset);
    return a;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void spit(const std::string& path, const std::string& data) {
    std::ofstream out(path, std::ios::binary);
    out << data;
}

std::uint32_t u32At(const std::string& data, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(data[at + i]);
    return v;
}

float f32At(const std::string& data, std::size_t at) {
    const std::uint32_t bits = u32At(data, at);
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(StlIo, BinaryRoundTripScalesToMillimetres) {
    TempDir dir;
    const std::string path = dir.file("cube.stl");
    ASSERT_EQ(writeStl(cube(), path, false, 10.0), "");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"cube.stl"}) << "no temporary file is left";
    EXPECT_EQ(fs::file_size(path), 84u + 50u * 12u);

    const StlReadResult r = readStl(path);
    ASSERT_EQ(r.error, "");
    EXPECT_FALSE(r.ascii);
    EXPECT_EQ(r.solidName, "hypergarden");
    EXPECT_EQ(r.mesh.triangleCount(), 12u);
    EXPECT_EQ(r.mesh.vertexCount(), 36u) << "reading gives a triangle soup";

    const Mesh welded = weldByPosition(r.mesh);
    EXPECT_EQ(welded.vertexCount(), 8u);
    const MeshReport report = validateMesh(welded);
    EXPECT_TRUE(report.ok()) << describe(report);
    EXPECT_EQ(report.volume, 1000.0);
    EXPECT_EQ(report.boxMax[0], 10.0f);
}

TEST(StlIo, AsciiRoundTripScalesToMillimetres) {
    TempDir dir;
    const std::string path = dir.file("cube.stl");
    ASSERT_EQ(writeStl(cube(), path, true, 10.0, "garden cube"), "");
    const std::string text = slurp(path);
    EXPECT_EQ(text.rfind("solid garden cube\n", 0), 0u) << text.substr(0, 40);
    EXPECT_TRUE(contains(text, "\nendsolid garden cube\n"));
    EXPECT_TRUE(contains(text, "facet normal 0 0 -1\n    outer loop\n      vertex 0 0 0\n      vertex 10 10 0\n"))
        << text.substr(0, 200);

    const StlReadResult r = readStl(path);
    ASSERT_EQ(r.error, "");
    EXPECT_TRUE(r.ascii);
    EXPECT_EQ(r.solidName, "garden cube");
    EXPECT_EQ(r.mesh.triangleCount(), 12u);
    const MeshReport report = validateMesh(weldByPosition(r.mesh));
    EXPECT_TRUE(report.ok()) << describe(report);
    EXPECT_EQ(report.volume, 1000.0);
}

TEST(StlIo, FloatsRoundTripExactlyInBothFormats) {
    TempDir dir;
    Mesh m;
    m.positions = {0.1f, 1.0f / 3, -1e-7f, 123456.789f, -2.5e-38f, 3.4e38f, 16777217.0f, 0.3f, -0.0f};
    m.indices = {0, 1, 2};
    for (bool ascii : {false, true}) {
        const std::string path = dir.file(ascii ? "a.stl" : "b.stl");
        ASSERT_EQ(writeStl(m, path, ascii), "");
        const StlReadResult r = readStl(path);
        ASSERT_EQ(r.error, "");
        ASSERT_EQ(r.mesh.positions.size(), m.positions.size());
        for (std::size_t i = 0; i < m.positions.size(); ++i)
            EXPECT_EQ(std::memcmp(&r.mesh.positions[i], &m.positions[i], sizeof(float)), 0)
                << (ascii ? "ASCII" : "binary") << " coordinate " << i << ": " << r.mesh.positions[i] << " vs "
                << m.positions[i];
    }
}

TEST(StlIo, BinaryLayoutIsStandardLittleEndian) {
    TempDir dir;
    const std::string path = dir.file("cube.stl");
    Mesh m = cube();
    // Vertex normals are not facet normals; the writer must not use them.
    m.normals.assign(m.positions.size(), 0.0f);
    ASSERT_EQ(writeStl(m, path, false, 2.0), "");
    const std::string data = slurp(path);
    ASSERT_EQ(data.size(), 84u + 50u * 12u);
    EXPECT_NE(data.compare(0, 5, "solid"), 0) << "a binary header that starts with 'solid' confuses readers";
    EXPECT_EQ(u32At(data, 80), 12u);
    // First facet: z = 0, corners 0, 2, 3 of the cube.
    const std::size_t f = 84;
    EXPECT_EQ(f32At(data, f + 0), 0.0f);
    EXPECT_EQ(f32At(data, f + 4), 0.0f);
    EXPECT_EQ(f32At(data, f + 8), -1.0f);
    const float corners[9] = {0, 0, 0, 0, 2, 0, 2, 2, 0};
    for (int k = 0; k < 9; ++k) EXPECT_EQ(f32At(data, f + 12 + 4 * k), corners[k]) << "coordinate " << k;
    EXPECT_EQ(data[f + 48], '\0');
    EXPECT_EQ(data[f + 49], '\0');
    // Byte order spelled out: 2.0f is 0x40000000.
    EXPECT_EQ(static_cast<unsigned char>(data[f + 12 + 4 * 4 + 3]), 0x40u);
    EXPECT_EQ(static_cast<unsigned char>(data[f + 12 + 4 * 4]), 0x00u);
}

TEST(StlIo, BinaryFileWhoseHeaderStartsWithSolid) {
    TempDir dir;
    const std::string path = dir.file("cube.stl");
    ASSERT_EQ(writeStl(cube(), path), "");
    std::string data = slurp(path);
    const std::string header = "solid cube exported by some CAD program";
    data.replace(0, header.size(), header);
    spit(path, data);

    const StlReadResult r = readStl(path);
    ASSERT_EQ(r.error, "");
    EXPECT_FALSE(r.ascii);
    EXPECT_EQ(r.mesh.triangleCount(), 12u);
    EXPECT_TRUE(validateMesh(weldByPosition(r.mesh)).ok());
}

TEST(StlIo, AsciiFromOtherExporters) {
    // Upper-case keywords, CRLF, exponents with signs, a leading '+', and
    // two solids in one file.
    TempDir dir;
    const std::string path = dir.file("other.stl");
    spit(path,
         "SOLID part one\r\n"
         "FACET NORMAL 0.000000e+00 0.000000e+00 -1.000000e+00\r\n"
         "OUTER LOOP\r\n"
         "VERTEX 0.000000e+00 0.000000e+00 0.000000e+00\r\n"
         "VERTEX 1.000000e+00 +1.0 0\r\n"
         "VERTEX 1.0E+00 0 0\r\n"
         "ENDLOOP\r\n"
         "ENDFACET\r\n"
         "ENDSOLID part one\r\n"
         "solid two\n"
         "facet normal 0 0 1 outer loop vertex 0 0 1 vertex 1 0 1 vertex 1 1 1 endloop endfacet\n"
         "endsolid\n");
    const StlReadResult r = readStl(path);
    ASSERT_EQ(r.error, "");
    EXPECT_TRUE(r.ascii);
    EXPECT_EQ(r.solidName, "part one");
    ASSERT_EQ(r.mesh.triangleCount(), 2u);
    EXPECT_EQ(r.mesh.positions[4], 1.0f);
    EXPECT_EQ(r.mesh.positions[17], 1.0f);
}

TEST(StlIo, TruncatedBinaryIsAnError) {
    TempDir dir;
    const std::string path = dir.file("cube.stl");
    ASSERT_EQ(writeStl(cube(), path), "");
    std::string data = slurp(path);
    spit(path, data.substr(0, data.size() - 20));
    StlReadResult r = readStl(path);
    EXPECT_TRUE(contains(r.error, path)) << r.error;
    EXPECT_TRUE(contains(r.error, "truncated")) << r.error;
    EXPECT_TRUE(r.mesh.empty());

    // Still binary, not an ASCII syntax error, when the header says "solid".
    data.replace(0, 6, "solid ");
    spit(path, data.substr(0, data.size() - 20));
    r = readStl(path);
    EXPECT_TRUE(contains(r.error, "truncated")) << r.error;

    spit(path, data.substr(0, 50));
    r = readStl(path);
    EXPECT_TRUE(contains(r.error, path)) << r.error;
    EXPECT_TRUE(contains(r.error, "truncated")) << r.error;
    EXPECT_TRUE(r.mesh.empty());
}

TEST(StlIo, MalformedAsciiNamesTheLine) {
    TempDir dir;
    const std::string path = dir.file("bad.stl");
    spit(path,
         "solid bad\n"
         "  facet normal 0 0 1\n"
         "    outer loop\n"
         "      vertex 0 0 0\n"
         "      vertx 1 0 0\n"
         "      vertex 0 1 0\n"
         "    endloop\n"
         "  endfacet\n"
         "endsolid bad\n");
    StlReadResult r = readStl(path);
    EXPECT_TRUE(contains(r.error, path)) << r.error;
    EXPECT_TRUE(contains(r.error, "line 5: expected 'vertex'")) << r.error;
    EXPECT_TRUE(contains(r.error, "'vertx'")) << r.error;
    EXPECT_TRUE(r.mesh.empty());

    spit(path, "solid bad\nfacet normal 0 0 1\nouter loop\nvertex 0 zero 0\n");
    r = readStl(path);
    EXPECT_TRUE(contains(r.error, "line 4: expected a number, found 'zero'")) << r.error;

    spit(path, "solid bad\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n");
    r = readStl(path);
    EXPECT_TRUE(contains(r.error, "expected 'vertex', but the file ends")) << r.error;

    spit(path, "solid bad\n");
    r = readStl(path);
    EXPECT_TRUE(contains(r.error, "expected 'endsolid'")) << r.error;

    spit(path, "this is not a mesh\n");
    r = readStl(path);
    EXPECT_TRUE(contains(r.error, path)) << r.error;
    EXPECT_TRUE(contains(r.error, "not an STL file")) << r.error;
}

TEST(StlIo, MissingFileIsAnError) {
    const StlReadResult r = readStl("/nonexistent/hypergarden/missing.stl");
    EXPECT_TRUE(contains(r.error, "/nonexistent/hypergarden/missing.stl")) << r.error;
}

TEST(StlIo, FailedWritesLeaveNothingBehind) {
    TempDir dir;
    // No such directory.
    const std::string missing = dir.file("no/such/dir/cube.stl");
    std::string why = writeStl(cube(), missing);
    EXPECT_TRUE(contains(why, missing)) << why;

    // The target is a directory: the temporary file is written, and the
    // rename fails; the temporary must go.
    fs::create_directory(dir.file("taken.stl"));
    for (bool ascii : {false, true}) {
        why = writeStl(cube(), dir.file("taken.stl"), ascii);
        EXPECT_TRUE(contains(why, dir.file("taken.stl"))) << why;
        EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken.stl"});
    }

    // Nonsense scales are refused before anything is written.
    for (double scale : {0.0, -1.0, std::nan("")}) {
        why = writeStl(cube(), dir.file("scaled.stl"), false, scale);
        EXPECT_TRUE(contains(why, "scale")) << why;
    }
    Mesh broken = cube();
    broken.indices[5] = 8;
    EXPECT_TRUE(contains(writeStl(broken, dir.file("broken.stl")), "out of range"));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken.stl"});
}

TEST(StlIo, EmptyMeshWritesAnEmptySolid) {
    TempDir dir;
    for (bool ascii : {false, true}) {
        const std::string path = dir.file(ascii ? "a.stl" : "b.stl");
        ASSERT_EQ(writeStl(Mesh{}, path, ascii), "");
        const StlReadResult r = readStl(path);
        EXPECT_EQ(r.error, "");
        EXPECT_EQ(r.ascii, ascii);
        EXPECT_TRUE(r.mesh.empty());
    }
}

// ------------------------------------------------------- large, streamed files

// What the writer wrote before it streamed slices on several threads, one
// facet after another: every file must still be these bytes.
std::string serialStl(const Mesh& m, bool ascii, double scale, const std::string& name) {
    std::string out;
    auto u32 = [&out](std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
    };
    auto number = [&out](float f) {
        char buf[32];
        out.append(buf, std::to_chars(buf, buf + sizeof buf, f).ptr);
    };
    if (ascii) {
        out += "solid " + name + "\n";
    } else {
        std::string header = "Hypergarden STL: " + name;
        header.resize(80, '\0');
        out += header;
        u32(static_cast<std::uint32_t>(m.triangleCount()));
    }
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
        float v[3][3], n[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a)
                v[k][a] = static_cast<float>(static_cast<double>(m.positions[3 * m.indices[3 * t + k] + a]) * scale);
        double e1[3], e2[3];
        for (int a = 0; a < 3; ++a) {
            e1[a] = static_cast<double>(v[1][a]) - static_cast<double>(v[0][a]);
            e2[a] = static_cast<double>(v[2][a]) - static_cast<double>(v[0][a]);
        }
        const double c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                             e1[0] * e2[1] - e1[1] * e2[0]};
        const double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        if (len > 0 && std::isfinite(len))
            for (int a = 0; a < 3; ++a) n[a] = static_cast<float>(c[a] / len);
        if (ascii) {
            out += "  facet normal ";
            for (int a = 0; a < 3; ++a) number(n[a]), out += a < 2 ? " " : "\n    outer loop\n";
            for (const auto& p : v) {
                out += "      vertex ";
                for (int a = 0; a < 3; ++a) number(p[a]), out += a < 2 ? ' ' : '\n';
            }
            out += "    endloop\n  endfacet\n";
        } else {
            auto f32 = [&u32](float f) {
                std::uint32_t bits;
                std::memcpy(&bits, &f, sizeof bits);
                u32(bits);
            };
            for (float x : n) f32(x);
            for (const auto& p : v)
                for (float x : p) f32(x);
            out += std::string(2, '\0');
        }
    }
    if (ascii) out += "endsolid " + name + "\n";
    return out;
}

// Many slices' worth of facets (the writer formats 16384 at a time), some
// without area.
Mesh largeMesh() {
    Mesh m = test::latLongSphere(120, 240, 0.7);
    m.indices.insert(m.indices.end(), {0, 0, 1, 5, 6, 5});
    return m;
}

TEST(StlIo, LargeFilesAreTheSerialWritersBytes) {
    TempDir dir;
    const Mesh m = largeMesh();
    ASSERT_GT(m.triangleCount(), 3u * 16384u);
    for (bool ascii : {false, true}) {
        const std::string path = dir.file(ascii ? "a.stl" : "b.stl");
        ASSERT_EQ(writeStl(m, path, ascii, 25.4, "sphere"), "");
        const std::string bytes = slurp(path);
        if (!ascii) {
            EXPECT_EQ(bytes.size(), 84u + 50u * m.triangleCount());
        }
        EXPECT_TRUE(bytes == serialStl(m, ascii, 25.4, "sphere")) << (ascii ? "ASCII" : "binary");
        const StlReadResult r = readStl(path);
        ASSERT_EQ(r.error, "");
        EXPECT_EQ(r.mesh.triangleCount(), m.triangleCount());
    }
}

TEST(StlIo, SameBytesOnAnyNumberOfThreads) {
    TempDir dir;
    const Mesh m = largeMesh();
    for (bool ascii : {false, true}) {
        std::string one, many;
        tbb::task_arena(1).execute([&] { ASSERT_EQ(writeStl(m, dir.file("one.stl"), ascii), ""); });
        tbb::task_arena(4).execute([&] { ASSERT_EQ(writeStl(m, dir.file("many.stl"), ascii), ""); });
        EXPECT_TRUE(slurp(dir.file("one.stl")) == slurp(dir.file("many.stl"))) << (ascii ? "ASCII" : "binary");
    }
}

TEST(StlIo, AWriteFailingHalfwayLeavesNothingBehind) {
    // The file size limit stops the write after a few slices: EFBIG, and
    // SIGXFSZ, which would otherwise end the process, is ignored meanwhile.
    TempDir dir;
    const Mesh m = largeMesh();
    rlimit old{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto oldSignal = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = old;
    small.rlim_cur = 1 << 20;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    std::string why[2];
    for (bool ascii : {false, true}) why[ascii] = writeStl(m, dir.file("big.stl"), ascii);
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldSignal);
    for (const std::string& w : why) {
        EXPECT_TRUE(contains(w, dir.file("big.stl"))) << w;
        EXPECT_TRUE(contains(w, std::strerror(EFBIG))) << w;
    }
    EXPECT_TRUE(dir.entries().empty()) << "no partial file is left";
}

// ------------------------------------------------------------------ ADMesh

std::optional<std::string> findAdmesh() {
    const char* env = std::getenv("PATH");
    std::stringstream dirs(env ? env : "/usr/bin");
    std::string d;
    while (std::getline(dirs, d, ':')) {
        const fs::path p = fs::path(d.empty() ? "." : d) / "admesh";
        if (::access(p.c_str(), X_OK) == 0) return p.string();
    }
    return std::nullopt;
}

std::string runCommand(const std::string& cmd) {
    std::string out;
    FILE* pipe = ::popen((cmd + " 2>&1").c_str(), "r");
    if (!pipe) return out;
    std::array<char, 4096> buf;
    std::size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
    ::pclose(pipe);
    return out;
}

// The first number after the colon on ADMesh's line that starts with
// `label` ("Edges fixed           :     0"); lines may carry a second
// statistic after the first.
std::optional<long> admeshValue(const std::string& report, const std::string& label) {
    std::istringstream lines(report);
    std::string line;
    while (std::getline(lines, line)) {
        const std::size_t start = line.find_first_not_of(" \t");
        if (start == std::string::npos || line.compare(start, label.size(), label) != 0) continue;
        const std::size_t colon = line.find(':', start + label.size());
        if (colon == std::string::npos || line.find_first_not_of(" \t", start + label.size()) != colon) continue;
        std::istringstream rest(line.substr(colon + 1));
        long value;
        if (rest >> value) return value;
    }
    return std::nullopt;
}

class Admesh : public ::testing::Test {
protected:
    void SetUp() override {
        const auto exe = findAdmesh();
        // scripts/install-deps.sh installs it: its absence is a failure, not a skip.
        ASSERT_TRUE(exe.has_value()) << "admesh is not installed (Debian package 'admesh')";
        admesh_ = *exe;
        const std::string help = runCommand("'" + admesh_ + "' --help");
        ASSERT_TRUE(contains(help, "Usage")) << "unexpected 'admesh --help' output:\n" << help;
    }

    // ADMesh's report on a file; it only writes files when asked to.
    std::string check(const std::string& path) { return runCommand("'" + admesh_ + "' '" + path + "'"); }

    std::string admesh_;
};

void expectNothingToRepair(const std::string& report, long parts) {
    for (const char* label : {"Edges fixed", "Facets removed", "Facets added", "Facets reversed", "Backwards edges",
                              "Degenerate facets", "Normals fixed"}) {
        const auto v = admeshValue(report, label);
        ASSERT_TRUE(v.has_value()) << "no '" << label << "' in ADMesh's report:\n" << report;
        EXPECT_EQ(*v, 0) << label << "\n" << report;
    }
    const auto p = admeshValue(report, "Number of parts");
    ASSERT_TRUE(p.has_value()) << report;
    EXPECT_EQ(*p, parts) << report;
}

TEST_F(Admesh, FindsNothingToRepairInACube) {
    TempDir dir;
    const std::string path = dir.file("cube.stl");
    ASSERT_EQ(writeStl(cube(), path, false, 10.0), "");
    const std::string report = check(path);
    expectNothingToRepair(report, 1);
    EXPECT_TRUE(contains(report, "Binary STL")) << report;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"cube.stl"}) << "ADMesh wrote nothing";
}

TEST_F(Admesh, CountsTwoPartsForTwoCubes) {
    TempDir dir;
    const std::string path = dir.file("cubes.stl");
    ASSERT_EQ(writeStl(concatenate(cube(), cube(2, 0.5f, 0)), path, false, 10.0), "");
    expectNothingToRepair(check(path), 2);
}

TEST_F(Admesh, SeesTheHoleInAnOpenCube) {
    // The parser reads real numbers, not just zeros.
    TempDir dir;
    const std::string path = dir.file("open.stl");
    Mesh m = cube();
    m.indices.resize(m.indices.size() - 3);
    ASSERT_EQ(writeStl(m, path), "");
    const auto added = admeshValue(check(path), "Facets added");
    ASSERT_TRUE(added.has_value());
    EXPECT_GT(*added, 0);
}

}  // namespace
}  // namespace hg::poly
