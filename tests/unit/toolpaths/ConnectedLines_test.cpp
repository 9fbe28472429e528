// Connected infill lines (toolpaths/infill/ConnectedLines.h): lines joined along the area's edge.
#include "toolpaths/infill/ConnectedLines.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ToolpathTestSupport.h"

namespace mixengine {
namespace {

using test::polylineLength;

double totalLength(const Paths& lines) {
    double total = 0;
    for (const Path& l : lines)
        total += polylineLength(l);
    return total;
}

TEST(ConnectedLines, ParallelLinesBecomeOneChainAlongTheEdge) {
    // Lines x = 1 … 9 mm in a square 0.5 … 9.5 mm, walked from (0.5, 0.5) counter-clockwise: along
    // the bottom 1–2, 3–4, 5–6, 7–8 are joined; 9 (its own top end passed over) goes round the
    // corner to the top of 8 (0.5 + 9 + 1.5 mm); along the top 7–6, 5–4, 3–2; the connector from
    // the top of 1 stays open as a 0.5 mm tail to the last corner. One chain.
    const Paths lines = connectedLines({test::square(500, 500, 9'000)}, {{1'000, 0, 0}});
    ASSERT_EQ(lines.size(), 1U);
    EXPECT_NEAR(polylineLength(lines[0]), 9 * 9'000.0 + 7 * 1'000.0 + 11'000.0 + 500.0, 1.0);
    EXPECT_EQ(lines[0].front(), Point2(500, 9'500));  // the tail's end is an end of the chain
}

TEST(ConnectedLines, CrossingSetsJoinIntoFewChainsWithoutLosingLines) {
    const Paths area{test::square(0, 0, 20'000)};
    const std::vector<LineSet> sets{{2'000, 45, 0}, {2'000, 135, 0}};
    const Paths lines = connectedLines(area, sets);
    // Every scanline segment is in some chain: at least the length of the bare lines.
    const double bare = 2 * 20'000.0 * 20'000.0 / 2'000.0;
    EXPECT_GT(totalLength(lines), 0.97 * bare);
    EXPECT_LT(lines.size(), 6U);  // instead of about 28 separate segments
    for (const Path& line : lines)
        for (const Point2& p : line) {
            EXPECT_GE(p.X, -2);
            EXPECT_LE(p.X, 20'002);
            EXPECT_GE(p.Y, -2);
            EXPECT_LE(p.Y, 20'002);
        }
}

TEST(ConnectedLines, NothingWithoutSpacing) {
    EXPECT_TRUE(connectedLines({test::square(0, 0, 1'000)}, {{0, 0, 0}}).empty());
}

}  // namespace
}  // namespace mixengine
