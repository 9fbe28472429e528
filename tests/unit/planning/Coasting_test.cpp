// Coasting (planning/Coasting.h): the end of a path followed by a travel is travelled over at
// coasting_speed instead of extruded, over coasting_volume / (thickness × width), as CuraEngine 4.13.
#include <gtest/gtest.h>

#include <cmath>

#include "planning/Coasting.h"

namespace mixengine {
namespace {

PlanStep travel(Point2 to) {
    PlanStep s;
    s.kind = PlanStep::Kind::Travel;
    s.to = to;
    s.speed_mm_s = 150;
    return s;
}

/// An extrusion to `to` from `from`, 0.4 mm wide and 0.2 mm high, at 30 mm/s.
PlanStep extrude(Point2 from, Point2 to) {
    PlanStep s;
    s.kind = PlanStep::Kind::Extrude;
    s.to = to;
    s.speed_mm_s = 30;
    s.width_um = 400;
    s.acceleration_mm_s2 = 500;
    s.volume_mm3 = std::hypot(double(to.X - from.X), double(to.Y - from.Y)) / 1000 * 0.4 * 0.2;
    return s;
}

PrintPlan squarePlan() {
    PlannedLayer layer;
    layer.thickness = 200;
    layer.steps = {travel({0, 0}),
                   extrude({0, 0}, {10'000, 0}),
                   extrude({10'000, 0}, {10'000, 10'000}),
                   extrude({10'000, 10'000}, {0, 10'000}),
                   extrude({0, 10'000}, {0, 0}),
                   travel({20'000, 0})};
    PrintPlan plan;
    plan.layers.push_back(layer);
    return plan;
}

CoastingParams coasting(double volume, double min_volume, double speed_ratio) {
    CoastingParams p;
    p.enabled = true;
    p.volume_mm3 = volume;
    p.min_volume_mm3 = min_volume;
    p.speed_ratio = speed_ratio;
    return p;
}

TEST(Coasting, TheEndOfALoopBeforeATravelIsTravelledAtTheCoastingSpeed) {
    PrintPlan plan = squarePlan();
    applyCoasting(plan, {coasting(0.064, 0.8, 0.9)}, 0);  // 0.064 / (0.2 × 0.4) = 0.8 mm
    const std::vector<PlanStep>& s = plan.layers[0].steps;
    ASSERT_EQ(s.size(), 7U);
    EXPECT_EQ(s[4].kind, PlanStep::Kind::Extrude);
    EXPECT_EQ(s[4].to, (Point2{0, 800}));
    EXPECT_NEAR(s[4].volume_mm3, 9.2 * 0.08, 1e-9);
    EXPECT_EQ(s[5].kind, PlanStep::Kind::Travel);
    EXPECT_EQ(s[5].to, (Point2{0, 0}));
    EXPECT_DOUBLE_EQ(s[5].speed_mm_s, 27);
    EXPECT_FALSE(s[5].retract);
    EXPECT_EQ(s[5].acceleration_mm_s2, 0);  // the print acceleration stays
    EXPECT_EQ(s[6].to, (Point2{20'000, 0}));
}

TEST(Coasting, ACoastLongerThanTheLastSegmentReachesBackOverSeveralPoints) {
    PrintPlan plan = squarePlan();
    applyCoasting(plan, {coasting(1.2, 0.8, 0.5)}, 0);  // 15 mm: all the last side, 5 mm of the one before
    const std::vector<PlanStep>& s = plan.layers[0].steps;
    ASSERT_EQ(s.size(), 7U);
    EXPECT_EQ(s[3].to, (Point2{5'000, 10'000}));
    EXPECT_NEAR(s[3].volume_mm3, 5 * 0.08, 1e-9);
    EXPECT_EQ(s[4].kind, PlanStep::Kind::Travel);
    EXPECT_EQ(s[4].to, (Point2{0, 10'000}));
    EXPECT_DOUBLE_EQ(s[4].speed_mm_s, 15);
    EXPECT_EQ(s[5].to, (Point2{0, 0}));
}

TEST(Coasting, AShortPathCoastsInProportionToItsLength) {
    PlannedLayer layer;
    layer.thickness = 200;
    // the path's own points span 1 mm (the line from the head is not counted, as CuraEngine); coasting
    // 0.8 mm, minimum (0.064 + 0.8) / 0.08 = 10.8 mm → 1 × 0.8 / 10.8 mm
    layer.steps = {travel({0, 0}), extrude({0, 0}, {1'000, 0}), extrude({1'000, 0}, {2'000, 0}),
                   travel({5'000, 5'000})};
    PrintPlan plan;
    plan.layers.push_back(layer);
    applyCoasting(plan, {coasting(0.064, 0.8, 0.9)}, 0);
    const std::vector<PlanStep>& s = plan.layers[0].steps;
    ASSERT_EQ(s.size(), 5U);
    EXPECT_EQ(s[2].to, (Point2{2'000 - 74, 0}));  // 1000 · 800 / 10800 in whole microns
    EXPECT_EQ(s[3].kind, PlanStep::Kind::Travel);
}

TEST(Coasting, NoCoastingWithoutATravelAfterOrWhenOff) {
    PrintPlan plan = squarePlan();
    plan.layers[0].steps.pop_back();  // the last path of the print: nothing follows
    PrintPlan off = squarePlan();
    const PrintPlan before = squarePlan();
    applyCoasting(plan, {coasting(0.064, 0.8, 0.9)}, 0);
    applyCoasting(off, {CoastingParams{}}, 0);
    EXPECT_EQ(plan.layers[0].steps.size(), 5U);
    EXPECT_EQ(off.layers[0].steps.size(), before.layers[0].steps.size());
}

TEST(Coasting, TheLastPathOfALayerCoastsBeforeTheNextLayersFirstTravel) {
    PrintPlan plan = squarePlan();
    plan.layers[0].steps.pop_back();
    PlannedLayer next;
    next.steps = {PlanStep{PlanStep::Kind::SetFan}, travel({3'000, 3'000})};
    plan.layers.push_back(next);
    applyCoasting(plan, {coasting(0.064, 0.8, 0.9)}, 0);
    EXPECT_EQ(plan.layers[0].steps.back().kind, PlanStep::Kind::Travel);
    EXPECT_EQ(plan.layers[0].steps.back().to, (Point2{0, 0}));
}

}  // namespace
}  // namespace mixengine
