// Wall generation (toolpaths/walls/Walls.h): concentric insets with exact geometry on squares, thin
// parts, holes and the skin reference regions.
#include "toolpaths/walls/Walls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::rect;
using test::square;

/// The corners of an axis-aligned square loop, sorted, for exact comparison.
Path sortedCorners(Path p) {
    std::sort(p.begin(), p.end(),
              [](const Point2& a, const Point2& b) { return a.X != b.X ? a.X < b.X : a.Y < b.Y; });
    return p;
}

TEST(Walls, TwentyMillimetreSquareTwoWalls) {
    WallParams p;
    p.outer_flow = 0.9;
    p.inner_extruder = 1;
    const WallResult result = generateWalls({square(0, 0, 20'000)}, p);
    ASSERT_EQ(result.walls.size(), 2U);
    const ExtrusionPath& outer = result.walls[0];
    const ExtrusionPath& inner = result.walls[1];
    EXPECT_EQ(outer.feature, Feature::WallOuter);
    EXPECT_EQ(inner.feature, Feature::WallInner);
    EXPECT_TRUE(outer.closed && inner.closed);
    EXPECT_EQ(outer.width_um, 400);
    EXPECT_EQ(outer.speed_mm_s, 30.0);
    EXPECT_EQ(inner.speed_mm_s, 60.0);
    EXPECT_EQ(outer.flow, 0.9);
    EXPECT_EQ(inner.flow, 1.0);
    EXPECT_EQ(outer.extruder, 0);
    EXPECT_EQ(inner.extruder, 1);
    EXPECT_EQ(sortedCorners(outer.points), sortedCorners(square(200, 200, 19'600)));
    EXPECT_EQ(sortedCorners(inner.points), sortedCorners(square(600, 600, 18'800)));
    ASSERT_EQ(result.inner_area.size(), 1U);
    EXPECT_EQ(sortedCorners(result.inner_area[0]), sortedCorners(square(800, 800, 18'400)));
}

TEST(Walls, OuterInsetMovesOnlyTheOuterWall) {
    // As CuraEngine 4.13 (checked against its G-code): outer wall at 0.2 + 0.1 mm, first inner wall at
    // 0.4 + 0.25 mm from the outline whatever the inset, then one 0.5 mm width further each.
    WallParams p;
    p.wall_count = 3;
    p.inner_width_um = 500;
    p.outer_inset_um = 100;
    const WallResult result = generateWalls({square(0, 0, 20'000)}, p);
    ASSERT_EQ(result.walls.size(), 3U);
    EXPECT_EQ(sortedCorners(result.walls[0].points), sortedCorners(square(300, 300, 19'400)));
    EXPECT_EQ(sortedCorners(result.walls[1].points), sortedCorners(square(650, 650, 18'700)));
    EXPECT_EQ(sortedCorners(result.walls[2].points), sortedCorners(square(1'150, 1'150, 17'700)));
    EXPECT_EQ(result.walls[2].width_um, 500);
    ASSERT_EQ(result.inner_area.size(), 1U);
    EXPECT_EQ(sortedCorners(result.inner_area[0]), sortedCorners(square(1'400, 1'400, 17'200)));
}

TEST(Walls, NoWallsLeaveTheOutlineUnited) {
    WallParams p;
    p.wall_count = 0;
    // Two overlapping squares: the inner area and the references are their union (WallResult).
    const Paths outline{square(0, 0, 5'000), square(3'000, 0, 5'000)};
    const WallResult result = generateWalls(outline, p);
    EXPECT_TRUE(result.walls.empty());
    ASSERT_EQ(result.inner_area.size(), 1U);
    EXPECT_EQ(areaUm2(result.inner_area), 8'000.0 * 5'000.0);
    EXPECT_EQ(result.top_reference, result.inner_area);
}

TEST(Walls, SquareWithHoleGetsLoopsAroundBoth) {
    Path hole = square(5'000, 5'000, 10'000);
    std::reverse(hole.begin(), hole.end());  // clockwise
    const WallResult result = generateWalls({square(0, 0, 20'000), hole}, WallParams{});
    ASSERT_EQ(result.walls.size(), 4U);
    int outer_loops = 0;
    for (const ExtrusionPath& w : result.walls) {
        if (w.feature != Feature::WallOuter)
            continue;
        ++outer_loops;
        if (ClipperLib::Area(w.points) < 0) {  // the hole's loop: 0.2 mm outside the hole, sharp corners
            EXPECT_EQ(sortedCorners(w.points), sortedCorners(square(4'800, 4'800, 10'400)));
        }
    }
    EXPECT_EQ(outer_loops, 2);
    // Inner area: the 18.4 mm square minus the hole grown by 0.8 mm.
    EXPECT_EQ(areaUm2(result.inner_area), 18'400.0 * 18'400.0 - 11'600.0 * 11'600.0);
}

TEST(Walls, GroupedByOutlineEachHoleAndOutlineIsOneSequence) {
    // Two holes in a 40 mm square, three walls: each hole's three loops share a sequence with the
    // hole's outer wall, the outline's with the outline's; inner loops are listed innermost first.
    Path left = square(5'000, 5'000, 10'000), right = square(25'000, 5'000, 10'000);
    std::reverse(left.begin(), left.end());
    std::reverse(right.begin(), right.end());
    WallParams p;
    p.wall_count = 3;
    p.group_by_outline = true;
    const WallResult result = generateWalls({square(0, 0, 40'000), left, right}, p);
    ASSERT_EQ(result.walls.size(), 9U);
    std::map<std::uint32_t, std::vector<const ExtrusionPath*>> by_sequence;
    for (const ExtrusionPath& w : result.walls)
        by_sequence[w.sequence].push_back(&w);
    ASSERT_EQ(by_sequence.size(), 3U);
    EXPECT_EQ(by_sequence.count(0), 0U);
    for (const auto& [sequence, loops] : by_sequence) {
        ASSERT_EQ(loops.size(), 3U) << sequence;
        EXPECT_EQ(loops[0]->feature, Feature::WallOuter);
        const ClipperLib::IntRect outer = boundsOf({loops[0]->points});
        const ClipperLib::IntRect deepest = boundsOf({loops[1]->points});
        const ClipperLib::IntRect middle = boundsOf({loops[2]->points});
        const bool hole = ClipperLib::Area(loops[0]->points) < 0;
        // Walls of a hole grow outwards, those of the outline shrink inwards.
        EXPECT_EQ(deepest.right - deepest.left > middle.right - middle.left, hole) << sequence;
        EXPECT_EQ(middle.right - middle.left > outer.right - outer.left, hole) << sequence;
    }
    // Outer walls first in the list, then the inner ones level by level from the innermost.
    EXPECT_EQ(result.walls[0].feature, Feature::WallOuter);
    EXPECT_EQ(result.walls[3].feature, Feature::WallInner);
    p.outer_first = true;  // the inner ones from the outermost in
    const WallResult outer_first = generateWalls({square(0, 0, 40'000), left, right}, p);
    EXPECT_EQ(boundsOf({outer_first.walls[3].points}).left, 600);  // the outline's first inner wall
    p.group_by_outline = false;
    for (const ExtrusionPath& w : generateWalls({square(0, 0, 40'000), left, right}, p).walls)
        EXPECT_EQ(w.sequence, 0U);
    p.group_by_outline = true;  // too thin for any wall
    EXPECT_TRUE(generateWalls({rect(0, 0, 10'000, 300)}, p).walls.empty());
}

TEST(Walls, PerimeterGapsWhereTheNextWallIsMissing) {
    // Walls touch where they all exist: a 20 mm square has no gaps.
    WallParams p;
    p.perimeter_gaps = true;
    EXPECT_TRUE(generateWalls({square(0, 0, 20'000)}, p).perimeter_gaps.empty());
    // A 1.0 mm strip holds the outer wall (centre region 0.6 mm wide) but no inner wall: what the
    // outer wall leaves, 0.6 − 2 × (0.2 mm + 15 µm) = 0.17 mm across, is a gap (3.3 mm², over the
    // filter's two outer wall widths squared).
    const WallResult strip = generateWalls({rect(0, 0, 20'000, 1'000)}, p);
    const ClipperLib::IntRect box = boundsOf(strip.perimeter_gaps);
    EXPECT_EQ(box.top, 415);
    EXPECT_EQ(box.bottom, 585);
    EXPECT_NEAR(areaUm2(strip.perimeter_gaps), 19'170.0 * 170.0, 1e3);  // 0.415 mm in from each end
    // A 1.4 mm strip holds both walls, the inner one overlapping itself: no gap between them.
    EXPECT_TRUE(generateWalls({rect(0, 0, 20'000, 1'400)}, p).perimeter_gaps.empty());
    p.perimeter_gaps = false;
    EXPECT_TRUE(generateWalls({rect(0, 0, 20'000, 1'000)}, p).perimeter_gaps.empty());
}

TEST(Walls, ThinPartsGetFewerWallsAsCuraEngine) {
    // As CuraEngine 4.13, each wall's centre region is a plain inset of the previous one: a part
    // keeps its outer wall while it is wider than one line (0.4 mm; narrower than two lines the
    // loop overlaps itself), its second wall while wider than 0.4 + 2 × 0.4 mm, and has room
    // inside the walls once wider than 1.6 mm.
    struct Case {
        coord_um width;
        std::size_t walls;
        bool inner_area;
    };
    const Case cases[] = {{300, 0, false},   {400, 0, false},   {500, 1, false},   {700, 1, false},
                          {1'200, 1, false}, {1'300, 2, false}, {1'600, 2, false}, {1'700, 2, true}};
    for (const Case& c : cases) {
        const WallResult result = generateWalls({rect(0, 0, 10'000, c.width)}, WallParams{});
        EXPECT_EQ(result.walls.size(), c.walls) << c.width;
        if (!result.walls.empty()) {  // the outer wall's centre line lies half a line inside
            const ClipperLib::IntRect box = boundsOf({result.walls[0].points});
            EXPECT_EQ(box.top, 200) << c.width;
            EXPECT_EQ(box.bottom, c.width - 200) << c.width;
        }
        EXPECT_EQ(!result.inner_area.empty(), c.inner_area) << c.width;
    }
}

TEST(Walls, ThinSpikeKeepsItsOuterWall) {
    // A 10 mm square with a 0.6 mm wide spike: the outer wall runs out along the spike (its centre
    // region there is 0.2 mm wide), the inner wall stays in the square.
    const Paths shape = unionOf({square(0, 0, 10'000)}, {rect(10'000, 4'000, 14'000, 4'600)});
    const WallResult result = generateWalls(shape, WallParams{});
    ASSERT_EQ(result.walls.size(), 2U);
    EXPECT_EQ(boundsOf({result.walls[0].points}).right, 13'800);
    EXPECT_EQ(sortedCorners(result.walls[1].points), sortedCorners(square(600, 600, 8'800)));
}

TEST(Walls, InsetsAreSimplifiedBeforeTheNextIsTaken) {
    // meshfix_maximum_resolution / _deviation act on each wall's centre region: a 20 µm notch in
    // the outline survives the plain inset but not a 0.25 mm / 25 µm simplification.
    const Path notched{{0, 0},      {5'000, 0},       {5'100, 20}, {5'200, 0},
                       {10'000, 0}, {10'000, 10'000}, {0, 10'000}};
    WallParams p;
    auto notchTops = [](const ExtrusionPath& wall) {  // vertices on the notch, off the straight edge
        return std::count_if(wall.points.begin(), wall.points.end(),
                             [](const Point2& v) { return v.Y > 200 && v.Y < 250; });
    };
    const WallResult plain = generateWalls({notched}, p);
    EXPECT_EQ(notchTops(plain.walls[0]), 1);
    EXPECT_EQ(plain.walls[0].points.size(), 7U);
    p.simplify_resolution_um = 250;
    p.simplify_deviation_um = 25;
    const WallResult simple = generateWalls({notched}, p);
    EXPECT_EQ(notchTops(simple.walls[0]), 0);
    EXPECT_LT(simple.walls[0].points.size(), 7U);
    EXPECT_EQ(sortedCorners(simple.walls[1].points), sortedCorners(square(600, 600, 8'800)));
}

TEST(Walls, ReferenceRegionsForTheSkin) {
    WallParams p;
    p.wall_count = 3;
    p.top_reference = 0;     // the outline
    p.bottom_reference = 2;  // the first inner wall's centre region
    const WallResult result = generateWalls({square(0, 0, 20'000)}, p);
    EXPECT_EQ(areaUm2(result.top_reference), 400e6);
    EXPECT_EQ(areaUm2(result.bottom_reference), 18'800.0 * 18'800.0);
    // A part too thin for the second wall uses its outer wall's region instead.
    const Paths two_parts{square(0, 0, 20'000), rect(30'000, 0, 31'000, 10'000)};
    const WallResult mixed = generateWalls(two_parts, p);
    EXPECT_EQ(areaUm2(mixed.bottom_reference), 18'800.0 * 18'800.0 + 600.0 * 9'600.0);
}

}  // namespace
}  // namespace mixengine
