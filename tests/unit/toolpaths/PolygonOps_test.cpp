// Area helpers (geometry/PolygonOps.h) on squares and strips.
#include "geometry/PolygonOps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "ToolpathTestSupport.h"

namespace mixengine {
namespace {

using test::rect;
using test::square;

TEST(PolygonOps, BooleansOnOverlappingSquares) {
    const Paths a{square(0, 0, 10'000)};
    const Paths b{square(5'000, 0, 10'000)};
    EXPECT_EQ(areaUm2(intersectAll(a, b)), 50e6);
    EXPECT_EQ(areaUm2(differenceOf(a, b)), 50e6);
    EXPECT_EQ(areaUm2(unionOf(a, b)), 150e6);
    EXPECT_EQ(areaUm2(unionOf(Paths{square(0, 0, 10'000), square(5'000, 0, 10'000)})), 150e6);
    EXPECT_TRUE(intersectAll(a, {}).empty());
    EXPECT_EQ(areaUm2(differenceOf(a, {})), 100e6);
    EXPECT_TRUE(differenceOf({}, a).empty());
}

TEST(PolygonOps, UnionOfUnitedReturnsTheOtherAsItIsWhenOneIsEmpty) {
    // Two squares touching at a corner, each starting at a vertex a union would not start from: a
    // union pass would change the loops; with an empty operand they come back as they are.
    const Paths touching{{{10'000, 10'000}, {0, 10'000}, {0, 0}, {10'000, 0}},
                         {{20'000, 20'000}, {10'000, 20'000}, {10'000, 10'000}, {20'000, 10'000}}};
    ASSERT_NE(unionOf(touching), touching);
    EXPECT_EQ(unionOfUnited(touching, {}), touching);
    EXPECT_EQ(unionOfUnited({}, touching), touching);
    const Paths other{test::square(30'000, 0, 5'000)};
    EXPECT_EQ(unionOfUnited(touching, other), unionOf(touching, other));
}

TEST(PolygonOps, MitredOffsetKeepsSquareCornersRoundOneRoundsThem) {
    const Paths grown = offsetMiter({square(0, 0, 10'000)}, 1'000);
    ASSERT_EQ(grown.size(), 1U);
    EXPECT_EQ(areaUm2(grown), 12'000.0 * 12'000.0);
    const double round = areaUm2(offsetPolygons({square(0, 0, 10'000)}, 1'000));
    const double exact = 100e6 + 4 * 10e6 + std::numbers::pi * 1e6;
    EXPECT_LT(round, exact);
    EXPECT_GT(round, 0.998 * exact);
}

TEST(PolygonOps, OpeningDropsTheThinPartAndKeepsCorners) {
    // A 10 mm square with a 0.3 mm wide, 5 mm long spike on its right side.
    const Paths shape = unionOf({square(0, 0, 10'000)}, {rect(10'000, 4'000, 15'000, 4'300)});
    const Paths opened = openPolygons(shape, 200);
    EXPECT_EQ(areaUm2(opened), 100e6);
    const ClipperLib::IntRect box = boundsOf(opened);
    EXPECT_EQ(box.right, 10'000);
    EXPECT_EQ(box.left, 0);
    // A strip 0.5 mm wide survives an opening of radius 0.2 mm unchanged.
    EXPECT_EQ(areaUm2(openPolygons({rect(0, 0, 10'000, 500)}, 200)), 10'000.0 * 500);
}

TEST(PolygonOps, IslandsKeepTheirHoles) {
    Path hole = square(2'000, 2'000, 6'000);
    std::reverse(hole.begin(), hole.end());
    const Paths shapes{square(0, 0, 10'000), hole, square(4'000, 4'000, 2'000), square(20'000, 0, 500)};
    const std::vector<Paths> islands = splitIslands(shapes);
    ASSERT_EQ(islands.size(), 3U);
    double total = 0;
    for (const Paths& island : islands)
        total += areaUm2(island);
    EXPECT_EQ(total, 100e6 - 36e6 + 4e6 + 0.25e6);
    // Dropping islands under 1 mm²: the 0.5 mm square goes, the frame (64 mm²) and the inner 4 mm² stay.
    EXPECT_EQ(areaUm2(removeSmallIslands(shapes, 1e6)), 100e6 - 36e6 + 4e6);
    EXPECT_EQ(areaUm2(removeSmallIslands(shapes, 5e6)), 64e6);
}

TEST(PolygonOps, SmallOutlinesAreWeighedWithoutTheirHoles) {
    // As CuraEngine 4.13's removeSmallAreas (keeping holes): a 10 mm square round a hole 1 µm smaller all
    // round is a ring of under 0.04 mm², yet its outline (100 mm²) is not small, so the ring stays.
    Path ring_hole = rect(1, 1, 9'999, 9'999);
    std::reverse(ring_hole.begin(), ring_hole.end());
    // A 0.5 mm square with a 0.1 mm hole goes with its hole; a 0.1 mm hole in a 5 mm square stays.
    Path small_hole = square(20'200, 200, 100);
    std::reverse(small_hole.begin(), small_hole.end());
    Path kept_hole = square(30'200, 200, 100);
    std::reverse(kept_hole.begin(), kept_hole.end());
    const Paths shapes{square(0, 0, 10'000),     ring_hole, square(20'000, 0, 500), small_hole,
                       square(30'000, 0, 5'000), kept_hole};
    const Paths kept = removeSmallOutlines(shapes, 1e6);
    ASSERT_EQ(kept.size(), 4U);
    EXPECT_EQ(kept[0], shapes[0]);
    EXPECT_EQ(kept[1], shapes[1]);
    EXPECT_EQ(kept[2], shapes[4]);
    EXPECT_EQ(kept[3], shapes[5]);
    EXPECT_EQ(areaUm2(kept), 100e6 - 9'998.0 * 9'998.0 + 25e6 - 1e4);
    // Weighed as islands (holes taken off), the ring goes.
    EXPECT_EQ(areaUm2(removeSmallIslands(shapes, 1e6)), 25e6 - 1e4);
}

TEST(PolygonOps, ClipLinesKeepsTheInsidePieces) {
    const Paths pieces = clipLines({{{-5'000, 5'000}, {15'000, 5'000}}}, {square(0, 0, 10'000)});
    ASSERT_EQ(pieces.size(), 1U);
    EXPECT_EQ(std::min(pieces[0][0].X, pieces[0][1].X), 0);
    EXPECT_EQ(std::max(pieces[0][0].X, pieces[0][1].X), 10'000);
}

/// Clipper's own answer: the bounds of the edges it builds from the loops.
ClipperLib::IntRect clipperBounds(const Paths& loops) {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(loops, ClipperLib::ptSubject, true);
    return clipper.GetBounds();
}

void expectSameBounds(const Paths& loops) {
    const ClipperLib::IntRect ours = boundsOf(loops), theirs = clipperBounds(loops);
    EXPECT_EQ(ours.left, theirs.left);
    EXPECT_EQ(ours.top, theirs.top);
    EXPECT_EQ(ours.right, theirs.right);
    EXPECT_EQ(ours.bottom, theirs.bottom);
}

TEST(PolygonOps, BoundsAreClippersBoundsAlsoForSpikesLinesAndRepeats) {
    const Path spike{{0, 0},       {1'000, 0},     {1'000, 500}, {3'000, 500},
                     {1'000, 500}, {1'000, 1'000}, {0, 1'000}};
    const Path line{{0, 0}, {2'000, 2'000}, {5'000, 5'000}};  // no area: Clipper leaves it out
    const Path repeated{{-700, 0}, {0, 0}, {0, 0}, {0, -900}, {-700, -900}};
    const Path collinear{{0, 0}, {500, 0}, {1'000, 0}, {1'000, 800}, {0, 800}};
    expectSameBounds({spike});
    EXPECT_EQ(boundsOf({spike}).right, 1'000);  // the spike's tip is not an edge Clipper keeps
    expectSameBounds({line});
    EXPECT_EQ(boundsOf({line}).right, 0);  // nothing left: all zero, as for no loops at all
    expectSameBounds({repeated});
    expectSameBounds({collinear});
    expectSameBounds({line, square(3'000, 3'000, 1'000), repeated});
    expectSameBounds({});
}

TEST(PolygonOps, LengthOfOpenAndClosedPaths) {
    const Path sq = square(0, 0, 1'000);
    EXPECT_EQ(lengthUm(sq, true), 4'000.0);
    EXPECT_EQ(lengthUm(sq, false), 3'000.0);
}

}  // namespace
}  // namespace mixengine
