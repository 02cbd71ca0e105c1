#include "garden/morph/blend_job.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>

namespace hg::garden::blend {

void BlendJob::add(std::size_t index, const BlendItem& item, std::uint32_t s0, std::uint32_t s1) {
    BlendPiece p;
    p.index = index;
    p.item = item;
    p.s0 = s0;
    p.s1 = s1;
    p.finishes = s1 == item.samples;
    p.whole = item.pass == BlendPass::Fine && s0 == 0 && p.finishes;
    // Only the layout here: the storage is made on the thread, in run().
    p.at = p.whole ? blockCount_++ : valueCount_;
    if (!p.whole) valueCount_ += s1 - s0;
    samples_ += s1 - s0;
    pieces_.push_back(p);
}

void BlendJob::run() {
    const auto start = std::chrono::steady_clock::now();
    blocks_.reset(new BlockValues[blockCount_]);
    values_.resize(valueCount_);
    // About 4096 samples per task, as the frame's batches.
    const std::size_t grain = std::max<std::size_t>(1, 4096 / (1 + samples_ / std::max<std::size_t>(1, pieces_.size())));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pieces_.size(), grain), [this](const tbb::blocked_range<std::size_t>& r) {
        if (abandoned()) return;  // for old weights, or a blender going away: nobody reads it
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            const BlendPiece& p = pieces_[i];
            if (p.whole) blendBlock(p.item.origin, in_, blocks_[p.at]);
            else sampleValues(p.item, p.s0, p.s1, in_, values_.data() + p.at);
        }
    });
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace hg::garden::blend
