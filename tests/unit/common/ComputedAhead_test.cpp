// computeAhead (common/ComputedAhead.h): values made on helper threads, used in order on the caller.
#include "common/ComputedAhead.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace mixengine {
namespace {

/// use() sees every index once, in ascending order, with make()'s value for it.
std::vector<long> usedInOrder(int threads, std::size_t ahead) {
    std::vector<long> seen;
    computeAhead<long>(
        50, threads, ahead, [](std::size_t i) { return static_cast<long>(i * i); },
        [&](std::size_t i, long value) {
            EXPECT_EQ(i, seen.size());
            seen.push_back(value);
        });
    return seen;
}

TEST(ComputedAhead, EveryValueIsUsedInOrderWhateverTheThreads) {
    const std::vector<long> inline_run = usedInOrder(1, 4);
    ASSERT_EQ(inline_run.size(), 50U);
    EXPECT_EQ(inline_run[7], 49);
    EXPECT_EQ(usedInOrder(2, 1), inline_run);
    EXPECT_EQ(usedInOrder(3, 8), inline_run);
}

TEST(ComputedAhead, HelpersStayWithinTheLookAhead) {
    std::atomic<std::size_t> used{0};
    std::atomic<bool> too_far{false};
    computeAhead<int>(
        40, 2, 3,
        [&](std::size_t i) {
            // used() below lags computeAhead's own count by at most the value being used.
            if (i >= used.load() + 3 + 1)
                too_far = true;
            return 0;
        },
        [&](std::size_t i, int) {
            used = i + 1;
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        });
    EXPECT_FALSE(too_far.load());
}

TEST(ComputedAhead, AnExceptionFromEitherSideReachesTheCaller) {
    auto failing_make = [] {
        computeAhead<int>(
            30, 2, 4,
            [](std::size_t i) {
                if (i == 11)
                    throw std::runtime_error("make 11");
                return 0;
            },
            [](std::size_t, int) {});
    };
    EXPECT_THROW(failing_make(), std::runtime_error);
    auto failing_use = [] {
        computeAhead<int>(
            30, 2, 4, [](std::size_t) { return 1; },
            [](std::size_t i, int) {
                if (i == 5)
                    throw std::logic_error("use 5");
            });
    };
    EXPECT_THROW(failing_use(), std::logic_error);
}

}  // namespace
}  // namespace mixengine
