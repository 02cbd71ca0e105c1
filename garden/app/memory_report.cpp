#include "garden/app/memory_report.h"

#include "garden/app/garden_session.h"
#include "garden/morph/morph_state.h"
#include "garden/sculpt/sculpture_edits.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "voxel/volume.h"

namespace hg::garden {

MemoryReport memoryReport(const GardenSession& session) {
    MemoryReport r;
    for (const Sculpture& s : session.sculptures()) {
        if (s.volume) {
            r.grids += s.volume->memoryBytes();
            ++r.sculptures;
        }
        if (s.pyramid) r.levels += s.pyramid->memoryBytes();
        if (s.queue) r.meshes += s.queue->meshBytesHeld();
        if (s.edits) r.editBases += s.edits->base().memoryBytes();
        if (s.morph && s.morph->sources)
            for (const BlockedField& f : s.morph->sources->fields) r.morphSources += f.bytes();
    }
    return r;
}

const MemoryReport& MemoryWatch::read(const GardenSession& session) {
    const auto now = std::chrono::steady_clock::now();
    if (!any_ || now - taken_ >= every_) {
        last_ = memoryReport(session);
        taken_ = now;
        any_ = true;
    }
    return last_;
}

}  // namespace hg::garden
