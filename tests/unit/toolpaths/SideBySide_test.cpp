// Side-by-side groups (geometry/SideBySide.h) and the area operations that run them apart
// (geometry/PolygonOps.h): the result must be the one a single operation gives.
#include "geometry/SideBySide.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::square;

using Groups = std::vector<std::vector<std::size_t>>;

TEST(SideBySide, LoopsApartInXAreGroupedLeftToRight) {
    // 1 lies right of 0; 2 lies high above 0 but overlaps it in x, so it shares 0's scan lines' edges.
    const Paths a{square(20'000, 0, 10'000), square(0, 0, 10'000), square(5'000, 50'000, 10'000)};
    EXPECT_EQ(sideBySideGroups(a, {}, 0), (Groups{{1, 2}, {0}}));
    EXPECT_EQ(sideBySideGroups(a, {}, 2'400), (Groups{{1, 2}, {0}}));
    EXPECT_TRUE(sideBySideGroups(a, {}, 2'500).empty());  // 2 × 2.5 mm bridges the 5 mm gap: one group
}

TEST(SideBySide, SecondOperandLoopsAreNumberedAfterTheFirst) {
    const Paths a{square(0, 0, 10'000)};
    const Paths b{square(100'000, 0, 10'000), square(5'000, 5'000, 10'000)};
    EXPECT_EQ(sideBySideGroups(a, b, 2), (Groups{{0, 2}, {1}}));
    EXPECT_TRUE(sideBySideGroups(a, {}, 2).empty());
    EXPECT_TRUE(sideBySideGroups({}, {}, 2).empty());
}

TEST(SideBySide, OffsetsStillMergeLoopsTheyGrowInto) {
    // 1 mm apart: grown by 0.6 mm each they meet and unite; 3 mm apart they stay two.
    const Paths near{square(0, 0, 10'000), square(11'000, 0, 10'000)};
    const Paths grown_near = offsetMiter(near, 600);
    ASSERT_EQ(grown_near.size(), 1U);
    EXPECT_EQ(areaUm2(grown_near), 22'200.0 * 11'200.0);
    const Paths far{square(0, 0, 10'000), square(13'000, 0, 10'000)};
    EXPECT_EQ(offsetMiter(far, 600).size(), 2U);
    EXPECT_EQ(areaUm2(offsetMiter(far, 600)), 2 * 11'200.0 * 11'200.0);
}

TEST(SideBySide, BooleansOnGroupsApartGiveTheWholeResult) {
    const Paths a{square(0, 0, 10'000), square(50'000, 0, 10'000)};
    const Paths b{square(5'000, 0, 10'000), square(100'000, 0, 10'000)};
    EXPECT_EQ(areaUm2(differenceOf(a, b)), 150e6);
    EXPECT_EQ(areaUm2(intersectAll(a, b)), 50e6);
    EXPECT_EQ(areaUm2(unionOf(a, b)), 350e6);
    EXPECT_EQ(splitIslands(unionOf(a, b)).size(), 3U);
    // A hole stays with its outline: its x range lies inside the outline's.
    const Paths with_hole{square(0, 0, 10'000), test::rect(3'000, 3'000, 7'000, 7'000),
                          square(30'000, 0, 1'000)};
    Paths reversed = with_hole;
    std::reverse(reversed[1].begin(), reversed[1].end());
    EXPECT_EQ(areaUm2(unionOf(reversed)), 100e6 - 16e6 + 1e6);
    EXPECT_EQ(splitIslands(reversed).size(), 2U);
}

TEST(SideBySide, DifferenceWithoutSmallIslandsIsTheDifferenceFilteredInOnePass) {
    // Left: a 10 mm square less a 9 mm one at its lower right leaves an L of 19 mm². Right: two
    // 9 mm squares leave two 1 mm² corners.
    const Paths a{square(0, 0, 10'000), square(40'000, 0, 10'000)};
    const Paths b{square(1'000, 0, 9'000), square(40'000, 1'000, 9'000), square(41'000, 0, 9'000)};
    const Paths all = differenceOf(a, b);
    EXPECT_EQ(areaUm2(all), 21e6);
    EXPECT_EQ(areaUm2(differenceWithoutSmallIslands(a, b, 0)), 21e6);
    EXPECT_EQ(areaUm2(differenceWithoutSmallIslands(a, b, 1e6)), 21e6);
    EXPECT_EQ(areaUm2(differenceWithoutSmallIslands(a, b, 1.5e6)), 19e6);
    EXPECT_EQ(areaUm2(removeSmallIslands(all, 1.5e6)), 19e6);
    EXPECT_TRUE(differenceWithoutSmallIslands(a, b, 20e6).empty());
    EXPECT_TRUE(differenceWithoutSmallIslands({}, b, 1).empty());
}

}  // namespace
}  // namespace mixengine
