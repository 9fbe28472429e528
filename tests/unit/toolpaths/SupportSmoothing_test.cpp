// The outward smoothing of joined support areas (toolpaths/support/SupportSmoothing.h): sharp notches are
// filled with a shortcut of the given length, everything else is left as it is.
#include "toolpaths/support/SupportSmoothing.h"

#include <gtest/gtest.h>

#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

TEST(SupportSmoothing, AnLShapesInnerCornerGetsAShortcut) {
    // The notch at (5, 5) mm is 90°: a 400 µm shortcut whose ends lie 400 / (2 sin 45°) = 283 µm
    // from the corner on both edges; the outer corners stay.
    const Paths l = {{{0, 0}, {10'000, 0}, {10'000, 5'000}, {5'000, 5'000}, {5'000, 10'000}, {0, 10'000}}};
    const Paths smooth = smoothOutward(l, 135, 400);
    ASSERT_EQ(smooth.size(), 1U);
    EXPECT_EQ(smooth[0], (Path{{0, 0},
                               {10'000, 0},
                               {10'000, 5'000},
                               {5'283, 5'000},
                               {5'000, 5'283},
                               {5'000, 10'000},
                               {0, 10'000}}));
    EXPECT_NEAR(areaUm2(smooth) - areaUm2(l), 283.0 * 283.0 / 2, 300.0);
}

TEST(SupportSmoothing, AHolesCornersAreNotchesToo) {
    // Seen from the support, each corner of a square hole bends into the area: each gets cut.
    const Paths ring = {{{0, 0}, {20'000, 0}, {20'000, 20'000}, {0, 20'000}},
                        {{5'000, 5'000}, {5'000, 15'000}, {15'000, 15'000}, {15'000, 5'000}}};
    const Paths smooth = smoothOutward(ring, 135, 400);
    ASSERT_EQ(smooth.size(), 2U);
    EXPECT_EQ(smooth[0], ring[0]);
    EXPECT_EQ(smooth[1].size(), 8U);
    EXPECT_NEAR(areaUm2(smooth) - areaUm2(ring), 4 * 283.0 * 283.0 / 2, 1'000.0);
}

TEST(SupportSmoothing, WideNotchesAndNoLengthLeaveTheAreaAlone) {
    // A notch of 150° (wider than 135°) stays; so does everything with a zero shortcut.
    const Paths wide = {{{0, 0}, {10'000, 0}, {10'000, 5'000}, {5'000, 3'660}, {0, 5'000}}};
    EXPECT_EQ(smoothOutward(wide, 135, 400), wide);
    const Paths l = {{{0, 0}, {10'000, 0}, {10'000, 5'000}, {5'000, 5'000}, {5'000, 10'000}, {0, 10'000}}};
    EXPECT_EQ(smoothOutward(l, 135, 0), l);
}

}  // namespace
}  // namespace mixengine
