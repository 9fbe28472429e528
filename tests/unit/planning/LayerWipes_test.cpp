// Where the wipe script between layers goes (planning/LayerWipes.h), as CuraEngine 4.13 decides.
#include "planning/LayerWipes.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

PlanStep step(PlanStep::Kind kind) {
    PlanStep s;
    s.kind = kind;
    return s;
}

/// A layer that travels (retracting at the layer change) and extrudes `volume` mm³.
PlannedLayer layer(double volume) {
    PlannedLayer l;
    PlanStep travel = step(PlanStep::Kind::Travel);
    travel.retract = true;
    PlanStep extrude = step(PlanStep::Kind::Extrude);
    extrude.volume_mm3 = volume;
    l.steps = {step(PlanStep::Kind::SetFan), travel, extrude};
    l.layer_change_retract_step = 1;
    return l;
}

LayerWipeParams on(double max) {
    return {true, max};
}

TEST(LayerWipes, AfterMoreThanTheMaximumExtrudedTheNextLayerStartsWithTheScript) {
    PrintPlan plan;
    plan.layers = {layer(6), layer(6), layer(6), layer(6), layer(3)};
    planLayerWipes(plan, {on(10)}, 0);
    std::vector<bool> wiped;
    for (const PlannedLayer& l : plan.layers)
        wiped.push_back(l.steps.front().kind == PlanStep::Kind::WipeScript);
    // 6, then 12 > 10: wipe on layer 2; 6, 12 > 10: wipe on layer 4
    EXPECT_EQ(wiped, (std::vector<bool>{false, false, true, false, true}));
    EXPECT_FALSE(plan.layers[2].steps[2].retract);  // the wipe replaces the layer-change retraction
    EXPECT_TRUE(plan.layers[1].steps[1].retract);
}

TEST(LayerWipes, NothingWhenOffOrWhenTheLayerStartsWithAnotherExtruder) {
    PrintPlan plan;
    plan.layers = {layer(20), layer(20)};
    planLayerWipes(plan, {LayerWipeParams{}}, 0);
    EXPECT_EQ(plan.layers[1].steps.front().kind, PlanStep::Kind::SetFan);

    PrintPlan two;
    two.layers = {layer(20), layer(20), layer(20)};
    PlanStep to1 = step(PlanStep::Kind::SetExtruder);
    to1.extruder = 1;
    two.layers[1].steps.insert(two.layers[1].steps.begin() + 1, to1);
    planLayerWipes(two, {on(10), on(10)}, 0);
    EXPECT_EQ(two.layers[1].steps.front().kind, PlanStep::Kind::SetFan);  // switched first
    // extruder 1 extruded 20 on layer 1: its wipe on layer 2
    EXPECT_EQ(two.layers[2].steps.front().kind, PlanStep::Kind::WipeScript);
    EXPECT_EQ(two.layers[2].steps.front().extruder, 1);
}

}  // namespace
}  // namespace mixengine
