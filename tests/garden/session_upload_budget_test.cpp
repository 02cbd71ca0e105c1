// New meshes spread over frames (SessionSettings::uploadBytesPerFrame): a
// recording sink, uploading every chunk whose mesh changed as a renderer
// does, sees at most the budget per frame, except a frame that shows one
// group of touching chunks larger than it (groups are never split: that
// would show a crack); and the garden settles to the same meshes as with
// no budget, later.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "garden/app/garden_session.h"
#include "garden/scene/scale_garden.h"

namespace hg::garden {
namespace {

// Uploads (counts) every chunk whose version it has not seen.
class RecordingSink : public ViewSink {
public:
    ViewUpload upload(GardenSession& session, double) override {
        ViewUpload up;
        for (std::size_t s = 0; s < session.sculptures().size(); ++s) {
            const Sculpture& st = session.sculptures()[s];
            if (!st.hasGrid()) continue;
            for (std::size_t c = 0; c < st.queue->count(); ++c) {
                std::uint64_t& seen = versions[{s, c}];
                if (st.queue->version(c) == seen) continue;
                seen = st.queue->version(c);
                if (const auto m = st.queue->mesh(c)) up.bytes += poly::meshBytes(*m);
            }
        }
        bytes.push_back(up.bytes);
        return up;
    }
    ViewDraw render(GardenSession&) override { return {}; }

    std::map<std::pair<std::size_t, std::size_t>, std::uint64_t> versions;
    std::vector<std::size_t> bytes;
};

struct Walk {
    std::vector<std::size_t> bytes, groups;
    std::size_t triangles = 0;
    int frames = 0;
};

// From far (everything coarse) to the middle of the garden, settled.
Walk walkIn(std::size_t budget) {
    ScaleGardenSpec spec;
    spec.count = 6;
    spec.resolution = 48;
    GardenLoad load = loadScaleGarden(std::string(HG_SOURCE_DIR) + "/content/gardens/default.json", spec);
    EXPECT_TRUE(load.ok()) << load.error;
    SessionSettings settings;
    settings.chunkSize = 16;
    settings.maxLevel = 2;
    settings.viewportHeight = 120;
    settings.remeshChunksPerFrame = 1000;
    settings.uploadBytesPerFrame = budget;
    GardenSession session(std::move(load), settings);
    RecordingSink sink;
    session.navigator().setPose(glm::vec3(0.0f, 1.7f, 400.0f), 0.0f, 0.0f);
    session.frame(FrameInput{}, sink);  // the coarse meshes made at start
    session.navigator().setPose(glm::vec3(0.0f, 1.7f, 0.5f), 0.0f, 0.0f);
    Walk w;
    do {
        const FrameStats& f = session.frame(FrameInput{}, sink);
        w.groups.push_back(f.groupsShown);
        EXPECT_EQ(sink.bytes.back(), f.meshBytesShown) << "the sink uploads what the frame showed";
        ++w.frames;
    } while (!session.idle() && w.frames < 10000);
    EXPECT_TRUE(session.idle());
    w.bytes.assign(sink.bytes.begin() + 1, sink.bytes.end());
    w.triangles = session.trianglesShown();
    return w;
}

TEST(UploadBudget, NoFrameCarriesMoreThanTheBudgetButOneGroupLargerThanIt) {
    const Walk free = walkIn(0);
    const std::size_t burst = *std::max_element(free.bytes.begin(), free.bytes.end());
    ASSERT_GT(burst, 0u);
    const std::size_t budget = burst / 3;
    const Walk spread = walkIn(budget);
    for (std::size_t f = 0; f < spread.bytes.size(); ++f) {
        if (spread.bytes[f] <= budget) continue;
        EXPECT_EQ(spread.groups[f], 1u) << "frame " << f << ": " << spread.bytes[f] << " bytes over " << budget;
    }
    EXPECT_GT(spread.frames, free.frames) << "the same meshes, over more frames";
    EXPECT_EQ(spread.triangles, free.triangles) << "settled to the same meshes";
    std::size_t total = 0, totalFree = 0;
    for (std::size_t b : spread.bytes) total += b;
    for (std::size_t b : free.bytes) totalFree += b;
    EXPECT_EQ(total, totalFree) << "nothing uploaded twice, nothing left out";
}

}  // namespace
}  // namespace hg::garden
