// Infill multiplier (toolpaths/infill/InfillMultiplier.h): every line as N parallel lines.
#include "toolpaths/infill/InfillMultiplier.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ToolpathTestSupport.h"

namespace mixengine {
namespace {

double lengthOf(const Paths& lines, bool closed) {
    double total = 0;
    for (const Path& p : lines) {
        for (std::size_t i = 1; i < p.size(); ++i)
            total += std::hypot(double(p[i].X - p[i - 1].X), double(p[i].Y - p[i - 1].Y));
        if (closed && p.size() > 2)
            total += std::hypot(double(p.front().X - p.back().X), double(p.front().Y - p.back().Y));
    }
    return total;
}

const Paths kOutline{test::square(0, 0, 10'000)};

TEST(InfillMultiplier, TwoLinesHalfAWidthEachSideInsteadOfOne) {
    Paths lines{{{5'000, 0}, {5'000, 10'000}}};
    Paths loops;
    multiplyInfill(lines, loops, kOutline, {2, 400, false, false});
    EXPECT_TRUE(loops.empty());
    bool left = false, right = false;
    for (const Path& l : lines) {
        ASSERT_EQ(l.size(), 2U);  // each side is cut off by the outline at both ends
        if (l[0].X == l[1].X) {   // the two long sides of the band
            left = left || l[0].X == 4'800;
            right = right || l[0].X == 5'200;
        }
    }
    EXPECT_TRUE(left && right);
    EXPECT_NEAR(lengthOf(lines, false), 2 * 10'000.0, 1.0);  // the band's ends lie outside the outline
}

TEST(InfillMultiplier, ThreeLinesKeepTheMiddleOne) {
    Paths lines{{{5'000, 1'000}, {5'000, 9'000}}};
    Paths loops;
    multiplyInfill(lines, loops, kOutline, {3, 400, false, false});
    int middle = 0;
    for (const Path& l : lines)
        middle += l[0].X == 5'000 && l[1].X == 5'000 ? 1 : 0;
    EXPECT_EQ(middle, 1);
    // The band 2w wide with square ends (one closed polyline, inside the outline): sides 2 × 8.8 mm,
    // ends 2 × 0.8 mm, plus the middle line.
    EXPECT_NEAR(lengthOf(lines, false), 2 * 8'800.0 + 2 * 800.0 + 8'000.0, 2.0);
}

TEST(InfillMultiplier, ConnectedLinesGiveTheCellsOutlines) {
    Paths lines{{{5'000, 0}, {5'000, 10'000}}};
    Paths loops;
    multiplyInfill(lines, loops, kOutline, {2, 400, true, false});
    EXPECT_TRUE(lines.empty());
    ASSERT_EQ(loops.size(), 2U);  // the two halves of the square beside the band
    EXPECT_NEAR(lengthOf(loops, true), 2 * (2 * 4'800.0 + 2 * 10'000.0), 2.0);
}

TEST(InfillMultiplier, OneLeavesEverythingAsItWas) {
    Paths lines{{{5'000, 0}, {5'000, 10'000}}};
    Paths loops;
    multiplyInfill(lines, loops, kOutline, {1, 400, false, false});
    EXPECT_EQ(lines.size(), 1U);
}

}  // namespace
}  // namespace mixengine
