// A grid kept on disk (voxel/grid_page.h, Volume::pageOut): back from the
// file bit for bit, taken back at no cost before its write, kept in memory
// when the write fails (a full disk), shared by identical copies, read back
// off the owner's thread, and brought back once when many threads ask.
#include <gtest/gtest.h>

#include <tbb/parallel_for.h>

#include <openvdb/openvdb.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <thread>

#include "io/write_faults.h"
#include "tests/disk_full.h"
#include "tests/same_grid.h"
#include "tests/test_folder.h"
#include "test_models.h"
#include "voxel/grid_page.h"
#include "voxel/sampler.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {
namespace {

namespace fs = std::filesystem;

using TempDir = ::hg::test::TestFolder;

Volume torusBlock(int resolution = 64) {
    frep::Model model = test::modelFromSource(test::kTorusBlock, {0.25, -3});
    VolumeRequest req;
    req.resolution = resolution;
    VoxelizeResult r = voxelize(model, req);
    EXPECT_TRUE(r.volume) << r.error;
    return std::move(*r.volume);
}

using ::hg::test::expectSameGrid;
using ::hg::test::sameBits;

TEST(GridPage, PagedOutAndBackIsTheSameGridBitForBit) {
    TempDir dir("hg_grid_page");
    Volume v = torusBlock();
    const Volume before = v.clone();
    ASSERT_GT(v.memoryBytes(), 0u);
    const std::shared_ptr<GridPage> page = v.pageOut(dir.path.string());
    EXPECT_FALSE(v.resident());
    EXPECT_EQ(v.memoryBytes(), 0u) << "a paged-out grid holds no memory the report counts";
    EXPECT_EQ(page->state(), GridPage::State::Holding);
    page->write();
    ASSERT_EQ(page->state(), GridPage::State::Written) << page->problem();
    EXPECT_TRUE(fs::exists(page->path()));
    EXPECT_EQ(fs::file_size(page->path()), page->fileBytes());
    EXPECT_EQ(dir.entries(), 1u) << "no temporary file is left beside the page";
    // Any read brings it back.
    EXPECT_TRUE(sameBits(v.value(1, 2, 3), before.value(1, 2, 3)));
    EXPECT_TRUE(v.resident());
    EXPECT_EQ(v.page(), nullptr);
    expectSameGrid(v, before);
    EXPECT_EQ(v.memoryBytes(), before.memoryBytes());
}

TEST(GridPage, TakenBackBeforeItsWriteWritesNothing) {
    TempDir dir("hg_grid_page");
    Volume v = torusBlock(32);
    const Volume before = v.clone();
    const std::shared_ptr<GridPage> page = v.pageOut(dir.path.string());
    (void)v.grid();  // wanted again before the writer got to it
    EXPECT_TRUE(v.resident());
    EXPECT_EQ(page->state(), GridPage::State::TakenBack);
    page->write();
    EXPECT_EQ(page->state(), GridPage::State::TakenBack);
    EXPECT_EQ(dir.entries(), 0u);
    expectSameGrid(v, before);
}

TEST(GridPage, AFailedWriteKeepsTheGridAndSaysWhy) {
    TempDir dir("hg_grid_page");
    Volume v = torusBlock(32);
    const Volume before = v.clone();
    io::setFaultPlan(::hg::test::diskFullAt(io::WriteSite::PageFile));
    const std::shared_ptr<GridPage> page = v.pageOut(dir.path.string());
    page->write();
    io::setFaultPlan(std::nullopt);
    ASSERT_EQ(page->state(), GridPage::State::Failed);
    EXPECT_NE(page->problem().find(dir.path.string()), std::string::npos) << page->problem();
    EXPECT_NE(page->problem().find(std::strerror(ENOSPC)), std::string::npos) << page->problem();
    EXPECT_EQ(dir.entries(), 0u) << "no partial page is left behind";
    expectSameGrid(v, before);  // taken back from memory: nothing lost
    EXPECT_TRUE(v.resident());
}

TEST(GridPage, IdenticalGridsShareOneFile) {
    TempDir dir("hg_grid_page");
    Volume a = torusBlock(32);
    Volume b = a.clone();
    const std::shared_ptr<GridPage> pa = a.pageOut(dir.path.string());
    const std::shared_ptr<GridPage> pb = b.pageOut(dir.path.string());
    pa->write();
    pb->write();
    ASSERT_EQ(pb->state(), GridPage::State::Written) << pb->problem();
    EXPECT_EQ(pa->path(), pb->path()) << "named by content";
    EXPECT_EQ(dir.entries(), 1u);
    expectSameGrid(a, b);
}

TEST(GridPage, ReadBackOffTheOwnersThreadIsAdopted) {
    TempDir dir("hg_grid_page");
    Volume v = torusBlock(32);
    const Volume before = v.clone();
    const std::shared_ptr<GridPage> page = v.pageOut(dir.path.string());
    std::thread([page] { page->write(); }).join();
    EXPECT_FALSE(v.adoptReadAhead()) << "nothing read ahead yet";
    EXPECT_FALSE(v.resident());
    std::thread([page] { page->readAhead(); }).join();
    EXPECT_TRUE(v.adoptReadAhead());
    EXPECT_TRUE(v.resident());
    expectSameGrid(v, before);
    EXPECT_FALSE(v.adoptReadAhead()) << "resident: nothing to adopt";
}

TEST(GridPage, ManyThreadsReadingBringItBackOnce) {
    TempDir dir("hg_grid_page");
    Volume v = torusBlock(48);
    const Volume before = v.clone();
    v.pageOut(dir.path.string())->write();
    std::atomic<int> differ{0};
    const int n = v.frame.indexBox.hi[0];
    tbb::parallel_for(0, n, [&](int i) {
        for (int j = 0; j < n; j += 3)
            if (!sameBits(v.value(i, j, n / 2), before.value(i, j, n / 2))) ++differ;
    });
    EXPECT_EQ(differ.load(), 0);
    EXPECT_TRUE(v.resident());
    expectSameGrid(v, before);
}

// A grid read back and not changed since goes again without a write (the
// disk refuses every write here, and the page still goes); one changed
// through its mutable grid() is written again.
TEST(GridPage, AnUnchangedGridGoesAgainWithoutAWrite) {
    TempDir dir("hg_grid_page");
    Volume v = torusBlock(32);
    const Volume before = v.clone();
    const std::shared_ptr<GridPage> first = v.pageOut(dir.path.string());
    first->write();
    ASSERT_EQ(first->state(), GridPage::State::Written);
    EXPECT_TRUE(sameBits(static_cast<const Volume&>(v).value(0, 0, 0), before.value(0, 0, 0)));  // read back, const
    io::setFaultPlan(::hg::test::diskFullAt(io::WriteSite::PageFile));
    const std::shared_ptr<GridPage> again = v.pageOut(dir.path.string());
    again->write();
    EXPECT_EQ(again->state(), GridPage::State::Written) << again->problem();
    EXPECT_EQ(again->path(), first->path());
    expectSameGrid(v, before);  // and back again
    vdb(v).tree().setValue(openvdb::Coord(0, 0, 0), 1.5f);  // a change, through the mutable grid
    const std::shared_ptr<GridPage> changed = v.pageOut(dir.path.string());
    changed->write();
    io::setFaultPlan(std::nullopt);
    EXPECT_EQ(changed->state(), GridPage::State::Failed) << "a grid that changed is written again";
    EXPECT_EQ(v.value(0, 0, 0), 1.5f) << "and, refused, kept";
}

TEST(GridPage, AMissingPageIsAnErrorNamingItsFile) {
    TempDir dir("hg_grid_page");
    Volume v = torusBlock(32);
    const std::shared_ptr<GridPage> page = v.pageOut(dir.path.string());
    page->write();
    ASSERT_EQ(page->state(), GridPage::State::Written);
    fs::remove(page->path());
    try {
        (void)v.grid();
        ADD_FAILURE() << "a missing page must not read as a grid";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(page->path()), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace hg::voxel
