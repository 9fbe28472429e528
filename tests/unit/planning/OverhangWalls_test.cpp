// Printing an overhanging wall (planning/BridgeWalls.h through planning/PathOrder.h): it starts on a
// vertex that does not overhang, and its lines with an overhanging end are slower.
#include "planning/BridgeWalls.h"

#include <gtest/gtest.h>

#include "planning/PathOrder.h"

namespace mixengine {
namespace {

/// A 10 mm square loop at 30 mm/s whose right side (vertices 1 and 2) overhangs, at half speed there.
ExtrusionPath overhangingLoop() {
    ExtrusionPath p;
    p.points = {{0, 0}, {10'000, 0}, {10'000, 10'000}, {0, 10'000}};
    p.closed = true;
    p.width_um = 400;
    p.feature = Feature::WallOuter;
    p.speed_mm_s = 30;
    p.overhanging = {0, 1, 1, 0};
    p.overhang_speed_factor = 0.5;
    return p;
}

TEST(OverhangWallPlan, TheHelpersTellOverhangingPointsAndLines) {
    const ExtrusionPath wall = overhangingLoop();
    EXPECT_FALSE(overhangsAt(wall, 0));
    EXPECT_TRUE(overhangsAt(wall, 1));
    EXPECT_EQ(firstNonOverhanging(wall, 1), 3U);
    EXPECT_EQ(firstNonOverhanging(wall, 0), 0U);
    EXPECT_DOUBLE_EQ(overhangSpeedFactor(wall, 0, 1), 0.5);
    EXPECT_DOUBLE_EQ(overhangSpeedFactor(wall, 3, 0), 1.0);
    ExtrusionPath plain = wall;
    plain.overhanging.clear();
    EXPECT_EQ(firstNonOverhanging(plain, 1), 1U);
    EXPECT_DOUBLE_EQ(overhangSpeedFactor(plain, 0, 1), 1.0);
}

TEST(OverhangWallPlan, TheLoopStartsOnASupportedVertexAndSlowsWhereItOverhangs) {
    ExtrusionPath wall = overhangingLoop();
    wall.fixed_start = true;  // the seam at vertex 1 (over the overhang): moved on to vertex 3
    std::rotate(wall.points.begin(), wall.points.begin() + 1, wall.points.end());
    std::rotate(wall.overhanging.begin(), wall.overhanging.begin() + 1, wall.overhanging.end());
    TravelParams travel;
    travel.travel_speed_mm_s = 150;
    travel.layer_thickness_um = 200;
    Point2 head{10'000, 0};
    std::optional<Feature> feature;
    std::vector<PlanStep> steps;
    appendOrderedPaths({wall}, travel, head, feature, steps);
    std::vector<PlanStep> moves;
    for (const PlanStep& s : steps) {
        if (s.kind == PlanStep::Kind::Extrude || s.kind == PlanStep::Kind::Travel)
            moves.push_back(s);
    }
    ASSERT_EQ(moves.size(), 5U);
    EXPECT_EQ(moves[0].kind, PlanStep::Kind::Travel);
    EXPECT_EQ(moves[0].to, (Point2{0, 10'000}));
    EXPECT_EQ(moves[1].to, (Point2{0, 0}));
    EXPECT_DOUBLE_EQ(moves[1].speed_mm_s, 30);
    EXPECT_EQ(moves[2].to, (Point2{10'000, 0}));  // ends on an overhanging vertex
    EXPECT_DOUBLE_EQ(moves[2].speed_mm_s, 15);
    EXPECT_DOUBLE_EQ(moves[3].speed_mm_s, 15);    // both ends overhang
    EXPECT_EQ(moves[4].to, (Point2{0, 10'000}));  // starts on one
    EXPECT_DOUBLE_EQ(moves[4].speed_mm_s, 15);
    EXPECT_EQ(head, (Point2{0, 10'000}));
}

}  // namespace
}  // namespace mixengine
