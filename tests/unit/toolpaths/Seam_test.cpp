// Seam placement (toolpaths/walls/Seam.h): which vertex a wall loop starts at.
#include "toolpaths/walls/Seam.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "common/Error.h"

#include "ToolpathTestSupport.h"

namespace mixengine {
namespace {

using test::square;

/// An L-shaped outline (counter-clockwise) whose only concave corner is at (10, 10) mm.
Path lShape() {
    return {{0, 0}, {20'000, 0}, {20'000, 10'000}, {10'000, 10'000}, {10'000, 20'000}, {0, 20'000}};
}

Path circle(int segments, coord_um r, const Point2& centre = {0, 0}) {
    Path c;
    for (int i = 0; i < segments; ++i) {
        const double a = 2 * std::numbers::pi * i / segments;
        c.push_back({centre.X + std::llround(r * std::cos(a)), centre.Y + std::llround(r * std::sin(a))});
    }
    return c;
}

ExtrusionPath loop(const Path& points) {
    ExtrusionPath p;
    p.points = points;
    p.closed = true;
    return p;
}

TEST(Seam, BackPicksTheVertexNearestToThePoint) {
    SeamParams p;
    p.type = SeamType::Back;
    p.position_um = {100'000, 200'000};  // far behind, to the right
    const Path sq = square(0, 0, 10'000);
    EXPECT_EQ(sq[seamVertex(sq, p, 0)], (Point2{10'000, 10'000}));
    p.position_um = {-50'000, 200'000};
    EXPECT_EQ(sq[seamVertex(sq, p, 0)], (Point2{0, 10'000}));
}

TEST(Seam, BackIsDrawnToCornersOfThePreferredKindAsInCuraEngine) {
    // From (15.05, 10) mm the convex corner (20, 10) is nearest (4.95 mm), the concave corner (10, 10)
    // a little farther (5.05 mm): a corner of the preferred kind takes a tenth off its squared
    // distance per unit of bend (0.5 for a right angle, doubled for concave corners when weighted).
    SeamParams p;
    p.type = SeamType::Back;
    p.position_um = {15'050, 10'000};
    const Path l = lShape();
    p.corner = SeamCorner::None;
    EXPECT_EQ(l[seamVertex(l, p, 0)], (Point2{20'000, 10'000}));
    p.corner = SeamCorner::Inner;
    EXPECT_EQ(l[seamVertex(l, p, 0)], (Point2{10'000, 10'000}));
    p.corner = SeamCorner::Outer;
    EXPECT_EQ(l[seamVertex(l, p, 0)], (Point2{20'000, 10'000}));
    p.corner = SeamCorner::Weighted;
    EXPECT_EQ(l[seamVertex(l, p, 0)], (Point2{10'000, 10'000}));
}

TEST(Seam, BackTiesFarFromTheSeamPointGoToTheFirstVertexMet) {
    // The two back corners are equally far from a point straight behind the middle; at ~90 mm the
    // single-precision scores cannot hold CuraEngine's 25 µm² margin, so the first vertex met (the
    // first of the nearest in the loop's order) stays.
    SeamParams p;
    p.type = SeamType::Back;
    p.corner = SeamCorner::Weighted;
    p.position_um = {5'000, 100'000};
    const Path sq = square(0, 0, 10'000);
    ASSERT_EQ(sq[2], (Point2{10'000, 10'000}));
    EXPECT_EQ(sq[seamVertex(sq, p, 0)], (Point2{10'000, 10'000}));
    Path rotated = sq;
    std::rotate(rotated.begin(), rotated.begin() + 3, rotated.end());  // (0, 10) mm first
    EXPECT_EQ(rotated[seamVertex(rotated, p, 0)], (Point2{0, 10'000}));
}

TEST(Seam, BackTiesNearTheSeamPointGoToTheLastVertexMet) {
    // 0.1 mm behind the middle of the back edge both back corners score 25 mm² + 0.01 mm²: the
    // search starts at the first of them and the other, met next, is within 25 µm² and wins.
    SeamParams p;
    p.type = SeamType::Back;
    p.corner = SeamCorner::Weighted;
    p.position_um = {5'000, 10'100};
    const Path sq = square(0, 0, 10'000);
    EXPECT_EQ(sq[seamVertex(sq, p, 0)], (Point2{0, 10'000}));
}

TEST(Seam, PlaceSeamsRotatesTheLoopAndFixesItsStart) {
    SeamParams p;
    p.type = SeamType::Back;
    p.position_um = {0, -100'000};  // in front
    std::vector<ExtrusionPath> paths{loop(square(0, 0, 10'000)), ExtrusionPath{}};
    paths[1].points = {{0, 0}, {5'000, 0}};  // an open line is left alone
    placeSeams(paths, p, 3);
    EXPECT_TRUE(paths[0].fixed_start);
    EXPECT_EQ(paths[0].points, (Path{{0, 0}, {10'000, 0}, {10'000, 10'000}, {0, 10'000}}));
    EXPECT_FALSE(paths[1].fixed_start);
}

TEST(Seam, InnerWallsStartNearestToTheirOuterWallsSeam) {
    // As CuraEngine 4.13 starts a part's inner walls: at the vertex nearest to the outer wall's seam,
    // corners aside: the inner L's concave corner, nearest to the seam point, is not taken.
    SeamParams p;
    p.type = SeamType::Back;
    p.corner = SeamCorner::Inner;
    p.position_um = {12'000, 9'000};
    std::vector<ExtrusionPath> paths{loop(square(-400, -400, 20'800)), loop(lShape())};
    paths[0].feature = Feature::WallOuter;
    paths[1].feature = Feature::WallInner;
    placeSeams(paths, p, 0);
    EXPECT_EQ(paths[0].points.front(), (Point2{20'400, -400}));
    EXPECT_EQ(paths[1].points.front(), (Point2{20'000, 0}));
    EXPECT_TRUE(paths[1].fixed_start);
}

TEST(Seam, ShortestLeavesTheStartToThePlanner) {
    SeamParams p;
    p.type = SeamType::Shortest;
    std::vector<ExtrusionPath> paths{loop(square(0, 0, 10'000))};
    placeSeams(paths, p, 0);
    EXPECT_FALSE(paths[0].fixed_start);
    EXPECT_EQ(paths[0].points, square(0, 0, 10'000));
}

TEST(Seam, SharpestCornerPrefersTheConcaveCornerWhenHidingInside) {
    SeamParams p;
    p.type = SeamType::SharpestCorner;
    p.corner = SeamCorner::Inner;
    const Path l = lShape();
    EXPECT_EQ(l[seamVertex(l, p, 0)], (Point2{10'000, 10'000}));
    // Outer corners only: the five convex corners tie, the back-most (then rightmost) wins.
    p.corner = SeamCorner::Outer;
    EXPECT_EQ(l[seamVertex(l, p, 0)], (Point2{10'000, 20'000}));
}

TEST(Seam, SharpestCornerTiesGoToTheLastVertexMetFromTheBack) {
    // A circle has no concave corner: every vertex scores alike, the search starts at the back-most
    // vertex and the last one met — the one before it in the loop's order — wins, as CuraEngine
    // puts it on a cylinder (on the plate: far below it the squared distances to the point far
    // behind overflow as CuraEngine's do).
    SeamParams p;
    p.type = SeamType::SharpestCorner;
    const Path c = circle(100, 10'000, {100'000, 100'000});
    ASSERT_EQ(c[25], (Point2{100'000, 110'000}));
    EXPECT_EQ(seamVertex(c, p, 0), 24U);
}

TEST(Seam, SharpestCornerWithoutPreferenceLeavesTheStartToThePlanner) {
    SeamParams p;
    p.type = SeamType::SharpestCorner;
    p.corner = SeamCorner::None;
    std::vector<ExtrusionPath> paths{loop(lShape())};
    placeSeams(paths, p, 0);
    EXPECT_FALSE(paths[0].fixed_start);
}

TEST(Seam, RandomIsReproducibleAndVaries) {
    SeamParams p;
    p.type = SeamType::Random;
    const Path c = circle(64, 10'000);
    EXPECT_EQ(seamVertex(c, p, 7), seamVertex(c, p, 7));
    std::set<std::size_t> seen;
    for (std::uint64_t seed = 0; seed < 20; ++seed)
        seen.insert(seamVertex(c, p, seed));
    EXPECT_GT(seen.size(), 10U);
}

TEST(Seam, SettingsWithRelativePosition) {
    const Settings s("mesh", {{"z_seam_type", "back"},
                              {"z_seam_corner", "z_seam_corner_none"},
                              {"z_seam_x", "10"},
                              {"z_seam_y", "-5"},
                              {"z_seam_relative", "True"},
                              {"wall_line_width_0", "0.4"}});
    const SeamParams p = seamParamsFrom(s, {100'000, 100'000});
    EXPECT_EQ(p.type, SeamType::Back);
    EXPECT_EQ(p.corner, SeamCorner::None);
    EXPECT_EQ(p.position_um, (Point2{110'000, 95'000}));
    EXPECT_THROW(seamParamsFrom(Settings("mesh", {{"z_seam_type", "front"}}), {0, 0}), InputError);
}

}  // namespace
}  // namespace mixengine
