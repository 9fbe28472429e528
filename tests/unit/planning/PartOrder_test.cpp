// A mesh's layer by part (planning/order/PartOrder.h): paths go to the part holding them, parts are
// ordered from the seam position or the head as CuraEngine 4.13's part order.
#include "planning/order/PartOrder.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

Path square(coord_um x, coord_um y, coord_um size) {
    return {{x, y}, {x + size, y}, {x + size, y + size}, {x, y + size}};
}

ExtrusionPath wall(Path points, Feature feature = Feature::WallOuter) {
    ExtrusionPath p;
    p.points = std::move(points);
    p.closed = true;
    p.feature = feature;
    return p;
}

ExtrusionPath line(Point2 a, Point2 b) {
    ExtrusionPath p;
    p.points = {a, b};
    return p;
}

/// Two 10 mm squares: part 0 at x 0..10 mm, part 1 at x 30..40 mm, each with its outer wall and a line.
MeshLayerGroups twoParts() {
    MeshLayerGroups g;
    g.parts = {{square(0, 0, 10'000)}, {square(30'000, 0, 10'000)}};
    g.outer_walls = {wall(square(30'200, 200, 9'600)), wall(square(200, 200, 9'600))};
    g.infill = {line({1'000, 5'000}, {9'000, 5'000}), line({31'000, 5'000}, {39'000, 5'000}),
                line({-5'000, 0}, {-4'000, 0})};
    return g;
}

TEST(PartOrder, PathsGoToTheirPart) {
    const LayerParts parts = splitByPart(twoParts());
    ASSERT_EQ(parts.parts.size(), 2U);
    ASSERT_EQ(parts.parts[0].outer_walls.size(), 1U);
    EXPECT_EQ(parts.parts[0].outer_walls[0].points.front(), (Point2{200, 200}));
    ASSERT_EQ(parts.parts[1].infill.size(), 1U);
    EXPECT_EQ(parts.parts[1].infill[0].points.front(), (Point2{31'000, 5'000}));
    ASSERT_EQ(parts.rest.infill.size(), 1U);  // outside both parts
    EXPECT_EQ(parts.loops[1], square(30'200, 200, 9'600));
}

TEST(PartOrder, SeamPositionChoosesTheFirstPart) {
    const LayerParts parts = splitByPart(twoParts());
    // The head is at the left part, the seam position at the right: the search starts at the seam.
    EXPECT_EQ(seamPartOrder(parts, Point2{50'000, 20'000}, {0, 0}), (std::vector<std::size_t>{1, 0}));
    EXPECT_EQ(seamPartOrder(parts, std::nullopt, {0, 0}), (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(seamPartOrder(parts, std::nullopt, {45'000, 0}), (std::vector<std::size_t>{1, 0}));
}

TEST(PartOrder, FixedSeamIsThePartsStart) {
    MeshLayerGroups g = twoParts();
    // From (20, 5) mm both parts' nearest vertices are equally far (the first part wins the tie); with
    // part 0's seam fixed at its far corner (0.2, 0.2) mm, part 1 comes first.
    EXPECT_EQ(seamPartOrder(splitByPart(g), std::nullopt, {20'000, 5'000}), (std::vector<std::size_t>{0, 1}));
    g.outer_walls[1].fixed_start = true;
    EXPECT_EQ(seamPartOrder(splitByPart(g), std::nullopt, {20'000, 5'000}), (std::vector<std::size_t>{1, 0}));
}

TEST(PartOrder, NearestPartSkipsDoneParts) {
    const LayerParts parts = splitByPart(twoParts());
    std::vector<bool> done{false, false};
    EXPECT_EQ(nearestPart(parts, done, {41'000, 0}), 1U);
    done[1] = true;
    EXPECT_EQ(nearestPart(parts, done, {41'000, 0}), 0U);
    done[0] = true;
    EXPECT_EQ(nearestPart(parts, done, {41'000, 0}), 2U);
}

}  // namespace
}  // namespace mixengine
