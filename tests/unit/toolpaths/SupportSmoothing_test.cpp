// The outward smoothing of joined support areas (toolpaths/support/SupportSmoothing.h): sharp notches are
// filled with a shortcut of the given length, everything else is left as it is. The expected points are
// those CuraEngine 4.13's Polygons::smooth_outward(135, 400) returns for the same loops (its source built
// and run on them), to the micrometre.
#include "toolpaths/support/SupportSmoothing.h"

#include <gtest/gtest.h>

#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

TEST(SupportSmoothing, AnLShapesInnerCornerGetsAShortcut) {
    // The notch at (5, 5) mm is 90°: a 400 µm shortcut whose ends lie 400 / (2 sin 45°) = 282.8 µm
    // (truncated to 282) from the corner on both edges; the outer corners stay.
    const Paths l = {{{0, 0}, {10'000, 0}, {10'000, 5'000}, {5'000, 5'000}, {5'000, 10'000}, {0, 10'000}}};
    const Paths smooth = smoothOutward(l, 135, 400);
    ASSERT_EQ(smooth.size(), 1U);
    EXPECT_EQ(smooth[0], (Path{{0, 0},
                               {10'000, 0},
                               {10'000, 5'000},
                               {5'282, 5'000},
                               {5'000, 5'282},
                               {5'000, 10'000},
                               {0, 10'000}}));
    EXPECT_NEAR(areaUm2(smooth) - areaUm2(l), 282.0 * 282.0 / 2, 1.0);
}

TEST(SupportSmoothing, AHolesCornersAreNotchesToo) {
    // Seen from the support, each corner of a square hole bends into the area: each gets cut.
    const Paths ring = {{{0, 0}, {20'000, 0}, {20'000, 20'000}, {0, 20'000}},
                        {{5'000, 5'000}, {5'000, 15'000}, {15'000, 15'000}, {15'000, 5'000}}};
    const Paths smooth = smoothOutward(ring, 135, 400);
    ASSERT_EQ(smooth.size(), 2U);
    EXPECT_EQ(smooth[0], ring[0]);
    EXPECT_EQ(smooth[1], (Path{{14'718, 5'000},
                               {5'282, 5'000},
                               {5'000, 5'282},
                               {5'000, 14'718},
                               {5'282, 15'000},
                               {14'718, 15'000},
                               {15'000, 14'718},
                               {15'000, 5'282}}));
}

TEST(SupportSmoothing, ANarrowSlotsCornersWalkAlongItsSides) {
    // A slot 0.3 mm wide, 2 mm deep: its bottom corners are notches whose neighbours lie closer than the
    // shortcut, so its ends walk along the slot's sides until it is 400 µm long.
    const Paths slot = {{{0, 0},
                         {10'000, 0},
                         {10'000, 5'000},
                         {5'150, 5'000},
                         {5'150, 3'000},
                         {4'850, 3'000},
                         {4'850, 5'000},
                         {0, 5'000}}};
    const Paths smooth = smoothOutward(slot, 135, 400);
    ASSERT_EQ(smooth.size(), 1U);
    EXPECT_EQ(smooth[0], (Path{{0, 0},
                               {10'000, 0},
                               {10'000, 5'000},
                               {5'150, 5'000},
                               {5'150, 3'282},
                               {4'868, 3'000},
                               {4'850, 3'399},
                               {4'850, 5'000},
                               {0, 5'000}}));
}

TEST(SupportSmoothing, AnUnevenVGetsItsShortcutAtEqualDistances) {
    // A V notch of unequal sides: the shortcut's ends lie at the same distance from its corner.
    const Paths v = {{{0, 0}, {10'000, 0}, {10'000, 5'000}, {5'000, 2'000}, {4'000, 5'000}, {0, 5'000}}};
    const Paths smooth = smoothOutward(v, 135, 400);
    ASSERT_EQ(smooth.size(), 1U);
    EXPECT_EQ(smooth[0], (Path{{0, 0},
                               {10'000, 0},
                               {10'000, 5'000},
                               {5'273, 2'164},
                               {4'900, 2'302},
                               {4'000, 5'000},
                               {0, 5'000}}));
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
