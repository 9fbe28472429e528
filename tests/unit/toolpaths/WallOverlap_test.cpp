// Overlap compensation of walls (toolpaths/walls/WallOverlap.h): the second pass over a line printed
// closer than a line width loses the overlapping share of its flow.
#include "toolpaths/walls/WallOverlap.h"

#include <gtest/gtest.h>

#include <vector>

namespace mixengine {
namespace {

ExtrusionPath loop(Path points, double flow = 1.0) {
    ExtrusionPath p;
    p.points = std::move(points);
    p.closed = true;
    p.width_um = 400;
    p.flow = flow;
    p.feature = Feature::WallOuter;
    return p;
}

TEST(WallOverlap, AThinLoopPrintsItsWayBackAtTheShareNotYetCovered) {
    // A 0.6 mm fin's outer wall with 0.4 mm lines: its centre line is a loop 0.2 mm wide. The way
    // back runs 200 µm from the way out: the two overlap by 200 of 400 µm, so it gets half the flow.
    std::vector<ExtrusionPath> walls{loop({{0, 0}, {7'600, 0}, {7'600, 200}, {0, 200}}, 0.9)};
    compensateWallOverlaps(walls, Feature::WallOuter, {400, 0.0});
    EXPECT_EQ(walls[0].points, (Path{{0, 0}, {7'600, 0}, {7'600, 200}, {0, 200}}));
    // flows[k]: the line ending at points[k]; flows[0] the closing line (200 µm, at full flow)
    ASSERT_EQ(walls[0].flows.size(), 4U);
    EXPECT_DOUBLE_EQ(walls[0].flows[0], 0.9);
    EXPECT_DOUBLE_EQ(walls[0].flows[1], 0.9);
    EXPECT_DOUBLE_EQ(walls[0].flows[2], 0.9);
    EXPECT_DOUBLE_EQ(walls[0].flows[3], 0.45);
}

TEST(WallOverlap, ALineIsSplitWhereTheOverlapEnds) {
    // The top of a 10 x 1 mm loop, printed first, runs back at y = 1000; a second loop's bottom runs
    // forward at y = 1300 from x = 5 to 15 mm: 100 µm of 400 overlap over x = 5..10 mm only. Its left
    // side comes down across the first loop's top to 300 µm from it: over its last 100 µm the overlap
    // grows from 0 to 100 µm (area 100 × 100 / 2 of 100 × 400: 7/8 of the flow).
    std::vector<ExtrusionPath> walls{
        loop({{0, 0}, {10'000, 0}, {10'000, 1'000}, {0, 1'000}}),
        loop({{5'000, 1'300}, {15'000, 1'300}, {15'000, 3'000}, {5'000, 3'000}})};
    compensateWallOverlaps(walls, Feature::WallOuter, {400, 0.0});
    EXPECT_EQ(walls[0].flows, (std::vector<double>{1.0, 1.0, 1.0, 1.0}));  // printed first: in full
    EXPECT_EQ(walls[1].points, (Path{{5'000, 1'300},
                                     {10'000, 1'300},
                                     {15'000, 1'300},
                                     {15'000, 3'000},
                                     {5'000, 3'000},
                                     {5'000, 1'400}}));
    EXPECT_EQ(walls[1].flows, (std::vector<double>{0.875, 0.75, 1.0, 1.0, 1.0, 1.0}));
}

TEST(WallOverlap, WallsApartKeepTheirFlowAndTheirPoints) {
    // Lines 400 µm apart or more do not overlap; a square's sides meet only their neighbours.
    std::vector<ExtrusionPath> walls{loop({{0, 0}, {7'600, 0}, {7'600, 400}, {0, 400}}),
                                     loop({{0, 1'000}, {20'000, 1'000}, {20'000, 21'000}, {0, 21'000}})};
    compensateWallOverlaps(walls, Feature::WallOuter, {400, 0.0});
    EXPECT_TRUE(walls[0].flows.empty());
    EXPECT_TRUE(walls[1].flows.empty());
    EXPECT_EQ(walls[0].points.size(), 4U);
}

TEST(WallOverlap, BelowTheMinimumFlowALineIsNotExtruded) {
    // wall_min_flow 60 %: the way back at 50 % becomes a move; other features are left alone.
    std::vector<ExtrusionPath> walls{loop({{0, 0}, {7'600, 0}, {7'600, 200}, {0, 200}})};
    ExtrusionPath inner = loop({{0, 0}, {7'600, 0}, {7'600, 200}, {0, 200}});
    inner.feature = Feature::WallInner;
    walls.push_back(inner);
    compensateWallOverlaps(walls, Feature::WallOuter, {400, 0.6});
    ASSERT_EQ(walls[0].flows.size(), 4U);
    EXPECT_DOUBLE_EQ(walls[0].flows[3], 0.0);
    EXPECT_DOUBLE_EQ(walls[0].flows[1], 1.0);
    EXPECT_TRUE(walls[1].flows.empty());
}

}  // namespace
}  // namespace mixengine
