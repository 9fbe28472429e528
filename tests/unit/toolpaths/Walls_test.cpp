// Wall generation (toolpaths/Walls.h): concentric insets with exact geometry on squares.
#include "toolpaths/Walls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mixengine {
namespace {

Path square(coord_um x0, coord_um y0, coord_um size) {
    return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};  // counter-clockwise
}

double areaOf(const Paths& paths) {
    double total = 0;
    for (const Path& p : paths)
        total += ClipperLib::Area(p);
    return total;
}

/// The corners of an axis-aligned square loop, sorted, for exact comparison.
Path sortedCorners(Path p) {
    std::sort(p.begin(), p.end(),
              [](const Point2& a, const Point2& b) { return a.X != b.X ? a.X < b.X : a.Y < b.Y; });
    return p;
}

TEST(Walls, TwentyMillimetreSquareTwoWalls) {
    const WallResult result = generateWalls({square(0, 0, 20'000)}, WallParams{});
    ASSERT_EQ(result.walls.size(), 2U);
    const ExtrusionPath& outer = result.walls[0];
    const ExtrusionPath& inner = result.walls[1];
    EXPECT_EQ(outer.feature, Feature::WallOuter);
    EXPECT_EQ(inner.feature, Feature::WallInner);
    EXPECT_TRUE(outer.closed && inner.closed);
    EXPECT_EQ(outer.width_um, 400);
    EXPECT_EQ(inner.width_um, 400);
    EXPECT_EQ(outer.speed_mm_s, 30.0);
    EXPECT_EQ(inner.speed_mm_s, 60.0);
    EXPECT_NEAR(ClipperLib::Area(outer.points), 19'600.0 * 19'600.0, 1.0);
    EXPECT_NEAR(ClipperLib::Area(inner.points), 18'800.0 * 18'800.0, 1.0);
    EXPECT_EQ(sortedCorners(outer.points), sortedCorners(square(200, 200, 19'600)));
    EXPECT_EQ(sortedCorners(inner.points), sortedCorners(square(600, 600, 18'800)));
    ASSERT_EQ(result.inner_area.size(), 1U);
    EXPECT_NEAR(areaOf(result.inner_area), 18'400.0 * 18'400.0, 1.0);
    EXPECT_EQ(sortedCorners(result.inner_area[0]), sortedCorners(square(800, 800, 18'400)));
}

TEST(Walls, WidthsAndOuterInset) {
    WallParams p;
    p.wall_count = 3;
    p.outer_width_um = 400;
    p.inner_width_um = 500;
    p.outer_inset_um = 100;
    const WallResult result = generateWalls({square(0, 0, 20'000)}, p);
    ASSERT_EQ(result.walls.size(), 3U);
    // Centres at 300 (200 + inset 100), 300 + 200 + 250 = 750, 750 + 500 = 1250; inner edge 1500.
    EXPECT_EQ(sortedCorners(result.walls[0].points), sortedCorners(square(300, 300, 19'400)));
    EXPECT_EQ(sortedCorners(result.walls[1].points), sortedCorners(square(750, 750, 18'500)));
    EXPECT_EQ(sortedCorners(result.walls[2].points), sortedCorners(square(1'250, 1'250, 17'500)));
    EXPECT_EQ(result.walls[2].width_um, 500);
    ASSERT_EQ(result.inner_area.size(), 1U);
    EXPECT_EQ(sortedCorners(result.inner_area[0]), sortedCorners(square(1'500, 1'500, 17'000)));
}

TEST(Walls, NoWallsLeaveTheOutline) {
    WallParams p;
    p.wall_count = 0;
    const Paths outline{square(0, 0, 5'000)};
    const WallResult result = generateWalls(outline, p);
    EXPECT_TRUE(result.walls.empty());
    EXPECT_EQ(result.inner_area, outline);
}

TEST(Walls, SquareWithHoleGetsLoopsAroundBoth) {
    Path hole = square(5'000, 5'000, 10'000);
    std::reverse(hole.begin(), hole.end());  // clockwise
    const WallResult result = generateWalls({square(0, 0, 20'000), hole}, WallParams{});
    ASSERT_EQ(result.walls.size(), 4U);
    EXPECT_EQ(std::count_if(result.walls.begin(), result.walls.end(),
                            [](const ExtrusionPath& w) { return w.feature == Feature::WallOuter; }),
              2);
    // The hole's outer wall lies 0.2 mm outside the hole: a clockwise loop of a 10 mm square grown
    // by 0.2 mm with round corners (polygonal arcs, vertices on the arc: less area; with a 10 µm arc
    // tolerance a 0.2 mm corner gets two segments, about 11 % short of the quarter circle).
    double hole_loop = 0;
    for (const ExtrusionPath& w : result.walls) {
        if (w.feature == Feature::WallOuter && ClipperLib::Area(w.points) < 0)
            hole_loop = -ClipperLib::Area(w.points);
    }
    const double corners = std::numbers::pi * 200.0 * 200.0;
    EXPECT_LT(hole_loop, 10'000.0 * 10'000.0 + 4 * 10'000.0 * 200.0 + corners);
    EXPECT_GT(hole_loop, 10'000.0 * 10'000.0 + 4 * 10'000.0 * 200.0 + 0.85 * corners);
    // Inner area: the 18.4 mm square minus the hole grown by 0.8 mm.
    const double hole_area = 10'000.0 * 10'000.0 + 4 * 10'000.0 * 800.0 + std::numbers::pi * 800.0 * 800.0;
    EXPECT_NEAR(areaOf(result.inner_area), 18'400.0 * 18'400.0 - hole_area, 100'000.0);
}

TEST(Walls, NarrowStripsGetFewerWallsAndNoEmptyLoops) {
    struct Case {
        coord_um width;
        std::size_t max_walls;
    };
    // Outer wall needs more than 0.4 mm, the second more than 1.2 mm.
    const Case cases[] = {{300, 0}, {400, 0},   {401, 1},   {500, 1},
                          {800, 1}, {1'000, 1}, {1'200, 1}, {1'300, 2}};
    for (const Case& c : cases) {
        const Path strip{{0, 0}, {10'000, 0}, {10'000, c.width}, {0, c.width}};
        const WallResult result = generateWalls({strip}, WallParams{});
        EXPECT_LE(result.walls.size(), c.max_walls) << c.width;
        for (const ExtrusionPath& wall : result.walls) {
            EXPECT_GE(wall.points.size(), 3U) << c.width;
            EXPECT_GT(std::fabs(ClipperLib::Area(wall.points)), 0.0) << c.width;
        }
        for (const Path& area : result.inner_area)
            EXPECT_GT(std::fabs(ClipperLib::Area(area)), 0.0) << c.width;
    }
    const WallResult half_mm = generateWalls({{{0, 0}, {10'000, 0}, {10'000, 500}, {0, 500}}}, WallParams{});
    ASSERT_EQ(half_mm.walls.size(), 1U);
    EXPECT_EQ(half_mm.walls[0].feature, Feature::WallOuter);
    EXPECT_NEAR(ClipperLib::Area(half_mm.walls[0].points), 9'600.0 * 100.0, 1.0);
    EXPECT_TRUE(half_mm.inner_area.empty());
}

TEST(Walls, OffsetPolygonsGrowsWithRoundCorners) {
    const Paths grown = offsetPolygons({square(0, 0, 10'000)}, 1'000);
    ASSERT_EQ(grown.size(), 1U);
    // 10×10 square + 4 side strips + a full circle of radius 1 mm at the corners (arc tolerance 10 µm).
    const double exact = 100e6 + 4 * 10e6 + std::numbers::pi * 1e6;
    EXPECT_NEAR(ClipperLib::Area(grown[0]), exact, 0.002 * exact);
    EXPECT_LT(ClipperLib::Area(grown[0]), exact);
    EXPECT_TRUE(offsetPolygons({square(0, 0, 1'000)}, -500).empty());
}

}  // namespace
}  // namespace mixengine
