// Acceleration and jerk per move (planning/Motion.h): each feature's keys, the raft's and ironing's
// included, the first layers' blend, and none below the model.
#include "planning/Motion.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

PlanStep feature(Feature f) {
    PlanStep s;
    s.kind = PlanStep::Kind::SetFeature;
    s.feature = f;
    return s;
}

PlanStep move(PlanStep::Kind kind) {
    PlanStep s;
    s.kind = kind;
    return s;
}

Settings train() {
    return Settings("extruder 0", {{"acceleration_print_layer_0", "100"},
                                   {"acceleration_travel_layer_0", "150"},
                                   {"acceleration_travel", "1500"},
                                   {"acceleration_ironing", "300"},
                                   {"acceleration_infill", "1000"},
                                   {"raft_base_acceleration", "200"},
                                   {"raft_surface_acceleration", "250"},
                                   {"jerk_print_layer_0", "5"},
                                   {"jerk_travel_layer_0", "6"},
                                   {"jerk_travel", "30"},
                                   {"jerk_ironing", "7"},
                                   {"jerk_infill", "20"},
                                   {"raft_base_jerk", "8"},
                                   {"raft_surface_jerk", "9"},
                                   {"speed_slowdown_layers", "2"}});
}

/// A layer: travel, a raft base line, a raft surface line, ironing, infill (all non-mesh).
PlannedLayer layer(int index) {
    PlannedLayer l;
    l.index = index;
    l.steps = {move(PlanStep::Kind::Travel),  feature(Feature::RaftBase),    move(PlanStep::Kind::Extrude),
               feature(Feature::RaftSurface), move(PlanStep::Kind::Extrude), feature(Feature::Ironing),
               move(PlanStep::Kind::Extrude), feature(Feature::Fill),        move(PlanStep::Kind::Extrude)};
    return l;
}

TEST(Motion, RaftAndIroningTakeTheirOwnKeys) {
    const std::vector<Settings> extruders{train()};
    const Settings global("global", {{"acceleration_enabled", "True"}, {"jerk_enabled", "True"}});
    const MotionSources sources = motionSources(global, {}, extruders);
    PlannedLayer below = layer(-3);  // a raft layer: every value as it is, travel too
    assignMotion(below, sources, 0);
    EXPECT_DOUBLE_EQ(below.steps[0].acceleration_mm_s2, 1500);
    EXPECT_DOUBLE_EQ(below.steps[2].acceleration_mm_s2, 200);
    EXPECT_DOUBLE_EQ(below.steps[4].acceleration_mm_s2, 250);
    EXPECT_DOUBLE_EQ(below.steps[6].acceleration_mm_s2, 300);
    EXPECT_DOUBLE_EQ(below.steps[8].acceleration_mm_s2, 1000);
    EXPECT_DOUBLE_EQ(below.steps[2].jerk_mm_s, 8);
    EXPECT_DOUBLE_EQ(below.steps[6].jerk_mm_s, 7);
    PlannedLayer first = layer(0);  // the model's first layer: the first-layer values, except the raft's
    assignMotion(first, sources, 0);
    EXPECT_DOUBLE_EQ(first.steps[0].acceleration_mm_s2, 150);
    EXPECT_DOUBLE_EQ(first.steps[2].acceleration_mm_s2, 200);
    EXPECT_DOUBLE_EQ(first.steps[6].acceleration_mm_s2, 100);
    EXPECT_DOUBLE_EQ(first.steps[6].jerk_mm_s, 5);
    PlannedLayer second = layer(1);  // halfway through the two slow-down layers
    assignMotion(second, sources, 0);
    EXPECT_DOUBLE_EQ(second.steps[6].acceleration_mm_s2, 200);
    EXPECT_DOUBLE_EQ(second.steps[6].jerk_mm_s, 6);
}

TEST(Motion, RoofingTakesItsOwnKeysNotTheSkins) {
    const std::vector<Settings> extruders{Settings("extruder 0", {{"acceleration_topbottom", "1000"},
                                                                  {"acceleration_roofing", "750"},
                                                                  {"jerk_topbottom", "20"},
                                                                  {"jerk_roofing", "12"},
                                                                  {"acceleration_print_layer_0", "100"},
                                                                  {"jerk_print_layer_0", "5"},
                                                                  {"speed_slowdown_layers", "2"}})};
    const Settings global("global", {{"acceleration_enabled", "True"}, {"jerk_enabled", "True"}});
    PlannedLayer l;
    l.index = 5;
    l.steps = {feature(Feature::Skin), move(PlanStep::Kind::Extrude), feature(Feature::Roofing),
               move(PlanStep::Kind::Extrude)};
    assignMotion(l, motionSources(global, {}, extruders), 0);
    EXPECT_DOUBLE_EQ(l.steps[1].acceleration_mm_s2, 1000);
    EXPECT_DOUBLE_EQ(l.steps[1].jerk_mm_s, 20);
    EXPECT_DOUBLE_EQ(l.steps[3].acceleration_mm_s2, 750);
    EXPECT_DOUBLE_EQ(l.steps[3].jerk_mm_s, 12);
}

TEST(Motion, NothingWhenSwitchedOff) {
    const std::vector<Settings> extruders{train()};
    const Settings global("global", {{"acceleration_enabled", "False"}, {"jerk_enabled", "False"}});
    PlannedLayer l = layer(-3);
    assignMotion(l, motionSources(global, {}, extruders), 0);
    for (const PlanStep& s : l.steps) {
        EXPECT_EQ(s.acceleration_mm_s2, 0);
        EXPECT_EQ(s.jerk_mm_s, 0);
    }
}

}  // namespace
}  // namespace mixengine
