// The line frame of line and zig-zag infill (toolpaths/infill/LineFrame.h) and its grid arithmetic.
#include "toolpaths/infill/LineFrame.h"

#include <gtest/gtest.h>

#include "geometry/Angles.h"

namespace mixengine {
namespace {

TEST(LineFrame, NinetyDegreesTurnsCounterClockwiseIntoTheFrameAndBack) {
    const LineFrame frame(90);
    Paths lines = frame.into({{{1'000, 0}, {0, 2'000}}});
    EXPECT_EQ(lines, (Paths{{{0, 1'000}, {-2'000, 0}}}));
    frame.back(lines);
    EXPECT_EQ(lines, (Paths{{{1'000, 0}, {0, 2'000}}}));
}

TEST(LineFrame, FloorDivRoundsTowardsMinusInfinity) {
    EXPECT_EQ(floorDiv(7, 2), 3);
    EXPECT_EQ(floorDiv(-7, 2), -4);
    EXPECT_EQ(floorDiv(7, -2), -4);
    EXPECT_EQ(floorDiv(-8, 2), -4);
    EXPECT_EQ(floorDiv(0, 5), 0);
}

TEST(LineFrame, LinePhaseIsTheShiftModuloTheSpacing) {
    EXPECT_EQ(linePhase(250, 1'000), 250);
    EXPECT_EQ(linePhase(1'250, 1'000), 250);
    EXPECT_EQ(linePhase(-250, 1'000), 750);
    EXPECT_EQ(linePhase(-1'000, 1'000), 0);
}

TEST(Angles, BothRoundingsGiveRightAnglesAndHalfTurns) {
    EXPECT_DOUBLE_EQ(radiansFromDegrees(180), std::numbers::pi);
    EXPECT_DOUBLE_EQ(90 * kRadiansPerDegree, std::numbers::pi / 2);
    EXPECT_DOUBLE_EQ(radiansFromDegrees(-45), -std::numbers::pi / 4);
}

}  // namespace
}  // namespace mixengine
