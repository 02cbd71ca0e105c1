// A sculpture's volume: one OpenVDB FloatGrid in the sculpture's model frame
// holding f scaled to about one unit per voxel near the surface, clamped to
// +-band voxels, positive inside (HyperFun's sign). Tiles and inactive voxels
// hold the clamped value with the right sign; active voxels are those inside
// the band.
//
// This header does not include OpenVDB: code that works on the grid itself
// includes voxel/volume_vdb.h.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "voxel/volume_frame.h"

namespace hg::voxel {

// Where a volume came from: written into .vdb metadata so that a grid can be
// traced back to (and re-sampled from) its program.
struct VolumeSource {
    std::string file;
    std::string body;
    std::vector<double> parameters;  // a[1], a[2], ...
};

struct VolumeGrid;  // defined in voxel/volume_vdb.h
class GridPage;    // voxel/grid_page.h

// How a volume's model box was found (voxel/model_box.h).
enum class BoxOrigin {
    Given,             // by the caller (--box, the garden file)
    IntervalEstimate,  // by interval subdivision (frep::estimateBounds)
    Sampled,           // by sampling the default box when the estimate failed
};

// "given", "interval estimate", "sampled": the .vdb metadata's words.
const char* boxOriginName(BoxOrigin origin);

enum class VolumeKind {
    NarrowBand,   // clamped to +-band, tiles beyond it (what the garden draws)
    DenseSource,  // every voxel active, unclamped (a morph source cache)
};

class Volume {
public:
    Volume();  // an empty grid (every voxel outside)
    ~Volume();
    Volume(Volume&&) noexcept;
    Volume& operator=(Volume&&) noexcept;
    Volume(const Volume&) = delete;
    Volume& operator=(const Volume&) = delete;
    Volume clone() const;  // deep copy of the grid

    VolumeFrame frame;
    // Stored value = f * normalization (then clamped): voxels per unit of f.
    double normalization = 1.0;
    BoxOrigin boxOrigin = BoxOrigin::Given;
    VolumeKind kind = VolumeKind::NarrowBand;
    VolumeSource source;

    // The stored value at voxel (i, j, k) (background outside the grid).
    float value(int i, int j, int k) const;
    bool active(int i, int j, int k) const;
    std::size_t activeVoxelCount() const;
    std::size_t leafCount() const;
    // The grid's memory; 0 while it is paged out.
    std::size_t memoryBytes() const;

    // The grid, brought back first when it is paged out (below).
    // (Non-const: the caller may change it, so a page it was read from no
    // longer stands for it.)
    VolumeGrid& grid() {
        touched_.store(true, std::memory_order_relaxed);
        return resident_.load(std::memory_order_acquire) ? *grid_ : bringBack();
    }
    const VolumeGrid& grid() const { return resident_.load(std::memory_order_acquire) ? *grid_ : bringBack(); }

    // --- a far grid on disk (voxel/grid_page.h; docs/design.md §5) --------
    // The grid handed to a page that a job thread then writes (GridPage::
    // write) and lets go. From here the volume is paged out: grid() (and
    // value(), clone(), ...) brings it back, waiting for the write if it is
    // under way. Only on the thread that owns the volume, while no other
    // thread reads it. `folder` must exist.
    std::shared_ptr<GridPage> pageOut(const std::string& folder);
    bool resident() const { return resident_.load(std::memory_order_acquire); }
    // The page it is out on (null while resident).
    const std::shared_ptr<GridPage>& page() const { return page_; }
    // The grid its page read back off this thread (GridPage::readAhead),
    // taken: whether there was one (false while resident, or before).
    bool adoptReadAhead();

private:
    VolumeGrid& bringBack() const;

    // Null while paged out; resident_ says which without a lock, for the
    // threads that read the grid while one of them brings it back.
    mutable std::unique_ptr<VolumeGrid> grid_;
    mutable std::shared_ptr<GridPage> page_;
    mutable std::atomic<bool> resident_{true};
    // The page file it was last read back from, and whether it may have
    // changed since (a mutable grid() was asked for): pageOut then names
    // that file instead of writing the grid again.
    mutable std::string readFrom_;
    mutable std::atomic<bool> touched_{true};
};

}  // namespace hg::voxel
