// Progressive loading (SessionSettings::progressiveLoading, garden/app/
// sculpture_loader.h): the generated 48-sculpture garden shows its first
// frame while sculptures are still loading, the nearest sculpture comes
// first, every sculpture loads in the end, and the grids are the grids a
// session that samples everything at start makes, voxel for voxel.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <thread>

#include <glm/geometric.hpp>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_loader.h"
#include "garden/scene/scale_garden.h"
#include "polygonizer/realtime/chunk_errors.h"
#include "polygonizer/realtime/chunk_layout.h"
#include "polygonizer/realtime/lod_pyramid.h"

namespace hg::garden {
namespace {

GardenLoad scaleGarden(int count) {
    ScaleGardenSpec spec;
    spec.count = count;
    spec.resolution = 24;
    return loadScaleGarden(std::string(HG_SOURCE_DIR) + "/content/gardens/default.json", spec);
}

SessionSettings loadingSettings(bool progressive) {
    SessionSettings s;
    s.chunkSize = 16;
    s.maxLevel = 1;
    s.remeshChunksPerFrame = 64;
    s.progressiveLoading = progressive;
    return s;
}

// Frames as a window runs them: sampling goes on in the background while
// frames pass, so a frame that finds nothing new waits a millisecond.
void nextFrame(GardenSession& session) {
    session.frame(FrameInput{});
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void loadAll(GardenSession& session) {
    while (session.sculpturesLoading() > 0) nextFrame(session);
}

// One loader job a sculpture of `load`, placed where the garden puts it.
std::vector<SculptureLoader::Job> loaderJobs(const GardenLoad& load) {
    const Garden& g = *load.garden;
    std::vector<SculptureLoader::Job> jobs;
    for (std::size_t i = 0; i < g.sculptures.size(); ++i) {
        voxel::VolumeRequest request;
        request.box = g.sculptures[i].box;
        request.resolution = g.sculptures[i].resolution;
        request.band = g.sculptures[i].band;
        const auto& p = g.sculptures[i].placement.position;
        jobs.push_back({i, std::make_shared<const SculptureLoad>(load.sculptures[i]), g.sculptures[i], request,
                        {p[0], p[1], p[2]}});
    }
    return jobs;
}

TEST(ProgressiveLoading, TheFirstFrameComesBeforeTheSculpturesNearestFirstAndAllLoad) {
    GardenLoad load = scaleGarden(48);
    ASSERT_TRUE(load.ok()) << load.error;
    GardenSession session(std::move(load), loadingSettings(true));
    const FrameStats& first = session.frame(FrameInput{});
    EXPECT_GT(first.sculpturesLoading, 0u) << "the garden opened before its sculptures were sampled";
    EXPECT_FALSE(session.idle());
    // The sculpture nearest the viewer is the first to arrive.
    std::size_t nearest = 0;
    float best = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < session.sculptures().size(); ++i) {
        const float d = glm::length(session.sculptures()[i].worldCentre() - session.navigator().eye());
        if (d < best) best = d, nearest = i;
    }
    auto anyGrid = [&] {
        return std::any_of(session.sculptures().begin(), session.sculptures().end(), [](const Sculpture& s) { return s.hasGrid(); });
    };
    while (!anyGrid()) nextFrame(session);
    ASSERT_TRUE(session.sculptures()[nearest].hasGrid()) << session.sculptures()[nearest].name;
    EXPECT_GT(session.sculptures()[nearest].queue->shownTriangles(), 0u) << "a sculpture shows its coarse mesh as it arrives";
    loadAll(session);
    EXPECT_EQ(session.frame(FrameInput{}).sculpturesLoading, 0u);
    for (const Sculpture& s : session.sculptures()) {
        EXPECT_TRUE(s.hasGrid()) << s.name << ": " << s.error;
        EXPECT_FALSE(s.loading);
    }
}

TEST(ProgressiveLoading, GridsEqualThoseSampledAtStart) {
    GardenLoad a = scaleGarden(10), b = scaleGarden(10);
    ASSERT_TRUE(a.ok() && b.ok());
    GardenSession progressive(std::move(a), loadingSettings(true));
    GardenSession atStart(std::move(b), loadingSettings(false));
    EXPECT_EQ(atStart.sculpturesLoading(), 0u);
    loadAll(progressive);
    ASSERT_EQ(progressive.sculptures().size(), atStart.sculptures().size());
    for (std::size_t n = 0; n < atStart.sculptures().size(); ++n) {
        const voxel::Volume& p = *progressive.sculptures()[n].volume;
        const voxel::Volume& q = *atStart.sculptures()[n].volume;
        const voxel::IndexBox& box = q.frame.indexBox;
        for (int a = 0; a < 3; ++a) {
            ASSERT_EQ(p.frame.indexBox.lo[a], box.lo[a]);
            ASSERT_EQ(p.frame.indexBox.hi[a], box.hi[a]);
        }
        for (int k = box.lo[2]; k <= box.hi[2]; ++k)
            for (int j = box.lo[1]; j <= box.hi[1]; ++j)
                for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                    ASSERT_EQ(p.value(i, j, k), q.value(i, j, k)) << atStart.sculptures()[n].name;
                    ASSERT_EQ(p.active(i, j, k), q.active(i, j, k)) << atStart.sculptures()[n].name;
                }
        // The loader built the coarse levels, chunks and level errors
        // (sculpture_meshing.h): on this very grid, equal to the session's own.
        const Sculpture& ps = progressive.sculptures()[n];
        const Sculpture& qs = atStart.sculptures()[n];
        ASSERT_EQ(&ps.pyramid->volume(), ps.volume.get());
        ASSERT_EQ(ps.pyramid->levels(), qs.pyramid->levels());
        ASSERT_EQ(ps.layout->count(), qs.layout->count());
        ASSERT_TRUE(ps.errors && qs.errors);
        for (int l = 1; l < qs.pyramid->levels(); ++l) {
            for (std::size_t c = 0; c < qs.layout->count(); ++c)
                ASSERT_EQ(ps.errors->error(c, l), qs.errors->error(c, l)) << qs.name << " chunk " << c << " level " << l;
            for (int k = box.lo[2] >> l; k <= box.hi[2] >> l; ++k)
                for (int j = box.lo[1] >> l; j <= box.hi[1] >> l; ++j)
                    for (int i = box.lo[0] >> l; i <= box.hi[0] >> l; ++i)
                        ASSERT_EQ(ps.pyramid->value(l, i, j, k), qs.pyramid->value(l, i, j, k)) << qs.name;
        }
    }
}

// Given a meshing shape, the loader builds each grid's coarse levels,
// chunks and level errors next to the sampling, off the frame (a copy of
// one source gets a copy of its meshing); each equals building it on the
// grid afresh. Without a shape it builds none (the session then builds
// them as it attaches).
TEST(ProgressiveLoading, TheLoaderBuildsEachGridsMeshingToTheShapeGiven) {
    GardenLoad load = scaleGarden(12);  // nine sources, three of them twice
    ASSERT_TRUE(load.ok()) << load.error;
    const Garden& g = *load.garden;
    auto jobsOf = [&] { return loaderJobs(load); };
    const MeshingShape shape{3, 16, true};
    SculptureLoader shaped(jobsOf(), {0.0, 1.7, 0.0}, shape);
    shaped.wait();
    EXPECT_EQ(shaped.copied(), 3u);
    std::vector<SculptureLoader::Loaded> got = shaped.take();
    ASSERT_EQ(got.size(), 12u);
    for (const SculptureLoader::Loaded& l : got) {
        SCOPED_TRACE(g.sculptures[l.sculpture].name);
        ASSERT_TRUE(l.volume) << l.error;
        const PreparedMeshing& m = l.meshing;
        ASSERT_TRUE(m.pyramid && m.layout && m.errors);
        EXPECT_EQ(&m.pyramid->volume(), l.volume.get());
        const PreparedMeshing own = prepareMeshing(*l.volume, shape);
        ASSERT_EQ(m.pyramid->levels(), 3);
        ASSERT_EQ(m.layout->count(), own.layout->count());
        ASSERT_EQ(m.layout->dims(), own.layout->dims());
        ASSERT_EQ(m.errors->unknown(), 0u);
        const voxel::IndexBox& box = l.volume->frame.indexBox;
        for (int lv = 1; lv < 3; ++lv) {
            for (std::size_t c = 0; c < own.layout->count(); ++c)
                ASSERT_EQ(m.errors->error(c, lv), own.errors->error(c, lv)) << "chunk " << c << " level " << lv;
            for (int k = box.lo[2] >> lv; k <= box.hi[2] >> lv; ++k)
                for (int j = box.lo[1] >> lv; j <= box.hi[1] >> lv; ++j)
                    for (int i = box.lo[0] >> lv; i <= box.hi[0] >> lv; ++i)
                        ASSERT_EQ(m.pyramid->value(lv, i, j, k), own.pyramid->value(lv, i, j, k));
        }
    }
    SculptureLoader plain(jobsOf(), {0.0, 1.7, 0.0}, MeshingShape{3, 16, false});
    plain.wait();
    for (const SculptureLoader::Loaded& l : plain.take()) {
        ASSERT_TRUE(l.meshing.pyramid) << l.error;
        EXPECT_FALSE(l.meshing.errors) << "errors measured with the measure off";
    }
    SculptureLoader none(jobsOf(), {0.0, 1.7, 0.0});
    none.wait();
    for (const SculptureLoader::Loaded& l : none.take()) EXPECT_FALSE(l.meshing.pyramid);
}

TEST(ProgressiveLoading, ALoadingSculptureIsNotEditableAndFinishLoadingBringsAll) {
    GardenLoad load = scaleGarden(30);
    ASSERT_TRUE(load.ok()) << load.error;
    GardenSession session(std::move(load), loadingSettings(true));
    const Sculpture& last = session.sculptures().back();  // the farthest row: sampled last
    ASSERT_TRUE(last.loading);
    const std::string why = session.applyPerturbation(static_cast<int>(session.sculptures().size()) - 1, QuadricShape::Ellipsoid,
                                                      {0.0, 1.0, 0.0}, {0.2, 0.2, 0.2}, 2.0);
    EXPECT_NE(why.find("still loading"), std::string::npos) << why;
    session.finishLoading();
    EXPECT_EQ(session.sculpturesLoading(), 0u);
    for (const Sculpture& s : session.sculptures()) EXPECT_TRUE(s.hasGrid()) << s.name;
}

// Copies of one source are sampled once: twenty sculptures of the default
// garden's nine sources take nine samplings, and every copy's grid is the
// grid its own sampling gives, voxel for voxel.
TEST(ProgressiveLoading, CopiesOfOneSourceAreSampledOnce) {
    GardenLoad load = scaleGarden(20);
    ASSERT_TRUE(load.ok()) << load.error;
    const Garden& g = *load.garden;
    const std::vector<SculptureLoader::Job> jobs = loaderJobs(load);
    SculptureLoader loader(jobs, {0.0, 1.7, 0.0});
    loader.wait();
    EXPECT_EQ(loader.sampled(), 9u);
    EXPECT_EQ(loader.copied(), 11u);
    std::vector<SculptureLoader::Loaded> got = loader.take();
    ASSERT_EQ(got.size(), 20u);
    for (const SculptureLoader::Loaded& l : got) {
        ASSERT_TRUE(l.volume) << l.error;
        const SculptureLoader::Job& job = jobs[l.sculpture];
        voxel::VoxelizeResult own = voxel::voxelize(*job.source->model, job.request);
        ASSERT_TRUE(own.volume) << own.error;
        const voxel::IndexBox& box = own.volume->frame.indexBox;
        for (int a = 0; a < 3; ++a) {
            ASSERT_EQ(l.volume->frame.indexBox.lo[a], box.lo[a]);
            ASSERT_EQ(l.volume->frame.indexBox.hi[a], box.hi[a]);
        }
        for (int k = box.lo[2]; k <= box.hi[2]; ++k)
            for (int j = box.lo[1]; j <= box.hi[1]; ++j)
                for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                    ASSERT_EQ(l.volume->value(i, j, k), own.volume->value(i, j, k)) << g.sculptures[l.sculpture].name;
                    ASSERT_EQ(l.volume->active(i, j, k), own.volume->active(i, j, k)) << g.sculptures[l.sculpture].name;
                }
    }
}

// A journal played into a session that loads progressively (the desktop
// window's) waits for the grids, so its actions on far sculptures play.
TEST(ProgressiveLoading, AJournalPlaysIntoALoadingSession) {
    GardenLoad load = scaleGarden(30);
    ASSERT_TRUE(load.ok()) << load.error;
    const std::string name = load.garden->sculptures.back().name;
    const Placement at = load.garden->sculptures.back().placement;
    std::vector<Action> journal;
    Perturbation p;
    p.center = {0.0, 0.5, 0.0};
    p.radii = {0.2, 0.2, 0.2};
    p.strength = 2.0;
    journal.push_back(PerturbAction{name, p});
    journal.push_back(MoveAction{name, Placement{{at.position[0] + 1.0, 0.0, at.position[2]}, 10.0, at.scale}});
    GardenSession session(std::move(load), loadingSettings(true));
    ASSERT_TRUE(session.sculptures().back().loading);
    ASSERT_EQ(session.restore(journal), "");
    EXPECT_EQ(session.editCount(session.findSculpture(name)), 1u);
    EXPECT_EQ(session.sculpturesLoading(), 0u);
}

}  // namespace
}  // namespace hg::garden
