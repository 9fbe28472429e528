// Monotonic line order (toolpaths/skin/MonotonicOrder.h): runs of adjacent lines across the area.
#include "toolpaths/skin/MonotonicOrder.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

Path vertical(coord_um x, coord_um y0, coord_um y1) {
    return {{x, y0}, {x, y1}};
}

TEST(MonotonicOrder, LinesAtZeroDegreesArePrintedFromRightToLeft) {
    // At 0° the lines run along Y and the direction is (−1, 0): largest X first, whatever the input order.
    const Paths lines{vertical(400, 0, 10'000), vertical(1'200, 0, 10'000), vertical(0, 10'000, 0),
                      vertical(800, 0, 10'000)};
    const Paths ordered = monotonicOrder(lines, 0, 440);
    ASSERT_EQ(ordered.size(), 4U);
    EXPECT_EQ(ordered[0], vertical(1'200, 0, 10'000));
    EXPECT_EQ(ordered[1], vertical(800, 0, 10'000));
    EXPECT_EQ(ordered[2], vertical(400, 0, 10'000));
    EXPECT_EQ(ordered[3], vertical(0, 10'000, 0));  // the ends are left as they were
}

TEST(MonotonicOrder, EachSideOfAHoleIsARunOfItsOwn) {
    // Full lines at x 1.2 and 0 mm, lines split by a hole (y 4 … 6 mm) at 0.8 and 0.4 mm: the full
    // line first, then the lower run to the hole's end, then the upper run, then the last full line.
    const Path low8 = vertical(800, 0, 4'000), high8 = vertical(800, 6'000, 10'000);
    const Path low4 = vertical(400, 0, 4'000), high4 = vertical(400, 6'000, 10'000);
    const Paths lines{vertical(0, 0, 10'000), high4, low4, high8, low8, vertical(1'200, 0, 10'000)};
    const Paths ordered = monotonicOrder(lines, 0, 440);
    ASSERT_EQ(ordered.size(), 6U);
    EXPECT_EQ(ordered[0], vertical(1'200, 0, 10'000));
    // The two 0.8 mm lines tie; the run of whichever came first in the input goes first.
    EXPECT_EQ(ordered[1], high8);
    EXPECT_EQ(ordered[2], high4);
    EXPECT_EQ(ordered[3], low8);
    EXPECT_EQ(ordered[4], low4);
    EXPECT_EQ(ordered[5], vertical(0, 0, 10'000));
}

TEST(MonotonicOrder, LinesTooFarApartAreOrderedByTheirPositionOnly) {
    // At 90° the lines run along X and the direction is (0, 1): lowest Y first.
    const Paths lines{{{0, 5'000}, {3'000, 5'000}}, {{0, 0}, {3'000, 0}}, {{0, 2'000}, {3'000, 2'000}}};
    const Paths ordered = monotonicOrder(lines, 90, 440);
    ASSERT_EQ(ordered.size(), 3U);
    EXPECT_EQ(ordered[0].front().Y, 0);
    EXPECT_EQ(ordered[1].front().Y, 2'000);
    EXPECT_EQ(ordered[2].front().Y, 5'000);
}

}  // namespace
}  // namespace mixengine
