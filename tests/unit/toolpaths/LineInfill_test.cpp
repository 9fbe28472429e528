// Line infill (toolpaths/infill/LineInfill.h): parallel lines on the plate's grid, clipped to the area.
#include "toolpaths/infill/LineInfill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ToolpathTestSupport.h"

namespace mixengine {
namespace {

using test::square;

double lengthOf(const Path& line) {
    return std::hypot(double(line[1].X - line[0].X), double(line[1].Y - line[0].Y));
}

TEST(LineInfill, ZeroDegreesGivesLinesAlongYOnTheMillimetreGrid) {
    LineInfillParams p;
    p.line_distance_um = 1'000;
    p.angle_degrees = 0;
    p.feature = Feature::Skin;
    p.flow = 0.8;
    p.extruder = 1;
    const std::vector<ExtrusionPath> lines = generateLineInfill({square(500, 500, 10'000)}, p);
    ASSERT_EQ(lines.size(), 10U);  // x = 1, 2, …, 10 mm
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const Path& line = lines[i].points;
        EXPECT_EQ(lines[i].feature, Feature::Skin);
        EXPECT_EQ(lines[i].flow, 0.8);
        EXPECT_EQ(lines[i].extruder, 1);
        EXPECT_FALSE(lines[i].closed);
        EXPECT_EQ(line[0].X, coord_um(1'000 * (i + 1)));
        EXPECT_EQ(line[1].X, coord_um(1'000 * (i + 1)));
        EXPECT_EQ(std::min(line[0].Y, line[1].Y), 500);
        EXPECT_EQ(std::max(line[0].Y, line[1].Y), 10'500);
    }
}

TEST(LineInfill, ShiftMovesTheGrid) {
    LineInfillParams p;
    p.line_distance_um = 1'000;
    p.angle_degrees = 0;
    p.shift_um = 250;
    const std::vector<ExtrusionPath> lines = generateLineInfill({square(0, 0, 5'000)}, p);
    ASSERT_EQ(lines.size(), 5U);  // x = 0.25, 1.25, …, 4.25 mm
    EXPECT_EQ(lines[0].points[0].X, 250);
    EXPECT_EQ(lines[4].points[0].X, 4'250);
}

TEST(LineInfill, FortyFiveDegreesRunsSouthWestToNorthEastAndAlternates) {
    LineInfillParams p;
    p.line_distance_um = 1'000;
    p.angle_degrees = 45;
    const std::vector<ExtrusionPath> lines = generateLineInfill({square(0, 0, 10'000)}, p);
    // In the rotated frame x' = (x − y)/√2 spans ±7.07 mm: lines at k mm for k = −7 … 7.
    ASSERT_EQ(lines.size(), 15U);
    double total = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const Path& a = lines[i].points;
        const coord_um dx = a[1].X - a[0].X, dy = a[1].Y - a[0].Y;
        EXPECT_NEAR(double(dx), double(dy), 3.0) << i;  // "/" direction (dx and dy of one sign)
        total += lengthOf(a);
        if (i == 0)
            continue;
        const Path& b = lines[i - 1].points;
        const double offset_a = (a[0].X - a[0].Y) / std::sqrt(2.0);
        const double offset_b = (b[0].X - b[0].Y) / std::sqrt(2.0);
        EXPECT_NEAR(std::fabs(offset_b - offset_a), 1'000.0, 3.0) << i;
        EXPECT_LT(double(dx) * double(b[1].X - b[0].X), 0.0) << i;  // zig-zag order
    }
    // Chord through the diagonal plus 2 × Σ chords at k = 1 … 7 mm: 14142 + 2·Σ(14142 − 2000k).
    EXPECT_NEAR(total, 14'142.1 + 2 * (7 * 14'142.1 - 2'000.0 * 28), 30.0);
}

TEST(LineInfill, HoleSplitsLines) {
    Path hole = square(3'000, 3'000, 4'000);
    std::reverse(hole.begin(), hole.end());
    LineInfillParams p;
    p.line_distance_um = 1'000;
    p.angle_degrees = 0;
    const std::vector<ExtrusionPath> lines = generateLineInfill({square(500, 500, 10'000), hole}, p);
    double total = 0;
    for (const ExtrusionPath& line : lines) {
        total += lengthOf(line.points);
        const Point2 mid{(line.points[0].X + line.points[1].X) / 2,
                         (line.points[0].Y + line.points[1].Y) / 2};
        EXPECT_FALSE(mid.X > 3'000 && mid.X < 7'000 && mid.Y > 3'000 && mid.Y < 7'000)
            << mid.X << "," << mid.Y;
    }
    // x = 4, 5, 6 mm lose 4 mm each to the hole; x = 3 and 7 run along its edges (kept or not).
    EXPECT_GE(total, 10 * 10'000.0 - 3 * 4'000.0 - 2 * 4'000.0 - 1.0);
    EXPECT_LE(total, 10 * 10'000.0 - 3 * 4'000.0 + 1.0);
}

TEST(LineInfill, NothingWithoutDistanceOrArea) {
    LineInfillParams p;
    p.line_distance_um = 0;
    EXPECT_TRUE(generateLineInfill({square(0, 0, 10'000)}, p).empty());
    p.line_distance_um = 1'000;
    EXPECT_TRUE(generateLineInfill({}, p).empty());
}

}  // namespace
}  // namespace mixengine
