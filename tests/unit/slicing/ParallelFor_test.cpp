#include "slicing/ParallelFor.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace mixengine {
namespace {

TEST(SlicingParallelFor, CallsEveryIndexOnceOnEachWorkerCount) {
    for (int threads : {-1, 1, 2, 5}) {
        std::vector<std::atomic<int>> calls(97);
        std::atomic<int> bad_worker{0};
        parallelFor(calls.size(), threads, [&](std::size_t i, int worker) {
            ++calls[i];
            if (worker < 0 || worker >= workerCount(calls.size(), threads))
                ++bad_worker;
        });
        for (const auto& c : calls)
            EXPECT_EQ(c.load(), 1);
        EXPECT_EQ(bad_worker.load(), 0);
    }
    EXPECT_EQ(workerCount(3, 8), 3);
    EXPECT_EQ(workerCount(0, 8), 1);
    EXPECT_EQ(workerCount(10, 0), 1);
}

TEST(SlicingParallelFor, RethrowsTheFirstError) {
    EXPECT_THROW(parallelFor(50, 2,
                             [](std::size_t i, int) {
                                 if (i == 7)
                                     throw std::runtime_error("boom");
                             }),
                 std::runtime_error);
}

}  // namespace
}  // namespace mixengine
