#include "graspsim/io/parallel_runs.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

using graspsim::io::runInParallel;

// Every run once, whatever the number of threads (more threads than runs, too).
TEST(ParallelRuns, EveryRunHappensOnce) {
    for (int jobs : {1, 2, 3, 16}) {
        std::vector<std::atomic<int>> calls(10);
        runInParallel(calls.size(), jobs, [&](std::size_t k) { ++calls[k]; });
        for (std::size_t k = 0; k < calls.size(); ++k) EXPECT_EQ(calls[k].load(), 1) << "run " << k << ", jobs " << jobs;
    }
    runInParallel(0, 4, [](std::size_t) { FAIL() << "no run to make"; });
}

// With one job the runs are in order on the calling thread, as the command was before --jobs.
TEST(ParallelRuns, OneJobRunsInOrder) {
    std::vector<std::size_t> order;
    runInParallel(5, 1, [&](std::size_t k) { order.push_back(k); });
    EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
}

// Of the runs that threw, the lowest's exception comes out, after every started run has ended.
TEST(ParallelRuns, TheLowestRunsExceptionIsRethrown) {
    for (int jobs : {1, 2, 4}) {
        std::atomic<int> running{0};
        try {
            runInParallel(8, jobs, [&](std::size_t k) {
                ++running;
                if (k == 1 || k == 2) {
                    --running;
                    throw std::runtime_error("run " + std::to_string(k));
                }
                --running;
            });
            ADD_FAILURE() << "nothing thrown, jobs " << jobs;
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()), "run 1") << "jobs " << jobs;
            EXPECT_EQ(running.load(), 0);
        }
    }
}
