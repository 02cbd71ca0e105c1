#include "garden/app/memory_report.h"

#include "garden/app/garden_session.h"
#include "garden/app/grid_pager.h"
#include "garden/morph/morph_state.h"
#include "garden/sculpt/sculpture_edits.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "voxel/volume.h"

namespace hg::garden {

MemoryReport& MemoryReport::operator+=(const MemoryReport& o) {
    grids += o.grids;
    levels += o.levels;
    meshes += o.meshes;
    editBases += o.editBases;
    morphSources += o.morphSources;
    sculptures += o.sculptures;
    pagedOut += o.pagedOut;
    return *this;
}

MemoryReport sculptureMemory(const Sculpture& s) {
    MemoryReport r;
    if (s.volume) {
        r.grids = s.volume->memoryBytes();
        r.sculptures = 1;
        r.pagedOut = s.volume->resident() ? 0 : 1;
    }
    if (s.pyramid) r.levels = s.pyramid->memoryBytes();
    if (s.queue) r.meshes = s.queue->meshBytesHeld();
    if (s.edits) r.editBases = s.edits->base().memoryBytes();
    if (s.morph && s.morph->sources)
        for (const BlockedField& f : s.morph->sources->fields) r.morphSources += f.bytes();
    return r;
}

MemoryReport memoryReport(const GardenSession& session) {
    MemoryReport r;
    for (const Sculpture& s : session.sculptures()) r += sculptureMemory(s);
    if (const GridPager* pager = session.pager()) {
        r.budget = pager->budget();
        r.pagingProblem = pager->problem();
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
