// Scanline crossings (toolpaths/infill/ScanCrossings.h): where vertical lines cross polygon edges.
#include "toolpaths/infill/ScanCrossings.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"

namespace mixengine {
namespace {

TEST(ScanCrossings, SquareCrossedTwicePerLineAndPaired) {
    // x = 1, 2, 3 mm through the square 0.5 … 3.5 mm: the bottom edge (edge 0) then the top (edge 2).
    const std::vector<ScanCrossing> cs = findScanCrossings({test::square(500, 500, 3'000)}, 1'000, 0);
    ASSERT_EQ(cs.size(), 6U);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(cs[i].edge, 0U);
        EXPECT_EQ(cs[i].point, Point2(coord_um(1'000 * (i + 1)), 500));
        EXPECT_EQ(cs[3 + i].edge, 2U);
        EXPECT_EQ(cs[3 + i].point, Point2(coord_um(3'000 - 1'000 * i), 3'500));  // walking right to left
    }
    const std::vector<long> partner = pairOnScanlines(cs);
    EXPECT_EQ(partner[0], 5);
    EXPECT_EQ(partner[1], 4);
    EXPECT_EQ(partner[2], 3);
}

TEST(ScanCrossings, VertexOnAScanlineCountsOnce) {
    // A diamond with its left and right corners on the scanlines x = 0 and 2 mm: those lines only
    // touch it; x = 1 mm crosses it twice.
    const Paths diamond{{{0, 1'000}, {1'000, 0}, {2'000, 1'000}, {1'000, 2'000}}};
    const std::vector<ScanCrossing> cs = findScanCrossings(diamond, 1'000, 0);
    std::size_t through_middle = 0;
    for (const ScanCrossing& c : cs)
        through_middle += c.line == 1 ? 1 : 0;
    EXPECT_EQ(through_middle, 2U);
    EXPECT_EQ(cs.size() % 2, 0U);
}

}  // namespace
}  // namespace mixengine
