// Line infill (toolpaths/LineInfill.h): parallel lines clipped to the area, in zig-zag order.
#include "toolpaths/LineInfill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace mixengine {
namespace {

Path square(coord_um x0, coord_um y0, coord_um size) {
    return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

double lengthUm(const Path& line) {
    return std::hypot(double(line[1].X - line[0].X), double(line[1].Y - line[0].Y));
}

constexpr coord_um kSlack = 2;  // rounding of the rotation, each way

TEST(LineInfill, TenMillimetreSquareAtFortyFiveDegrees) {
    LineInfillParams p;
    p.line_distance_um = 1'000;
    p.line_width_um = 450;
    p.angle_degrees = 45;
    p.speed_mm_s = 80;
    const std::vector<ExtrusionPath> lines = generateLineInfill({square(0, 0, 10'000)}, p);
    // Lines at 1 mm spacing across the 14.142 mm diagonal, the corner itself excluded: 14.
    ASSERT_EQ(lines.size(), 14U);
    double total = 0;
    for (const ExtrusionPath& line : lines) {
        ASSERT_EQ(line.points.size(), 2U);
        EXPECT_FALSE(line.closed);
        EXPECT_EQ(line.width_um, 450);
        EXPECT_EQ(line.feature, Feature::Fill);
        EXPECT_EQ(line.speed_mm_s, 80.0);
        for (const Point2& q : line.points) {
            EXPECT_GE(q.X, -kSlack);
            EXPECT_LE(q.X, 10'000 + kSlack);
            EXPECT_GE(q.Y, -kSlack);
            EXPECT_LE(q.Y, 10'000 + kSlack);
        }
        // Diagonal: |dx| == |dy|, both ends on the square's boundary.
        const coord_um dx = line.points[1].X - line.points[0].X;
        const coord_um dy = line.points[1].Y - line.points[0].Y;
        EXPECT_NEAR(std::abs(dx), std::abs(dy), 2 * kSlack);
        EXPECT_GT(lengthUm(line.points), 250.0);  // shortest chord: 2·(14142 − 14000) µm
        total += lengthUm(line.points);
    }
    // Sum of the chords of the diamond: 2·1000·(1+…+7) + 2·Σ(14142.1 − 1000k, k = 8…14).
    EXPECT_NEAR(total, 99'990.0, 60.0);
}

TEST(LineInfill, NeighboursAreOneLineDistanceApartAndAlternate) {
    LineInfillParams p;
    p.line_distance_um = 1'000;
    p.angle_degrees = 45;
    const std::vector<ExtrusionPath> lines = generateLineInfill({square(0, 0, 10'000)}, p);
    ASSERT_GE(lines.size(), 2U);
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const Path& a = lines[i - 1].points;
        const Path& b = lines[i].points;
        // Perpendicular distance between the parallel lines (normal (1, 1)/√2 for 45° diagonals).
        const double offset_a = (a[0].X + a[0].Y) / std::sqrt(2.0);
        const double offset_b = (b[0].X + b[0].Y) / std::sqrt(2.0);
        EXPECT_NEAR(std::fabs(offset_b - offset_a), 1'000.0, 3.0) << i;
        // Zig-zag: consecutive lines run in opposite directions.
        const double dot = double(a[1].X - a[0].X) * double(b[1].X - b[0].X) +
                           double(a[1].Y - a[0].Y) * double(b[1].Y - b[0].Y);
        EXPECT_LT(dot, 0.0) << i;
    }
}

TEST(LineInfill, ZeroDegreesGivesLinesAlongY) {
    LineInfillParams p;
    p.line_distance_um = 1'000;
    p.angle_degrees = 0;
    p.feature = Feature::Skin;
    const std::vector<ExtrusionPath> lines = generateLineInfill({square(500, 500, 10'000)}, p);
    ASSERT_EQ(lines.size(), 10U);  // x = 1, 2, …, 10 mm
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const Path& line = lines[i].points;
        EXPECT_EQ(lines[i].feature, Feature::Skin);
        EXPECT_EQ(line[0].X, coord_um(1'000 * (i + 1)));
        EXPECT_EQ(line[1].X, coord_um(1'000 * (i + 1)));
        EXPECT_EQ(std::min(line[0].Y, line[1].Y), 500);
        EXPECT_EQ(std::max(line[0].Y, line[1].Y), 10'500);
    }
}

TEST(LineInfill, HoleSplitsLines) {
    Path hole = square(3'000, 3'000, 4'000);
    std::reverse(hole.begin(), hole.end());
    LineInfillParams p;
    p.line_distance_um = 1'000;
    p.angle_degrees = 0;
    const std::vector<ExtrusionPath> lines = generateLineInfill({square(500, 500, 10'000), hole}, p);
    // x = 4, 5, 6 mm cross the hole (3..7 mm) and are cut in two; x = 3 and 7 run along its edges
    // (whether those 4 mm stretches are kept is up to Clipper).
    double total = 0;
    for (const ExtrusionPath& line : lines)
        total += lengthUm(line.points);
    EXPECT_GE(total, 10 * 10'000.0 - 3 * 4'000.0 - 2 * 4'000.0 - 1.0);
    EXPECT_LE(total, 10 * 10'000.0 - 3 * 4'000.0 + 1.0);
    EXPECT_GE(lines.size(), 13U);
    for (const ExtrusionPath& line : lines) {
        const Point2 mid{(line.points[0].X + line.points[1].X) / 2,
                         (line.points[0].Y + line.points[1].Y) / 2};
        const bool inside_hole = mid.X > 3'000 && mid.X < 7'000 && mid.Y > 3'000 && mid.Y < 7'000;
        EXPECT_FALSE(inside_hole) << mid.X << "," << mid.Y;
    }
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
