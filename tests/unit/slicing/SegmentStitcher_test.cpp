#include "slicing/SegmentStitcher.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "slicing/GapCloser.h"

namespace mixengine {
namespace {

/// The segments of a CCW square [x0, x0 + side]² with `per_side` pieces on each side.
std::vector<FacetSegment> squareSegments(coord_um x0, coord_um side, int per_side) {
    const Path corners{{x0, x0}, {x0 + side, x0}, {x0 + side, x0 + side}, {x0, x0 + side}};
    std::vector<FacetSegment> out;
    for (std::size_t c = 0; c < 4; ++c) {
        const Point2 a = corners[c];
        const Point2 b = corners[(c + 1) % 4];
        for (int k = 0; k < per_side; ++k) {
            out.push_back({{a.X + (b.X - a.X) * k / per_side, a.Y + (b.Y - a.Y) * k / per_side},
                           {a.X + (b.X - a.X) * (k + 1) / per_side, a.Y + (b.Y - a.Y) * (k + 1) / per_side}});
        }
    }
    return out;
}

TEST(StitchSegments, ShuffledSquareBecomesOneLoop) {
    std::vector<FacetSegment> segments = squareSegments(0, 1000, 5);
    std::shuffle(segments.begin(), segments.end(), std::mt19937(7));
    SegmentStitcher stitcher;
    const StitchResult result = stitcher.stitch(segments, 100);
    ASSERT_EQ(result.loops.size(), 1U);
    EXPECT_TRUE(result.open_polylines.empty());
    EXPECT_EQ(result.loops[0].points.size(), 20U);
    EXPECT_DOUBLE_EQ(std::abs(ClipperLib::Area(result.loops[0].points)), 1e6);
    EXPECT_DOUBLE_EQ(result.loops[0].along_facets_um + result.loops[0].against_facets_um, 4000.0);
}

TEST(StitchSegments, ReversedSegmentsStillChainAndAreCounted) {
    std::vector<FacetSegment> segments = squareSegments(0, 1000, 2);
    std::swap(segments[3].from, segments[3].to);  // one inconsistently wound facet
    SegmentStitcher stitcher;
    const StitchResult result = stitcher.stitch(segments, 0);
    ASSERT_EQ(result.loops.size(), 1U);
    const StitchedPath& loop = result.loops[0];
    EXPECT_EQ(loop.points.size(), 8U);
    EXPECT_DOUBLE_EQ(std::min(loop.along_facets_um, loop.against_facets_um), 500.0);
}

TEST(StitchSegments, TouchingSquaresSeparateAtTheSharedCorner) {
    std::vector<FacetSegment> segments = squareSegments(0, 1000, 1);
    const std::vector<FacetSegment> second = squareSegments(1000, 1000, 1);
    segments.insert(segments.end(), second.begin(), second.end());
    SegmentStitcher stitcher;
    const StitchResult result = stitcher.stitch(segments, 0);
    ASSERT_EQ(result.loops.size(), 2U);
    for (const StitchedPath& loop : result.loops) {
        EXPECT_EQ(loop.points.size(), 4U);
        EXPECT_DOUBLE_EQ(ClipperLib::Area(loop.points), 1e6);
        EXPECT_DOUBLE_EQ(loop.against_facets_um, 0.0);
    }
}

TEST(StitchSegments, SmallGapIsClosedLargeGapStaysOpen) {
    std::vector<FacetSegment> segments = squareSegments(0, 1000, 4);
    segments[5].to.Y -= 60;  // shortens a segment: a 60 µm gap
    SegmentStitcher stitcher;
    const StitchResult closed = stitcher.stitch(segments, 100);
    ASSERT_EQ(closed.loops.size(), 1U);
    EXPECT_TRUE(closed.open_polylines.empty());
    EXPECT_EQ(closed.loops[0].points.size(), 17U);

    const StitchResult open = stitcher.stitch(segments, 50);
    EXPECT_TRUE(open.loops.empty());
    ASSERT_EQ(open.open_polylines.size(), 1U);
    EXPECT_EQ(open.open_polylines[0].size(), 17U);  // every segment is in the one open chain
}

TEST(StitchSegments, ZeroLengthSegmentsAreIgnored) {
    std::vector<FacetSegment> segments = squareSegments(0, 1000, 1);
    segments.push_back({{500, 500}, {500, 500}});
    segments.push_back({{0, 0}, {0, 0}});
    SegmentStitcher stitcher;
    const StitchResult result = stitcher.stitch(segments, 0);
    ASSERT_EQ(result.loops.size(), 1U);
    EXPECT_EQ(result.loops[0].points.size(), 4U);
    EXPECT_TRUE(result.open_polylines.empty());
}

TEST(StitchGaps, JoinsPiecesNearestFirstAndReversesWhereNeeded) {
    // Two halves of a square; the second is stored backwards.
    std::vector<StitchedPath> pieces{
        {{{0, 0}, {1000, 0}, {1000, 1000}}, 2000, 0},
        {{{-30, 20}, {0, 1000}, {1000, 1040}}, 0, 2000},
    };
    std::vector<StitchedPath> loops;
    closeGaps(pieces, 100, loops);
    EXPECT_TRUE(pieces.empty());
    ASSERT_EQ(loops.size(), 1U);
    EXPECT_EQ(loops[0].points.size(), 6U);
    EXPECT_DOUBLE_EQ(loops[0].along_facets_um, 4000.0);
    EXPECT_DOUBLE_EQ(loops[0].against_facets_um, 0.0);
}

TEST(StitchGaps, LeavesFarEndsOpenButJoinsNearOnes) {
    std::vector<StitchedPath> pieces{
        {{{0, 0}, {1000, 0}}, 1000, 0},
        {{{1010, 0}, {2000, 0}}, 990, 0},
        {{{5000, 0}, {6000, 0}}, 1000, 0},
    };
    std::vector<StitchedPath> loops;
    closeGaps(pieces, 100, loops);
    EXPECT_TRUE(loops.empty());
    ASSERT_EQ(pieces.size(), 2U);
    EXPECT_EQ(pieces[0].points, (Path{{0, 0}, {1000, 0}, {1010, 0}, {2000, 0}}));
}

}  // namespace
}  // namespace mixengine
