// The job thread (jobs/job_thread.h): jobs run one after another in the
// order handed over, off the caller's thread; an abandoned job that has not
// started is skipped; what a job throws is kept for its owner; a thread
// that stops finishes the job under way and drops the rest, so nobody
// waits for ever.
#include <gtest/gtest.h>

#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "gate_job.h"
#include "jobs/job_thread.h"

namespace hg::jobs {
namespace {

using test::Gate;

// Appends its number to a shared list.
class Numbered final : public BackgroundJob {
public:
    Numbered(int n, std::vector<int>& out, std::mutex& m) : n_(n), out_(out), m_(m) {}
    std::thread::id ranOn;

private:
    void run() override {
        ranOn = std::this_thread::get_id();
        std::lock_guard<std::mutex> lock(m_);
        out_.push_back(n_);
    }
    int n_;
    std::vector<int>& out_;
    std::mutex& m_;
};

class Throws final : public BackgroundJob {
    void run() override { throw std::runtime_error("the job failed"); }
};

TEST(JobThread, RunsJobsInTheOrderHandedOverOffTheCallersThread) {
    JobThread thread;
    std::vector<int> order;
    std::mutex m;
    std::vector<std::shared_ptr<Numbered>> jobs;
    for (int i = 0; i < 20; ++i) {
        jobs.push_back(std::make_shared<Numbered>(i, order, m));
        thread.submit(jobs.back());
    }
    for (const auto& j : jobs) j->wait();
    for (const auto& j : jobs) {
        EXPECT_TRUE(j->done());
        EXPECT_TRUE(j->ran());
        EXPECT_NE(j->ranOn, std::this_thread::get_id());
    }
    std::vector<int> expected(20);
    for (int i = 0; i < 20; ++i) expected[static_cast<std::size_t>(i)] = i;
    EXPECT_EQ(order, expected);
    EXPECT_EQ(thread.backlog(), 0u);
}

TEST(JobThread, CountsWhatWaitsAndSkipsAnAbandonedJob) {
    JobThread thread;
    auto gate = std::make_shared<Gate>();
    thread.submit(gate);
    while (!gate->entered) std::this_thread::yield();
    std::vector<int> order;
    std::mutex m;
    auto kept = std::make_shared<Numbered>(1, order, m);
    auto abandoned = std::make_shared<Numbered>(2, order, m);
    thread.submit(abandoned);
    thread.submit(kept);
    EXPECT_EQ(thread.queued(), 2u);
    EXPECT_EQ(thread.backlog(), 3u) << "the gate under way and the two behind it";
    EXPECT_FALSE(abandoned->done());
    abandoned->abandon();
    gate->open();
    kept->wait();
    abandoned->wait();
    EXPECT_TRUE(abandoned->done());
    EXPECT_FALSE(abandoned->ran());
    EXPECT_TRUE(kept->ran());
    EXPECT_EQ(order, std::vector<int>{1});
}

TEST(JobThread, KeepsWhatAJobThrowsAndRunsTheNext) {
    JobThread thread;
    auto bad = std::make_shared<Throws>();
    std::vector<int> order;
    std::mutex m;
    auto next = std::make_shared<Numbered>(7, order, m);
    thread.submit(bad);
    thread.submit(next);
    next->wait();
    ASSERT_TRUE(bad->done());
    ASSERT_TRUE(bad->error);
    EXPECT_THROW(std::rethrow_exception(bad->error), std::runtime_error);
    EXPECT_EQ(order, std::vector<int>{7});
}

TEST(JobThread, AThreadThatStopsFinishesTheJobUnderWayAndDropsTheRest) {
    auto thread = std::make_unique<JobThread>();
    auto gate = std::make_shared<Gate>();
    thread->submit(gate);
    while (!gate->entered) std::this_thread::yield();
    std::vector<int> order;
    std::mutex m;
    auto dropped = std::make_shared<Numbered>(3, order, m);
    thread->submit(dropped);
    JobThread* raw = thread.get();
    std::thread stop([&thread] { thread.reset(); });
    while (raw->queued() > 0) std::this_thread::yield();  // the stopping thread took it off the queue
    gate->open();
    stop.join();
    EXPECT_TRUE(gate->ran());
    EXPECT_TRUE(dropped->done()) << "nobody waits for ever on a dropped job";
    EXPECT_FALSE(dropped->ran());
    EXPECT_TRUE(order.empty());
}

}  // namespace
}  // namespace hg::jobs
