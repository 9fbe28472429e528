// Bridged walls (toolpaths/walls/BridgeWalls.h): the air mask and the wall split where it crosses air.
#include "toolpaths/walls/BridgeWalls.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

Path box(coord_um x0, coord_um y0, coord_um x1, coord_um y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

BridgeWallParams params(coord_um min_length) {
    BridgeWallParams p;
    p.enabled = true;
    p.outer_width_um = 400;
    p.min_length_um = min_length;
    p.style = {12.5, 0.5, 1.0, 1.0};
    return p;
}

TEST(BridgeWalls, TheMaskIsTheAirUnderTheOutlineGrownToTheWallLine) {
    const Paths mask = bridgeWallMask({box(0, 0, 30'000, 10'000)},
                                      {box(0, 0, 5'000, 10'000), box(25'000, 0, 30'000, 10'000)}, 400);
    ASSERT_EQ(mask.size(), 1U);
    const ClipperLib::IntRect b{4'800, -200, 25'200, 10'200};  // the gap, grown by half a line
    ClipperLib::IntRect got{INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
    for (const Point2& p : mask[0])
        got = {std::min(got.left, p.X), std::min(got.top, p.Y), std::max(got.right, p.X),
               std::max(got.bottom, p.Y)};
    EXPECT_EQ(got.left, b.left);
    EXPECT_EQ(got.right, b.right);
    EXPECT_TRUE(bridgeWallMask({box(0, 0, 30'000, 10'000)}, {box(0, 0, 30'000, 10'000)}, 400).empty());
}

TEST(BridgeWalls, AWallIsSplitWhereItEntersAndLeavesTheAir) {
    ExtrusionPath wall;
    wall.closed = true;
    wall.points = box(200, 200, 29'800, 9'800);
    const Paths mask{box(4'800, -200, 25'200, 10'200)};
    markBridgedEdges(wall, mask, params(5'000));
    const Path expected{{200, 200},      {4'800, 200},    {25'200, 200},  {29'800, 200},
                        {29'800, 9'800}, {25'200, 9'800}, {4'800, 9'800}, {200, 9'800}};
    EXPECT_EQ(wall.points, expected);
    const std::vector<std::uint8_t> kinds{
        kSupported, kBridged | kContinuesEdge, kSupported | kContinuesEdge, kSupported,
        kSupported, kBridged | kContinuesEdge, kSupported | kContinuesEdge, kSupported};
    EXPECT_EQ(wall.air_edges, kinds);
    ASSERT_TRUE(wall.bridge_wall);
    EXPECT_DOUBLE_EQ(wall.bridge_wall->speed_mm_s, 12.5);
}

TEST(BridgeWalls, AirShorterThanTheMinimumLengthIsNotBridgedAndNoAirChangesNothing) {
    ExtrusionPath wall;
    wall.closed = true;
    wall.points = box(200, 200, 29'800, 9'800);
    markBridgedEdges(wall, {box(4'800, -200, 25'200, 10'200)}, params(25'000));
    EXPECT_EQ(wall.air_edges[1], kShortAir | kContinuesEdge);
    ExtrusionPath supported;
    supported.closed = true;
    supported.points = box(200, 200, 29'800, 9'800);
    markBridgedEdges(supported, {box(40'000, 0, 50'000, 10'000)}, params(5'000));
    EXPECT_TRUE(supported.air_edges.empty());
    EXPECT_FALSE(supported.bridge_wall);
}

}  // namespace
}  // namespace mixengine
