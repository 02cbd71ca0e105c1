// Shared by the OBJ and glTF writer tests: a scratch folder per test, a
// real mesh (the torus block sampled and meshed, with normals), a large
// synthetic one, and a write failure made on purpose through io's fault
// seam.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "io/write_faults.h"
#include "polygonizer/export/export_mesher.h"
#include "polygonizer/mesh.h"
#include "sample_program.h"
#include "tests/test_models.h"

namespace hg::poly::test {

namespace fs = std::filesystem;

struct ScratchFolder {
    fs::path path;
    ScratchFolder() {
        path = fs::temp_directory_path() / ("hg_mesh_files_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~ScratchFolder() { fs::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(path)) names.push_back(e.path().filename().string());
        return names;
    }
};

inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The torus block in [-1, 1]^3 at 40 voxels, meshed: a few thousand
// vertices with unit normals, closed and outward.
inline Mesh torusMesh() {
    const frep::Model model = ::hg::test::modelFromSource(::hg::test::kTorusBlock);
    Mesh m = meshVolume(sampleInUnitCube(model, 40));
    EXPECT_GT(m.triangleCount(), 1000u);
    EXPECT_EQ(m.normals.size(), m.positions.size());
    return m;
}

// A latitude-longitude sphere of radius 0.7 with `rings` x `segments`
// quads (closed by the poles' fans), outward normals: large meshes without
// sampling.
inline Mesh uvSphere(int rings, int segments) {
    Mesh m;
    const double pi = 3.14159265358979323846;
    const auto add = [&](double x, double y, double z) {
        for (double c : {x, y, z}) m.positions.push_back(static_cast<float>(0.7 * c));
        for (double c : {x, y, z}) m.normals.push_back(static_cast<float>(c));
    };
    add(0, 0, 1);
    for (int r = 1; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const double th = pi * r / rings, ph = 2 * pi * s / segments;
            add(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
        }
    add(0, 0, -1);
    const auto ring = [&](int r, int s) { return static_cast<std::uint32_t>(1 + (r - 1) * segments + (s % segments)); };
    const auto south = static_cast<std::uint32_t>(m.vertexCount() - 1);
    for (int s = 0; s < segments; ++s) m.indices.insert(m.indices.end(), {0u, ring(1, s), ring(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r)
        for (int s = 0; s < segments; ++s)
            m.indices.insert(m.indices.end(), {ring(r, s), ring(r + 1, s), ring(r + 1, s + 1), ring(r, s),
                                               ring(r + 1, s + 1), ring(r, s + 1)});
    for (int s = 0; s < segments; ++s) m.indices.insert(m.indices.end(), {south, ring(rings - 1, s + 1), ring(rings - 1, s)});
    return m;
}

// Every export write step fails with `error` while this lives.
struct FailingExportWrites {
    explicit FailingExportWrites(int error) {
        io::FaultPlan p;
        p.anySite = false;
        p.site = io::WriteSite::Export;
        p.first = 1;
        p.last = SIZE_MAX;
        p.error = error;
        io::setFaultPlan(p);
    }
    ~FailingExportWrites() { io::setFaultPlan(std::nullopt); }
};

}  // namespace hg::poly::test
