// Far grids on disk (garden/app/grid_pager.h): with a budget the garden
// cannot keep, far sculptures' grids go to disk while their coarse meshes
// stay on show, and a session that pages shows the same meshes, chunk for
// chunk, as one that does not; walking up to a paged sculpture brings its
// grid back bit for bit; editing one brings it back first; a full disk
// keeps every grid in memory and says so; and the budget holds on a garden
// of a thousand sculptures.
#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <sys/wait.h>
#include <unistd.h>

#include "garden/app/garden_session.h"
#include "garden/app/grid_pager.h"
#include "garden/app/memory_report.h"
#include "garden/scene/scale_garden.h"
#include "io/write_faults.h"
#include "tests/disk_full.h"
#include "tests/same_grid.h"
#include "tests/test_folder.h"

namespace hg::garden {
namespace {

namespace fs = std::filesystem;

using TempDir = test::TestFolder;

GardenLoad scaleGarden(int count, int resolution) {
    ScaleGardenSpec spec;
    spec.count = count;
    spec.resolution = resolution;
    return loadScaleGarden(std::string(HG_SOURCE_DIR) + "/content/gardens/default.json", spec);
}

// `count` copies of a small sphere in a given box (no box estimate, no
// normalization search to speak of): a large garden that samples quickly.
GardenLoad pebbleGarden(const TempDir& dir, int count) {
    fs::create_directories(dir.path);
    std::ofstream((dir.path / "pebble.hf").string()) << "pebble(x[3], a[1]) { pebble = 0.16 - (x[1]^2 + (x[2] - 0.4)^2 + x[3]^2); }\n";
    std::ofstream((dir.path / "pebbles.json").string())
        << R"({"version": 1, "name": "pebbles", "sculptures": [{"name": "pebble", "file": "pebble.hf", "a": [0],)"
        << R"( "resolution": 16, "box": {"min": [-0.5, 0, -0.5], "max": [0.5, 0.9, 0.5]},)"
        << R"( "placement": {"position": [0, 0, 0], "yaw": 0}}]})";
    ScaleGardenSpec spec;
    spec.count = count;
    return loadScaleGarden((dir.path / "pebbles.json").string(), spec);
}

// Levels change within a few metres (a small viewport), so a garden of
// small grids has near sculptures at level 0 and far ones coarser.
SessionSettings pagingSettings(std::size_t budget, const std::string& folder) {
    SessionSettings s;
    s.chunkSize = 16;
    s.maxLevel = 2;
    s.remeshChunksPerFrame = 64;
    s.viewportHeight = 60;
    s.memoryBudgetBytes = budget;
    s.pageFolder = folder;
    return s;
}

// Until idle, the pager's writes and reads taken, and idle again.
void settle(GardenSession& session) {
    for (int round = 0; round < 3; ++round) {
        session.frame(FrameInput{});
        for (int f = 0; f < 5000 && !session.idle(); ++f) session.frame(FrameInput{});
        ASSERT_TRUE(session.idle());
        session.settlePaging();
    }
}

std::size_t pagedOut(const GardenSession& session) {
    std::size_t n = 0;
    for (const Sculpture& s : session.sculptures()) n += s.volume && !s.volume->resident();
    return n;
}

// Every chunk of every sculpture shows the same level and the same mesh.
void expectSameMeshes(const GardenSession& a, const GardenSession& b) {
    ASSERT_EQ(a.sculptures().size(), b.sculptures().size());
    for (std::size_t i = 0; i < a.sculptures().size(); ++i) {
        const poly::RemeshQueue& qa = *a.sculptures()[i].queue;
        const poly::RemeshQueue& qb = *b.sculptures()[i].queue;
        ASSERT_EQ(qa.count(), qb.count());
        for (std::size_t c = 0; c < qa.count(); ++c) {
            ASSERT_EQ(qa.shownLod(c).level, qb.shownLod(c).level) << a.sculptures()[i].name << ", chunk " << c;
            const auto ma = qa.mesh(c), mb = qb.mesh(c);
            ASSERT_EQ(ma == nullptr, mb == nullptr) << a.sculptures()[i].name << ", chunk " << c;
            if (!ma) continue;
            ASSERT_EQ(ma->positions, mb->positions) << a.sculptures()[i].name << ", chunk " << c;
            ASSERT_EQ(ma->normals, mb->normals) << a.sculptures()[i].name << ", chunk " << c;
            ASSERT_EQ(ma->indices, mb->indices) << a.sculptures()[i].name << ", chunk " << c;
        }
    }
}

void walkTo(GardenSession& session, const Sculpture& s) {
    const glm::vec3 c = s.worldCentre();
    session.navigator().setPose(glm::vec3(c.x, 1.7f, c.z + 1.2f), 0.0f, 0.0f);
}

TEST(GridPager, FarGridsGoToDiskAndComeBackTheSame) {
    TempDir dir("hg_grid_pager", false);
    GardenSession paging(scaleGarden(16, 40), pagingSettings(1, dir.path.string()));
    GardenSession whole(scaleGarden(16, 40), pagingSettings(0, ""));
    settle(paging);
    settle(whole);
    const std::size_t out = pagedOut(paging);
    EXPECT_GT(out, 4u) << "far sculptures' grids are on disk";
    EXPECT_LT(out, 16u) << "the near ones, at level 0, are not";
    EXPECT_EQ(pagedOut(whole), 0u) << "no budget, nothing paged";
    EXPECT_TRUE(fs::is_directory(dir.path));
    EXPECT_EQ(paging.pager()->problem(), "");
    const MemoryReport report = memoryReport(paging);
    EXPECT_EQ(report.pagedOut, out);
    EXPECT_LT(report.grids, memoryReport(whole).grids);
    // Paged or not, the same meshes are on show.
    expectSameMeshes(paging, whole);

    // Walk up to the farthest paged sculpture: its grid comes back, the
    // same bit for bit, and its chunks refine as in the other session.
    std::size_t target = 0;
    for (std::size_t i = 0; i < paging.sculptures().size(); ++i)
        if (!paging.sculptures()[i].volume->resident()) target = i;
    walkTo(paging, paging.sculptures()[target]);
    walkTo(whole, whole.sculptures()[target]);
    settle(paging);
    settle(whole);
    const Sculpture& back = paging.sculptures()[target];
    ASSERT_TRUE(back.volume->resident()) << back.name;
    EXPECT_GT(paging.pager()->broughtBackTotal(), 0u);
    test::expectSameGrid(*back.volume, *whole.sculptures()[target].volume);
    bool levelZero = false;
    for (std::size_t c = 0; c < back.queue->count(); ++c) levelZero = levelZero || back.queue->shownLod(c).level == 0;
    EXPECT_TRUE(levelZero) << back.name << " refines to level 0 once its grid is back";
    expectSameMeshes(paging, whole);
}

TEST(GridPager, EditingAFarSculptureBringsItsGridBackFirst) {
    TempDir dir("hg_grid_pager", false);
    GardenSession paging(scaleGarden(16, 40), pagingSettings(1, dir.path.string()));
    GardenSession whole(scaleGarden(16, 40), pagingSettings(0, ""));
    settle(paging);
    settle(whole);
    std::size_t target = 0;
    for (std::size_t i = 0; i < paging.sculptures().size(); ++i)
        if (!paging.sculptures()[i].volume->resident()) target = i;
    ASSERT_FALSE(paging.sculptures()[target].volume->resident());
    const Sculpture& s = paging.sculptures()[target];
    const frep::Box3& box = s.volume->frame.modelBox;
    Perturbation p;
    p.center = {0.5 * (box.lo[0] + box.hi[0]), box.hi[1] - 0.2 * (box.hi[1] - box.lo[1]),
                0.5 * (box.lo[2] + box.hi[2])};
    p.radii = {0.3 * (box.hi[0] - box.lo[0]), 0.3 * (box.hi[0] - box.lo[0]), 0.3 * (box.hi[0] - box.lo[0])};
    p.strength = 3.0;
    ASSERT_EQ(paging.apply(PerturbAction{s.name, p}), "");
    ASSERT_EQ(whole.apply(PerturbAction{s.name, p}), "");
    EXPECT_TRUE(s.volume->resident()) << "an edit brings the grid back first";
    settle(paging);
    settle(whole);
    EXPECT_TRUE(s.volume->resident()) << "an edited sculpture stays in memory";
    test::expectSameGrid(*s.volume, *whole.sculptures()[target].volume);
    expectSameMeshes(paging, whole);
}

TEST(GridPager, AFullDiskKeepsEveryGridAndSaysSo) {
    TempDir dir("hg_grid_pager", false);
    io::setFaultPlan(test::diskFullAt(io::WriteSite::PageFile));
    GardenSession paging(scaleGarden(9, 40), pagingSettings(1, dir.path.string()));
    GardenSession whole(scaleGarden(9, 40), pagingSettings(0, ""));
    settle(paging);
    settle(whole);
    io::setFaultPlan(std::nullopt);
    EXPECT_EQ(pagedOut(paging), 0u) << "a grid that could not be written stays in memory";
    const std::string& why = paging.pager()->problem();
    EXPECT_NE(why.find(std::strerror(ENOSPC)), std::string::npos) << why;
    EXPECT_NE(why.find(dir.path.string()), std::string::npos) << why;
    EXPECT_EQ(memoryReport(paging).pagingProblem, why) << "the report carries it to the panel";
    for (std::size_t i = 0; i < paging.sculptures().size(); ++i)
        test::expectSameGrid(*paging.sculptures()[i].volume, *whole.sculptures()[i].volume);
    expectSameMeshes(paging, whole);
}

// A thousand small sculptures, their figures measured whole, then a budget
// of a third of that: after the walk settles, the pager's figures and a
// fresh walk over every sculpture agree, and both are within the budget.
TEST(GridPager, TheBudgetHoldsOnAThousandSculptures) {
    TempDir dir("hg_grid_pager", false);
    SessionSettings settings = pagingSettings(0, dir.path.string());
    settings.remeshChunksPerFrame = 4096;
    GardenSession session(pebbleGarden(dir, 1000), settings);
    settle(session);
    const std::size_t whole = memoryReport(session).total();
    const std::size_t budget = whole / 3;
    session.pager()->setBudget(budget);
    settle(session);
    const MemoryReport now = memoryReport(session);
    const MemoryReport kept = session.pager()->report();
    EXPECT_GT(now.pagedOut, 500u);
    EXPECT_EQ(kept.total(), now.total()) << "the pager's figures are the sculptures' own";
    EXPECT_LE(now.total(), budget) << "held " << now.total() << " of " << whole << " whole";
    EXPECT_EQ(now.budget, budget);
}

}  // namespace
}  // namespace hg::garden

namespace hg::garden {
namespace {

// The default page folder is the process's own under the cache folder; it
// goes with the session, and so do the folders of processes that died
// without removing theirs (only folders of the pager's own naming).
TEST(GridPager, ItsFolderGoesWithItAndSoDoThoseOfDeadProcesses) {
    TempDir dir("hg_grid_pager", false);
    fs::create_directories(dir.path);
    ASSERT_EQ(::setenv("XDG_CACHE_HOME", dir.path.c_str(), 1), 0);
    const fs::path pages = dir.path / "hypergarden";
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ASSERT_GT(child, 0);
    ::waitpid(child, nullptr, 0);  // a process id no one has now
    const fs::path dead = pages / ("pages-" + std::to_string(child));
    fs::create_directories(dead);
    std::ofstream((dead / "left.vdb").string()) << "a page";
    fs::create_directories(pages / "pages-notanumber");
    fs::create_directories(pages / "mine");
    const std::string own = GridPager::defaultPageFolder();
    EXPECT_EQ(own, (pages / ("pages-" + std::to_string(::getpid()))).string());
    {
        GardenSession session(scaleGarden(16, 40), pagingSettings(1, ""));
        settle(session);
        EXPECT_GT(pagedOut(session), 0u);
        EXPECT_EQ(session.pager()->folder(), own);
        EXPECT_TRUE(fs::is_directory(own));
        EXPECT_FALSE(fs::exists(dead)) << "a dead process's pages are removed";
        EXPECT_TRUE(fs::exists(pages / "pages-notanumber"));
        EXPECT_TRUE(fs::exists(pages / "mine"));
    }
    EXPECT_FALSE(fs::exists(own)) << "the session's pages go with it";
    ::unsetenv("XDG_CACHE_HOME");
}

}  // namespace
}  // namespace hg::garden
