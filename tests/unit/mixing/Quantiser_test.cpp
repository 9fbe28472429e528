// The firmware resolution (mixing/setup/Quantiser.h): whole steps that add up to exactly the resolution.
#include "mixing/setup/Quantiser.h"

#include <gtest/gtest.h>

#include <numeric>

namespace mixengine {
namespace {

MixVector mixOf(std::initializer_list<double> shares) {
    MixVector m;
    m.channels = static_cast<int>(shares.size());
    int c = 0;
    for (double s : shares)
        m[c++] = s;
    return m;
}

TEST(MixingQuantiser, RoundsToNearestStepsAndKeepsTheSum) {
    const auto steps = quantiseSteps(mixOf({0.374, 0.626}), 100);
    EXPECT_EQ(steps[0], 37);
    EXPECT_EQ(steps[1], 63);
    const auto q = quantise(mixOf({0.2, 0.3, 0.5}), 100);
    EXPECT_DOUBLE_EQ(q[0], 0.2);
    EXPECT_DOUBLE_EQ(q[1], 0.3);
    EXPECT_DOUBLE_EQ(q[2], 0.5);
}

TEST(MixingQuantiser, ThirdsAndTiesGoToTheLowerChannel) {
    const auto thirds = quantiseSteps(mixOf({1.0 / 3, 1.0 / 3, 1.0 / 3}), 100);
    EXPECT_EQ(thirds[0], 34);
    EXPECT_EQ(thirds[1], 33);
    EXPECT_EQ(thirds[2], 33);
    const auto half = quantiseSteps(mixOf({0.5, 0.5}), 3);
    EXPECT_EQ(half[0], 2);
    EXPECT_EQ(half[1], 1);
}

TEST(MixingQuantiser, EveryMixOfFiveChannelsSumsToTheResolution) {
    for (int steps : {1, 7, 100, 128, 1000}) {
        for (int k = 0; k < 200; ++k) {
            MixVector m;
            m.channels = 5;
            double sum = 0;
            for (int c = 0; c < 5; ++c)
                sum += (m[c] = (k * (c + 3) % 17) + 0.37 * c);
            for (int c = 0; c < 5; ++c)
                m[c] /= sum;
            const auto q = quantiseSteps(m, steps);
            EXPECT_EQ(std::accumulate(q.begin(), q.end(), 0), steps);
            for (int c = 0; c < 5; ++c)
                EXPECT_LE(std::abs(q[static_cast<std::size_t>(c)] - m[c] * steps), 1.0);
        }
    }
}

TEST(MixingQuantiser, MarlinEightBitResolution) {
    const MixVector q = quantise(mixOf({0.3, 0.7}), 128);  // 38.4 → 38, 89.6 → 90
    EXPECT_DOUBLE_EQ(q[0], 38.0 / 128);
    EXPECT_DOUBLE_EQ(q[1], 90.0 / 128);
}

}  // namespace
}  // namespace mixengine
