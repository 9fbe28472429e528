// Zigzag (toolpaths/infill/ZigZag.h): the lines of a square joined along its edge into one polyline.
#include "toolpaths/infill/ZigZag.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ToolpathTestSupport.h"

namespace mixengine {
namespace {

using test::polylineLength;

TEST(ZigZag, SquareBecomesOneConnectedPolyline) {
    // Lines x = 1 … 9 mm in a square 0.5 … 9.5 mm: nine 9 mm lines joined by eight 1 mm pieces.
    const Paths lines = zigzagLines({test::square(500, 500, 9'000)}, 1'000, 0, 0, ZigzagEnds::None);
    ASSERT_EQ(lines.size(), 1U);
    EXPECT_NEAR(polylineLength(lines[0]), 9 * 9'000.0 + 8 * 1'000.0, 1.0);
    // Consecutive vertices alternate: a line along Y, then a step along X on the edge.
    for (std::size_t i = 1; i < lines[0].size(); ++i) {
        const bool along_y = lines[0][i].X == lines[0][i - 1].X;
        const bool along_x = lines[0][i].Y == lines[0][i - 1].Y;
        EXPECT_TRUE(along_x != along_y) << i;
    }
}

TEST(ZigZag, EndPiecesAddTheAreasEnds) {
    // With end pieces the edge beyond the first and last line (0.5 mm each side, along 9 mm) comes too.
    const Paths lines = zigzagLines({test::square(500, 500, 9'000)}, 1'000, 0, 0, ZigzagEnds::Connected);
    double total = 0;
    for (const Path& l : lines)
        total += polylineLength(l);
    EXPECT_NEAR(total, 9 * 9'000.0 + 8 * 1'000.0 + 2 * (9'000.0 + 2 * 500.0), 1.0);
}

TEST(ZigZag, OpenEndPiecesLeaveOutTheirLastLine) {
    // As CuraEngine 4.13's end pieces not connected: each end (0.5 + 9 + 0.5 mm) loses the line that
    // closes it onto the scanline (0.5 mm).
    const Paths lines = zigzagLines({test::square(500, 500, 9'000)}, 1'000, 0, 0, ZigzagEnds::Open);
    double total = 0;
    for (const Path& l : lines)
        total += polylineLength(l);
    EXPECT_NEAR(total, 9 * 9'000.0 + 8 * 1'000.0 + 2 * (9'000.0 + 500.0), 1.0);
}

TEST(ZigZag, PolygonsNoScanlineCrossesArePrintedWholeWithEndPieces) {
    const Paths small{test::square(1'100, 1'100, 600)};  // between the scanlines x = 1 and 2 mm
    EXPECT_TRUE(zigzagLines(small, 1'000, 0, 0, ZigzagEnds::None).empty());
    const auto length = [&](ZigzagEnds ends) {
        double total = 0;
        for (const Path& l : zigzagLines(small, 1'000, 0, 0, ends))
            total += polylineLength(l);
        return total;
    };
    EXPECT_NEAR(length(ZigzagEnds::Connected), 4 * 600.0, 1.0);
    EXPECT_NEAR(length(ZigzagEnds::Open), 3 * 600.0, 1.0);
}

TEST(ZigZag, SkippedZagsBreakItIntoPieces) {
    // Lines x = 1 … 9 mm (scanlines 1 … 9); connections start on even scanlines. With a skip count of 3,
    // as CuraEngine, 6→7 (going right from a multiple of 3) and 4→3 (going left to a multiple of 3) are
    // left out of the eight 1 mm connections: pieces of lines 1-3, 4-6 and 7-9.
    const Paths lines = zigzagLines({test::square(500, 500, 9'000)}, 1'000, 0, 0, ZigzagEnds::None, 3);
    ASSERT_EQ(lines.size(), 3U);
    double total = 0;
    for (const Path& line : lines)
        total += polylineLength(line);
    EXPECT_NEAR(total, 9 * 9'000.0 + 6 * 1'000.0, 1.0);
    EXPECT_EQ(zigzagLines({test::square(500, 500, 9'000)}, 1'000, 0, 0, ZigzagEnds::None, 0).size(),
              1U);  // 0: off
}

TEST(ZigZag, NothingWithoutDistance) {
    EXPECT_TRUE(zigzagLines({test::square(0, 0, 1'000)}, 0, 0, 0, ZigzagEnds::None).empty());
}

}  // namespace
}  // namespace mixengine
