// Printing a wall that crosses air (planning/BridgeWalls.h), as CuraEngine 4.13's addWall.
#include "planning/BridgeWalls.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

/// A 30 × 10 mm wall loop bridged along [5, 25] mm of its bottom edge, at 25 mm/s, 0.4 mm wide.
ExtrusionPath bridgedWall() {
    ExtrusionPath wall;
    wall.closed = true;
    wall.feature = Feature::WallOuter;
    wall.width_um = 400;
    wall.speed_mm_s = 25;
    wall.flow = 1.0;
    wall.points = {{0, 0}, {5'000, 0}, {25'000, 0}, {30'000, 0}, {30'000, 10'000}, {0, 10'000}};
    wall.air_edges = {
        kSupported, kBridged | kContinuesEdge, kSupported | kContinuesEdge, kSupported, kSupported,
        kSupported};
    wall.bridge_wall = BridgeWallStyle{12.5, 0.5, 1.0, 1.0};
    return wall;
}

TravelParams travel() {
    TravelParams t;
    t.layer_thickness_um = 200;
    return t;
}

TEST(BridgeWallPlan, TheBridgeIsSlowThinMarkedAndFannedThenTheWallSpeedsUp) {
    std::vector<PlanStep> steps;
    std::optional<Feature> feature = Feature::WallOuter;
    BridgeMarks marks;
    Point2 head{0, 0};
    const ExtrusionPath wall = bridgedWall();
    EXPECT_EQ(emitBridgedWall(wall, 0, travel(), head, feature, marks, steps), 0U);
    std::vector<PlanStep> extrusions;
    std::size_t bridge_marker = steps.size(), fan = steps.size();
    for (std::size_t i = 0; i < steps.size(); ++i) {
        if (steps[i].kind == PlanStep::Kind::Extrude)
            extrusions.push_back(steps[i]);
        if (steps[i].kind == PlanStep::Kind::SetFeature && steps[i].bridge && bridge_marker == steps.size())
            bridge_marker = i;
        if (steps[i].kind == PlanStep::Kind::SetFan && steps[i].fan_fixed)
            fan = i;
    }
    ASSERT_LT(bridge_marker, steps.size());
    EXPECT_EQ(steps[fan].fan_ratio, 1.0);
    // 5 mm to the bridge, coasting its last part: min(100 mm, …) × (1 − 12.5·0.5 / 25) × 1 / 40 = 1.875 mm
    ASSERT_GE(extrusions.size(), 4U);
    EXPECT_EQ(extrusions[0].to, (Point2{3'125, 0}));
    EXPECT_EQ(extrusions[1].to, (Point2{5'000, 0}));
    EXPECT_EQ(extrusions[1].volume_mm3, 0);  // coasting: no flow
    EXPECT_EQ(extrusions[2].to, (Point2{25'000, 0}));
    EXPECT_DOUBLE_EQ(extrusions[2].speed_mm_s, 12.5);
    EXPECT_NEAR(extrusions[2].volume_mm3, 20 * 0.4 * 0.2 * 0.5, 1e-9);
    // after it, 1 mm at half speed with twice the flow, then 1 mm at 5/8 speed, …
    EXPECT_EQ(extrusions[3].to, (Point2{26'000, 0}));
    EXPECT_DOUBLE_EQ(extrusions[3].speed_mm_s, 12.5);
    EXPECT_NEAR(extrusions[3].volume_mm3, 1 * 0.4 * 0.2 * 2, 1e-9);
    EXPECT_DOUBLE_EQ(extrusions[4].speed_mm_s, 25 * 0.625);
    EXPECT_EQ(extrusions.back().to, (Point2{0, 0}));
    EXPECT_FALSE(marks.bridge);  // back to the plain wall
    EXPECT_EQ(marks.fan, -1);
}

TEST(BridgeWallPlan, TheWallStartsOnTheFirstVertexNotOverAir) {
    std::vector<PlanStep> steps;
    std::optional<Feature> feature;
    BridgeMarks marks;
    Point2 head{0, 0};
    const ExtrusionPath wall = bridgedWall();
    EXPECT_EQ(emitBridgedWall(wall, 1, travel(), head, feature, marks, steps), 3U);  // 1 and 2 touch air
}

}  // namespace
}  // namespace mixengine
