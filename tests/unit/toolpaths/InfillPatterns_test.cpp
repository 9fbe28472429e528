// Infill patterns (toolpaths/infill/InfillPatterns.h): amounts and shapes on a square.
#include "toolpaths/infill/InfillPatterns.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "ToolpathTestSupport.h"
#include "common/Error.h"

namespace mixengine {
namespace {

using test::square;
using test::totalLength;

const Paths kArea{square(0, 0, 40'000)};

std::vector<ExtrusionPath> infill(InfillPattern pattern, coord_um distance, coord_um z = 0,
                                  double angle = 45) {
    InfillParams p;
    p.pattern = pattern;
    p.line_distance_um = distance;
    p.angle_degrees = angle;
    p.z_um = z;
    return generateInfill(kArea, p);
}

/// Length per area of `distance`-spaced lines, times the area: what every pattern should print
/// when its distance carries Cura's multiplier (grid ×2, triangles/cubic ×3, tetrahedral ×2).
double linesLength(coord_um distance) {
    return 40'000.0 * 40'000.0 / double(distance);
}

TEST(InfillPatterns, LinesAtZeroDegreesAreExact) {
    InfillParams p;
    p.line_distance_um = 2'000;
    p.angle_degrees = 0;
    const std::vector<ExtrusionPath> lines = generateInfill({square(1'000, 1'000, 38'000)}, p);
    EXPECT_EQ(lines.size(), 19U);  // x = 2, 4, …, 38 mm
    EXPECT_NEAR(totalLength(lines), 19 * 38'000.0, 1.0);
}

TEST(InfillPatterns, EveryPatternPrintsTheSameAmountAsLines) {
    struct Case {
        InfillPattern pattern;
        int multiplier;
        double tolerance;
    };
    const Case cases[] = {{InfillPattern::Lines, 1, 0.02},        {InfillPattern::Grid, 2, 0.02},
                          {InfillPattern::Triangles, 3, 0.02},    {InfillPattern::TriHexagon, 3, 0.02},
                          {InfillPattern::Cubic, 3, 0.02},        {InfillPattern::Tetrahedral, 2, 0.02},
                          {InfillPattern::QuarterCubic, 2, 0.02}, {InfillPattern::Gyroid, 1, 0.08}};
    for (const Case& c : cases) {
        const double expected = linesLength(2'000);
        const double got = totalLength(infill(c.pattern, 2'000 * c.multiplier, 5'000));
        EXPECT_NEAR(got / expected, 1.0, c.tolerance) << static_cast<int>(c.pattern);
    }
}

TEST(InfillPatterns, GridCrossesAtRightAngles) {
    std::set<long> directions;
    for (const ExtrusionPath& line : infill(InfillPattern::Grid, 4'000)) {
        const double a = std::atan2(double(line.points[1].Y - line.points[0].Y),
                                    double(line.points[1].X - line.points[0].X));
        directions.insert(std::lround(std::fmod(a * 180 / std::numbers::pi + 360.0, 180.0)));
    }
    EXPECT_EQ(directions, (std::set<long>{45, 135}));
}

TEST(InfillPatterns, CubicShiftsWithHeightTrianglesDoNot) {
    const auto first = [](const std::vector<ExtrusionPath>& lines) { return lines.front().points; };
    EXPECT_EQ(first(infill(InfillPattern::Triangles, 6'000, 0)),
              first(infill(InfillPattern::Triangles, 6'000, 3'000)));
    EXPECT_NE(first(infill(InfillPattern::Cubic, 6'000, 0)),
              first(infill(InfillPattern::Cubic, 6'000, 3'000)));
}

TEST(InfillPatterns, ConcentricLoopsOneDistanceApart) {
    const std::vector<ExtrusionPath> loops = infill(InfillPattern::Concentric, 4'000);
    // First loop 4 − 0.2 mm inside the edge, then every 4 mm: side 40 − 2·3.8 = 32.4, 24.4, …, 0.4 mm.
    ASSERT_EQ(loops.size(), 5U);
    for (std::size_t i = 0; i < loops.size(); ++i) {
        EXPECT_TRUE(loops[i].closed);
        EXPECT_NEAR(test::pathLength(loops[i]), 4 * (32'400.0 - 8'000.0 * double(i)), 1.0) << i;
    }
}

TEST(InfillPatterns, GyroidIsCurvedAndReachesTheEdges) {
    const std::vector<ExtrusionPath> curves = infill(InfillPattern::Gyroid, 2'000, 1'234);
    ASSERT_FALSE(curves.empty());
    std::size_t many_points = 0;
    for (const ExtrusionPath& c : curves) {
        many_points += c.points.size() > 10 ? 1 : 0;
        for (const Point2& p : c.points) {
            EXPECT_GE(p.X, -1);
            EXPECT_LE(p.X, 40'001);
            EXPECT_GE(p.Y, -1);
            EXPECT_LE(p.Y, 40'001);
        }
    }
    EXPECT_GT(many_points, curves.size() / 2);
}

TEST(InfillPatterns, LinesPassThroughTheOrigin) {
    InfillParams p;
    p.line_distance_um = 2'000;
    p.angle_degrees = 0;
    p.origin_um = {12'345, 777};  // at 0° the lines are x = 12.345 mm + k · 2 mm
    for (const ExtrusionPath& line : generateInfill(kArea, p))
        EXPECT_EQ((line.points[0].X - 12'345) % 2'000, 0) << line.points[0].X;
    p.angle_degrees = 180;  // the same lines, found in the frame turned half a turn
    for (const ExtrusionPath& line : generateInfill(kArea, p))
        EXPECT_EQ((line.points[0].X - 12'345) % 2'000, 0) << line.points[0].X;
    p.origin_um = {0, 777};
    p.angle_degrees = 270;  // y = 0.777 mm + k · 2 mm
    for (const ExtrusionPath& line : generateInfill(kArea, p))
        EXPECT_EQ((line.points[0].Y - 777) % 2'000, 0) << line.points[0].Y;
}

TEST(InfillPatterns, WallsAroundTheAreaAndLinesInsideThem) {
    InfillParams p;
    p.line_distance_um = 4'000;
    p.angle_degrees = 0;
    p.wall_count = 2;
    p.overlap_um = 100;
    const std::vector<ExtrusionPath> paths = generateInfill(kArea, p);
    ASSERT_GE(paths.size(), 3U);
    // Loops 0.2 and 0.6 mm inside the 40 mm square, then the lines reach 0.8 − 0.1 mm from its edge.
    EXPECT_TRUE(paths[0].closed && paths[1].closed);
    EXPECT_NEAR(test::pathLength(paths[0]), 4 * 39'600.0, 1.0);
    EXPECT_NEAR(test::pathLength(paths[1]), 4 * 38'800.0, 1.0);
    for (std::size_t i = 2; i < paths.size(); ++i) {
        EXPECT_FALSE(paths[i].closed);
        EXPECT_NEAR(test::pathLength(paths[i]), 40'000.0 - 2 * 700.0, 1.0) << i;
    }
}

TEST(InfillPatterns, MultiplierPrintsEveryLineTwice) {
    InfillParams p;
    p.line_distance_um = 4'000;
    p.angle_degrees = 0;
    p.origin_um = {2'000, 0};  // x = 2, 6, …, 38 mm: none on the edge
    const double single = test::totalLength(generateInfill(kArea, p));
    p.multiplier = 2;
    EXPECT_NEAR(test::totalLength(generateInfill(kArea, p)) / single, 2.0, 0.02);
    p.multiplier = 3;
    EXPECT_NEAR(test::totalLength(generateInfill(kArea, p)) / single, 3.0, 0.03);
}

TEST(InfillPatterns, ConnectedLinesArePolylinesAlongTheEdge) {
    InfillParams p;
    p.pattern = InfillPattern::Cubic;
    p.line_distance_um = 6'000;
    const std::vector<ExtrusionPath> separate = generateInfill(kArea, p);
    p.connect_lines = true;
    const std::vector<ExtrusionPath> connected = generateInfill(kArea, p);
    EXPECT_LT(connected.size() * 4, separate.size());
    EXPECT_GT(test::totalLength(connected), test::totalLength(separate));  // the connectors
}

TEST(InfillPatterns, NamesAsCura) {
    EXPECT_EQ(infillPatternOf("grid", "infill_pattern"), InfillPattern::Grid);
    EXPECT_EQ(infillPatternOf("quarter_cubic", "infill_pattern"), InfillPattern::QuarterCubic);
    EXPECT_EQ(infillPatternOf("cubicsubdiv", "infill_pattern"), InfillPattern::CubicSubdiv);
    EXPECT_EQ(infillPatternOf("cross", "infill_pattern"), InfillPattern::Cross);
    EXPECT_EQ(infillPatternOf("cross_3d", "infill_pattern"), InfillPattern::Cross3d);
    EXPECT_EQ(infillPatternOf("lightning", "infill_pattern"), InfillPattern::Lightning);
    EXPECT_THROW(infillPatternOf("honeycomb", "infill_pattern"), InputError);
    EXPECT_TRUE(infill(InfillPattern::Grid, 0).empty());
}

}  // namespace
}  // namespace mixengine
