// A batch of the morph's blend computed off the frame thread (internal to
// garden/morph; see morph_blend.h, "Off the frame thread"). The blender
// hands a thread the next pieces of its work list with the weights of the
// moment; the thread computes their values from the sources alone (it
// never touches the result grid); the frame thread writes them into the
// grid at a later frame boundary, exactly as if it had blended them itself.
// The job copies its pieces, so the blender may re-sort or restart its
// list meanwhile; it reads the sources, so the blender waits for it before
// it (and the sources) go.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "garden/morph/blend_block_vdb.h"
#include "jobs/job_thread.h"

namespace hg::garden::blend {

struct BlendPiece {
    std::size_t index = 0;         // the item's place in the blender's list
    BlendItem item;
    std::uint32_t s0 = 0, s1 = 0;  // its samples in this job
    bool finishes = false;         // s1 is the item's end
    // A whole fine block: its values are blocks[at]; else samples[at ...].
    bool whole = false;
    std::size_t at = 0;
};

class BlendJob final : public jobs::BackgroundJob {
public:
    BlendJob(const BlendInputs& in, std::uint64_t generation) : in_(in), generation_(generation) {}

    // Before submitting: the next piece, laid out in the job's storage.
    void add(std::size_t index, const BlendItem& item, std::uint32_t s0, std::uint32_t s1);

    const BlendInputs& inputs() const { return in_; }
    std::uint64_t generation() const { return generation_; }
    const std::vector<BlendPiece>& pieces() const { return pieces_; }
    std::uint64_t samples() const { return samples_; }
    // The values, once done() and ran().
    const BlockValues& block(const BlendPiece& p) const { return blocks_[p.at]; }
    const float* values(const BlendPiece& p) const { return values_.data() + p.at; }
    // Time the thread spent computing.
    double seconds() const { return seconds_; }

private:
    void run() override;

    BlendInputs in_;
    std::uint64_t generation_;
    std::vector<BlendPiece> pieces_;
    std::unique_ptr<BlockValues[]> blocks_;  // not value-initialized: run() writes every one
    std::vector<float> values_;
    std::size_t blockCount_ = 0, valueCount_ = 0;
    std::uint64_t samples_ = 0;
    double seconds_ = 0.0;
};

}  // namespace hg::garden::blend
