#include "garden/app/sculpture_loader.h"

#include <algorithm>
#include <chrono>

#include "garden/app/sculpture_sampling.h"

namespace hg::garden {

SculptureLoader::SculptureLoader(std::vector<Job> jobs, const std::array<double, 3>& viewer,
                                 std::optional<MeshingShape> meshing)
    : waiting_(std::move(jobs)),
      remaining_(waiting_.size()),
      viewer_(viewer),
      meshing_(meshing),
      worker_([this] { run(); }) {}

SculptureLoader::~SculptureLoader() { close(); }

bool SculptureLoader::close() {
    stop_.cancel();
    if (worker_.joinable()) worker_.join();
    return cutShort_;  // the worker has ended: no lock needed
}

void SculptureLoader::setViewer(const std::array<double, 3>& viewer) {
    std::lock_guard<std::mutex> lock(mutex_);
    viewer_ = viewer;
}

void SculptureLoader::run() {
    for (;;) {
        Job job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            // Not more than kAhead grids ahead of the frame (closing is
            // noticed within a few milliseconds).
            while (!all_ && !stop_.cancelled() && finished_.size() >= kAhead)
                taken_.wait_for(lock, std::chrono::milliseconds(5));
            if (stop_.cancelled() || waiting_.empty()) return;
            auto distance = [this](const Job& j) {
                double s = 0.0;
                for (std::size_t a = 0; a < 3; ++a) s += (j.where[a] - viewer_[a]) * (j.where[a] - viewer_[a]);
                return s;
            };
            const auto next = std::min_element(waiting_.begin(), waiting_.end(),
                                               [&](const Job& a, const Job& b) { return distance(a) < distance(b); });
            job = *next;
            waiting_.erase(next);
        }
        Loaded done;
        done.sculpture = job.sculpture;
        const std::string key = sourceKey(job);
        const auto kept = key.empty() ? kept_.end() : kept_.find(key);
        if (kept != kept_.end()) {
            done.volume = std::make_unique<voxel::Volume>(kept->second.volume->clone());
            done.meshing = copyMeshing(kept->second.meshing, *done.volume);
        } else {
            voxel::VoxelizeResult r = sampleSculptureSource(job.spec, *job.source, job.request, &stop_);
            if (r.cancelled) {  // closing: nobody takes it
                cutShort_ = true;
                return;
            }
            if (r.volume) done.volume = std::make_unique<voxel::Volume>(std::move(*r.volume));
            else done.error = r.error;
        }
        // Off the frame too (about 18 ms of level errors a 256^3 grid).
        if (meshing_ && done.volume && !done.meshing.pyramid) done.meshing = prepareMeshing(*done.volume, *meshing_);
        // Kept while a copy waits; let go with the last one. (Jobs only
        // leave waiting_, so a copy found here still waits after the lock;
        // the copying is done without it, the frame's take() not waiting.)
        bool wanted = false;
        if (!key.empty() && done.volume) {
            std::lock_guard<std::mutex> lock(mutex_);
            wanted = std::any_of(waiting_.begin(), waiting_.end(), [&](const Job& j) { return sourceKey(j) == key; });
        }
        const bool copy = kept != kept_.end();
        if (wanted && !copy) {
            Kept& k = kept_[key];
            k.volume = std::make_unique<voxel::Volume>(done.volume->clone());
            k.meshing = copyMeshing(done.meshing, *k.volume);
        }
        if (!wanted && copy) kept_.erase(kept);
        std::lock_guard<std::mutex> lock(mutex_);
        (copy ? copied_ : sampled_) += 1;
        finished_.push_back(std::move(done));
    }
}

std::string SculptureLoader::sourceKey(const Job& job) {
    return job.source->model ? sampledSourceKey(job.spec) : "";
}

std::size_t SculptureLoader::sampled() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return sampled_;
}

std::size_t SculptureLoader::copied() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return copied_;
}

std::vector<SculptureLoader::Loaded> SculptureLoader::take(std::size_t max) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::size_t n = max == 0 ? finished_.size() : std::min(max, finished_.size());
    std::vector<Loaded> out(std::make_move_iterator(finished_.begin()),
                            std::make_move_iterator(finished_.begin() + static_cast<std::ptrdiff_t>(n)));
    finished_.erase(finished_.begin(), finished_.begin() + static_cast<std::ptrdiff_t>(n));
    remaining_ -= n;
    taken_.notify_one();
    return out;
}

std::size_t SculptureLoader::remaining() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return remaining_;
}

void SculptureLoader::wait() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        all_ = true;
    }
    taken_.notify_one();
    for (;;) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (waiting_.empty() && finished_.size() == remaining_) return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

}  // namespace hg::garden
