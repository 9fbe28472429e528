// Cooling (planning/Cooling.h): minimum layer time slow-down and fan speed by layer time.
#include "planning/Cooling.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

PlannedLayer layerOf(double extrude_mm, double speed, int index = 5) {
    PlannedLayer layer;
    layer.index = index;
    PlanStep fan;
    fan.kind = PlanStep::Kind::SetFan;
    PlanStep move;
    move.kind = PlanStep::Kind::Extrude;
    move.to = {static_cast<coord_um>(extrude_mm * 1000), 0};
    move.speed_mm_s = speed;
    layer.steps = {fan, move};
    return layer;
}

CoolingParams params() {
    CoolingParams p;
    p.fan_min_ratio = 0.5;
    p.fan_max_ratio = 1.0;
    p.fan_first_ratio = 0;
    p.fan_full_layer = 3;
    p.min_layer_time_s = 5;
    p.fan_max_layer_time_s = 10;
    p.min_speed_mm_s = 10;
    return p;
}

TEST(Cooling, SlowsShortLayersToTheMinimumTime) {
    PlannedLayer layer = layerOf(100, 50);  // 2 s → slowed to 20 mm/s = 5 s
    applyCooling(layer, {0, 0}, params());
    EXPECT_DOUBLE_EQ(layer.steps[1].speed_mm_s, 20);
    EXPECT_NEAR(naiveLayerSeconds(layer, {0, 0}), 5.0, 1e-9);
    EXPECT_DOUBLE_EQ(layer.steps[0].fan_ratio, 1.0);  // at the minimum time: full fan
}

TEST(Cooling, NeverBelowMinimumSpeed) {
    PlannedLayer layer = layerOf(10, 50);  // would need 2 mm/s
    applyCooling(layer, {0, 0}, params());
    EXPECT_DOUBLE_EQ(layer.steps[1].speed_mm_s, 10);
}

PlanStep moveTo(PlanStep::Kind kind, double x_mm, double speed, bool retract = false) {
    PlanStep step;
    step.kind = kind;
    step.to = {static_cast<coord_um>(x_mm * 1000), 0};
    step.speed_mm_s = speed;
    step.retract = retract;
    return step;
}

TEST(Cooling, OneFactorForEveryExtrusionTheSlowestAtTheMinimumSpeed) {
    // 100 mm at 50 mm/s and 20 mm at 20 mm/s: 3 s; 0.6 would print the slow one at 12 mm/s, but
    // the 10 mm/s minimum speed already caps the slow one when the layer needs 0.3
    PlannedLayer layer = layerOf(100, 50);
    layer.steps.push_back(moveTo(PlanStep::Kind::Extrude, 120, 20));
    CoolingParams p = params();
    p.min_layer_time_s = 10;  // would need 0.3
    applyCooling(layer, {0, 0}, p);
    EXPECT_DOUBLE_EQ(layer.steps[1].speed_mm_s, 25);  // the same factor, 0.5, as the slow one
    EXPECT_DOUBLE_EQ(layer.steps[2].speed_mm_s, 10);
}

TEST(Cooling, EstimateCountsRetractionsButNotTheLeadingTravelsRoute) {
    PlannedLayer layer = layerOf(0, 50);
    layer.steps.pop_back();
    // the travel the layer starts with: a route of two moves, counted as the straight 30 mm
    layer.steps.push_back(moveTo(PlanStep::Kind::Travel, 60, 150, true));
    layer.steps.push_back(moveTo(PlanStep::Kind::Travel, 30, 150));
    layer.steps.push_back(moveTo(PlanStep::Kind::Extrude, 130, 50));         // 2 s
    layer.steps.push_back(moveTo(PlanStep::Kind::Travel, 280, 150, true));   // 1 s + 0.5 s retraction
    layer.steps.push_back(moveTo(PlanStep::Kind::Travel, 430, 150));         // the same travel
    layer.steps.push_back(moveTo(PlanStep::Kind::Travel, 580, 150, false));  // still the same travel
    const LayerEstimate estimate = estimateLayer(layer, {0, 0}, 0.5);
    EXPECT_NEAR(estimate.extrude_s, 2.0, 1e-9);
    EXPECT_NEAR(estimate.travel_s, 0.2 + 3.0 + 0.5, 1e-9);
    EXPECT_NEAR(estimate.unretracted_s, 0.2 + 0.25, 1e-9);
}

TEST(Cooling, ExtrusionsTakeAtLeastOneSecond) {
    // 4.5 s of travel leaves 0.5 s of a 5 s minimum for 0.4 s of extrusion: slowed to 1 s, not 0.5
    PlannedLayer layer = layerOf(20, 50);
    layer.steps.push_back(moveTo(PlanStep::Kind::Travel, 695, 150));
    CoolingParams p = params();
    p.min_speed_mm_s = 1;
    applyCooling(layer, {0, 0}, p);
    EXPECT_DOUBLE_EQ(layer.steps[1].speed_mm_s, 20);
}

TEST(Cooling, FanFollowsTheEstimateBeforeTheSlowDownWithoutRetractedTravel) {
    // 5.5 s extruding, a retracted 1 s travel and its 0.5 s retraction: 7 s, no slow-down; the fan
    // sees 5.5 s + half the retraction = 5.75 s
    PlannedLayer layer = layerOf(275, 50);
    layer.steps.push_back(moveTo(PlanStep::Kind::Travel, 425, 150, true));
    CoolingParams p = params();
    p.retract_seconds = 0.5;
    applyCooling(layer, {0, 0}, p);
    EXPECT_DOUBLE_EQ(layer.steps[1].speed_mm_s, 50);
    EXPECT_NEAR(layer.steps[0].fan_ratio, 0.5 + 0.5 * (10 - 5.75) / 5, 1e-9);
}

TEST(Cooling, LiftHeadWaitsOutWhatTheMinimumSpeedLeaves) {
    CoolingParams p = params();
    p.lift_head = true;
    p.bed_middle_um = {110'000, 0};
    p.travel_speed_mm_s = 150;
    PlannedLayer layer = layerOf(10, 50);  // 10 mm at the 10 mm/s minimum: 1 s of the 5
    applyCooling(layer, {0, 0}, p);
    ASSERT_EQ(layer.steps.size(), 3U);
    const PlanStep& lift = layer.steps.back();
    EXPECT_EQ(lift.kind, PlanStep::Kind::LiftHead);
    EXPECT_EQ(lift.to, (Point2{30'000, 0}));  // 20 mm from the last position towards the middle
    EXPECT_NEAR(lift.dwell_seconds, 4.0, 1e-9);
    EXPECT_EQ(lift.speed_mm_s, 150.0);
    PlannedLayer slowed = layerOf(100, 50);  // reaches the 5 s by slowing down: no lift
    applyCooling(slowed, {0, 0}, p);
    EXPECT_EQ(slowed.steps.size(), 2U);
    p.lift_head = false;
    PlannedLayer off = layerOf(10, 50);
    applyCooling(off, {0, 0}, p);
    EXPECT_EQ(off.steps.size(), 2U);
}

TEST(Cooling, FanBetweenMinAndMaxByLayerTime) {
    PlannedLayer slow = layerOf(600, 50);  // 12 s: regular fan
    applyCooling(slow, {0, 0}, params());
    EXPECT_DOUBLE_EQ(slow.steps[0].fan_ratio, 0.5);
    EXPECT_DOUBLE_EQ(slow.steps[1].speed_mm_s, 50);
    PlannedLayer middle = layerOf(375, 50);  // 7.5 s: halfway
    applyCooling(middle, {0, 0}, params());
    EXPECT_DOUBLE_EQ(middle.steps[0].fan_ratio, 0.75);
}

TEST(Cooling, FirstLayersRampFromTheInitialFanSpeed) {
    PlannedLayer first = layerOf(600, 50, 0);
    applyCooling(first, {0, 0}, params());
    EXPECT_DOUBLE_EQ(first.steps[0].fan_ratio, 0.0);
    PlannedLayer second = layerOf(600, 50, 1);  // full speed from layer index 2
    applyCooling(second, {0, 0}, params());
    EXPECT_DOUBLE_EQ(second.steps[0].fan_ratio, 0.25);
    CoolingParams off = params();
    off.fan_enabled = false;
    PlannedLayer none = layerOf(600, 50);
    applyCooling(none, {0, 0}, off);
    EXPECT_DOUBLE_EQ(none.steps[0].fan_ratio, 0.0);
}

TEST(Cooling, LayersBelowTheModelCoolAsItsFirstLayer) {
    PlannedLayer filler = layerOf(600, 50, -2);  // a raft filler layer
    applyCooling(filler, {0, 0}, params());
    EXPECT_DOUBLE_EQ(filler.steps[0].fan_ratio, 0.0);  // cool_fan_speed_0, not below it
}

TEST(Cooling, RaftLayersTakeTheirOwnFanWithoutTheRamp) {
    const CoolingParams raft = raftCooling(params(), 0.3);
    PlannedLayer base = layerOf(600, 50, -6);  // 12 s: the raft's fan
    applyCooling(base, {0, 0}, raft);
    EXPECT_DOUBLE_EQ(base.steps[0].fan_ratio, 0.3);
    PlannedLayer quick = layerOf(100, 50, -4);  // slowed to the minimum time: cool_fan_speed_max
    applyCooling(quick, {0, 0}, raft);
    EXPECT_DOUBLE_EQ(quick.steps[0].fan_ratio, 1.0);
    EXPECT_DOUBLE_EQ(quick.steps[1].speed_mm_s, 20);
    CoolingParams off = params();
    off.fan_enabled = false;  // CuraEngine zeroes the fan speeds, then sets the raft's
    PlannedLayer unfanned = layerOf(600, 50, -6);
    applyCooling(unfanned, {0, 0}, raftCooling(off, 0.3));
    EXPECT_DOUBLE_EQ(unfanned.steps[0].fan_ratio, 0.3);
}

// Gap lines merged as CuraEngine 4.13's MergeInfillLines merges them (mergeGapLines).
PlanStep stepAt(PlanStep::Kind kind, coord_um x, coord_um y, bool gap) {
    PlanStep step;
    step.kind = kind;
    step.to = {x, y};
    step.speed_mm_s = kind == PlanStep::Kind::Travel ? 150 : 25;
    if (kind == PlanStep::Kind::Extrude) {
        step.width_um = 200;
        step.mergeable = gap;
        step.volume_mm3 = 0.3 * 0.2 * 0.2;  // a 0.3 mm line, 0.2 mm wide and high
    }
    return step;
}

/// A wall, then three 0.3 mm gap lines side by side 0.2 mm apart (travel between), then travel away.
PlannedLayer threeGapLines(bool gap, Point2 second_from = {200, 300}, Point2 second_to = {200, 0}) {
    using K = PlanStep::Kind;
    PlannedLayer layer;
    layer.steps = {stepAt(K::SetFan, 0, 0, false),
                   stepAt(K::Travel, -5000, 0, false),
                   stepAt(K::Extrude, -4000, 0, false),
                   stepAt(K::Travel, 0, 0, false),
                   stepAt(K::Extrude, 0, 300, gap),
                   stepAt(K::Travel, second_from.X, second_from.Y, false),
                   stepAt(K::Extrude, second_to.X, second_to.Y, gap),
                   stepAt(K::Travel, 400, 0, false),
                   stepAt(K::Extrude, 400, 300, gap),
                   stepAt(K::Travel, 9000, 0, false)};
    return layer;
}

GapMergeParams gapParams(int) {
    return {400, 25};
}

TEST(Cooling, GapLinesSideBySideBecomeOneLineThroughTheirMiddles) {
    PlannedLayer layer = threeGapLines(true);
    mergeGapLines(layer, 0, gapParams);
    // travel to the first line's middle, then its flow times the lengths CuraEngine predicts:
    // 600 µm of line over 200 µm (flow 3), then 250 µm × 3 + 300 µm over 450 µm
    ASSERT_EQ(layer.steps.size(), 7u);
    EXPECT_EQ(layer.steps[3].kind, PlanStep::Kind::Travel);
    EXPECT_EQ(layer.steps[3].to, (Point2{0, 150}));
    EXPECT_EQ(layer.steps[4].to, (Point2{200, 150}));
    EXPECT_EQ(layer.steps[5].to, (Point2{400, 150}));
    const double per_mm = 0.2 * 0.2;
    EXPECT_NEAR(layer.steps[4].volume_mm3, 0.2 * per_mm * 1050.0 / 450.0, 1e-12);
    EXPECT_NEAR(layer.steps[5].volume_mm3, 0.2 * per_mm * 1050.0 / 450.0, 1e-12);
    EXPECT_EQ(layer.steps[6].to, (Point2{9000, 0}));
}

TEST(Cooling, OtherLinesAndLinesEndToEndStayApart) {
    PlannedLayer skin = threeGapLines(false);
    const std::size_t steps = skin.steps.size();
    mergeGapLines(skin, 0, gapParams);
    EXPECT_EQ(skin.steps.size(), steps);
    // the second line continues the first (its start 50 µm past the first's end): the first stays
    // whole, and the second (merged with the third) starts after a travel
    PlannedLayer in_line = threeGapLines(true, {0, 350}, {0, 650});
    mergeGapLines(in_line, 0, gapParams);
    EXPECT_EQ(in_line.steps[4].to, (Point2{0, 300}));
    EXPECT_EQ(in_line.steps[5].kind, PlanStep::Kind::Travel);
    EXPECT_EQ(in_line.steps[5].to, (Point2{0, 500}));
}

// No merge makes a line wider than 3 nozzles: with a 0.1 mm nozzle the 0.2 mm lines may reach flow 1.5,
// and the first pair would need 3 (600 µm of line over 200 µm), so nothing merges.
TEST(Cooling, GapLinesStayApartWhereTheMergedLineWouldBeWiderThanThreeNozzles) {
    PlannedLayer layer = threeGapLines(true);
    const std::size_t steps = layer.steps.size();
    mergeGapLines(layer, 0, [](int) { return GapMergeParams{100, 25}; });
    EXPECT_EQ(layer.steps.size(), steps);
}

}  // namespace
}  // namespace mixengine
