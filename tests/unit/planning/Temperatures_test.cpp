// Temperatures during the print (planning/Temperatures.h): the flow graph, where the nozzle's
// M104 goes (CuraEngine's preheat rule), the bed at layer 1.
#include "planning/Temperatures.h"

#include <gtest/gtest.h>

#include "common/Error.h"

namespace mixengine {
namespace {

/// A layer of `moves` 10 mm extrusions along X at 10 mm/s (1 s each), 2 mm³ each.
PlannedLayer layer(int index, int moves) {
    PlannedLayer l;
    l.index = index;
    for (int i = 1; i <= moves; ++i) {
        PlanStep s;
        s.kind = PlanStep::Kind::Extrude;
        s.to = {i * 10'000, 0};
        s.speed_mm_s = 10;
        s.volume_mm3 = 2;
        l.steps.push_back(s);
    }
    return l;
}

std::vector<std::size_t> positions(const PlannedLayer& l, PlanStep::Kind kind) {
    std::vector<std::size_t> at;
    for (std::size_t i = 0; i < l.steps.size(); ++i)
        if (l.steps[i].kind == kind)
            at.push_back(i);
    return at;
}

TemperatureParams params() {
    TemperatureParams p;
    p.bed_c = 50;
    p.bed_layer0_c = 60;
    p.nozzle.print_c = 200;
    p.nozzle.layer0_c = 215;
    p.nozzle.cool_down_c_per_s = 2.0;
    p.nozzle.extrusion_cool_c_per_s = 0.5;
    p.nozzle.heat_up_c_per_s = 2.0;
    return p;
}

TEST(Temperatures, FlowGraphClampsAndInterpolates) {
    NozzleTemperatureParams p;
    p.print_c = 210;
    p.graph = parseFlowTemperatureGraph("[[3.5, 200], [7.0, 240]]");
    EXPECT_EQ(flowTemperature(p, 5.0), 210);  // not flow dependent: the print temperature
    p.flow_dependent = true;
    EXPECT_EQ(flowTemperature(p, 1.0), 200);
    EXPECT_EQ(flowTemperature(p, 5.25), 220);
    EXPECT_EQ(flowTemperature(p, 9.0), 240);
    EXPECT_THROW(parseFlowTemperatureGraph("[[3.5, 200], [7.0]]"), InputError);
}

TEST(Temperatures, LayerZeroToPrintTemperatureHalfTheCoolingTimeBeforeLayerOneStarts) {
    PrintPlan plan;
    plan.layers = {layer(0, 20), layer(1, 20), layer(2, 20)};
    planTemperatures(plan, params(), true, {0, 0});
    // 215 -> 200 while printing cools at 2.0 + 0.5 °C/s: 6 s; half of it, 3 s, before layer 0 ends:
    // after the 17th of its twenty 1-second moves.
    const std::vector<std::size_t> at = positions(plan.layers[0], PlanStep::Kind::SetNozzleTemperature);
    ASSERT_EQ(at.size(), 1u);
    EXPECT_EQ(at[0], 17u);
    EXPECT_EQ(plan.layers[0].steps[at[0]].temperature_c, 200);
    EXPECT_TRUE(positions(plan.layers[1], PlanStep::Kind::SetNozzleTemperature).empty());
    EXPECT_TRUE(positions(plan.layers[2], PlanStep::Kind::SetNozzleTemperature).empty());
}

TEST(Temperatures, BedChangesAtTheStartOfLayerOneOnly) {
    PrintPlan plan;
    plan.layers = {layer(0, 3), layer(1, 3), layer(2, 3)};
    planTemperatures(plan, params(), true, {0, 0});
    ASSERT_EQ(positions(plan.layers[1], PlanStep::Kind::SetBedTemperature), std::vector<std::size_t>{0});
    EXPECT_EQ(plan.layers[1].steps[0].temperature_c, 50);
    EXPECT_TRUE(positions(plan.layers[2], PlanStep::Kind::SetBedTemperature).empty());
}

TEST(Temperatures, NothingWhenTemperaturesDoNotChangeOrNozzleControlIsOff) {
    TemperatureParams same = params();
    same.bed_c = same.bed_layer0_c;
    same.nozzle.layer0_c = 0;  // layer 0 prints at the print temperature
    PrintPlan plan;
    plan.layers = {layer(0, 5), layer(1, 5)};
    planTemperatures(plan, same, true, {0, 0});
    EXPECT_EQ(plan.layers[0].steps.size(), 5u);
    EXPECT_EQ(plan.layers[1].steps.size(), 5u);

    TemperatureParams off = params();
    off.nozzle.enabled = false;
    off.heated_bed = false;
    planTemperatures(plan, off, true, {0, 0});
    EXPECT_EQ(plan.layers[0].steps.size(), 5u);
}

TEST(Temperatures, FlowDependentLayersGetTheirOwnTemperature) {
    TemperatureParams p = params();
    p.nozzle.layer0_c = 0;
    p.nozzle.flow_dependent = true;
    p.nozzle.graph = {{1.0, 190}, {3.0, 230}};
    PrintPlan plan;
    plan.layers = {layer(0, 10), layer(1, 10), layer(2, 10)};
    for (PlannedLayer& l : plan.layers) {
        PlanStep back;  // travel to the origin first (travel time does not count for the flow)
        back.kind = PlanStep::Kind::Travel;
        back.speed_mm_s = 100;
        l.steps.insert(l.steps.begin(), back);
    }
    for (PlanStep& s : plan.layers[2].steps)
        s.volume_mm3 = 3;  // 3 mm³/s: 230 °C
    planTemperatures(plan, p, true, {0, 0});
    // Layers 0 and 1 extrude 2 mm³/s: 210 °C (the start), layer 2 wants 230: set in layer 1.
    const std::vector<std::size_t> at = positions(plan.layers[1], PlanStep::Kind::SetNozzleTemperature);
    ASSERT_EQ(at.size(), 1u);
    EXPECT_EQ(plan.layers[1].steps[at[0]].temperature_c, 230);
}

TEST(Temperatures, UnderARaftTheRaftsBaseIsTheInitialLayer) {
    // Raft layers −3 … −1, then the model from 0: the first-layer temperature is the raft base's
    // (CuraEngine's "initial layer"), the bed changes at the start of the second layer.
    PrintPlan plan;
    plan.layers = {layer(-3, 20), layer(-2, 20), layer(-1, 20), layer(0, 20)};
    planTemperatures(plan, params(), true, {0, 0});
    const std::vector<std::size_t> at = positions(plan.layers[0], PlanStep::Kind::SetNozzleTemperature);
    ASSERT_EQ(at.size(), 1u);
    EXPECT_EQ(plan.layers[0].steps[at[0]].temperature_c, 200);
    EXPECT_TRUE(positions(plan.layers[3], PlanStep::Kind::SetNozzleTemperature).empty());
    EXPECT_EQ(positions(plan.layers[1], PlanStep::Kind::SetBedTemperature), std::vector<std::size_t>{0});
}

TEST(Temperatures, LayerByLayerGivesTheWholePlansStepsAndFinalLayersStayFinal) {
    // Layers of 20, 4, 20, 3, 20 moves, layer 2 with more material per move: with the flow graph each
    // layer wants its own temperature, set in the layer before; the bed changes in layer 1.
    TemperatureParams p = params();
    p.nozzle.flow_dependent = true;
    p.nozzle.graph = {{1.0, 190}, {3.0, 230}};
    PrintPlan source;
    source.layers = {layer(0, 20), layer(1, 4), layer(2, 20), layer(3, 3), layer(4, 20)};
    for (PlanStep& s : source.layers[2].steps)
        s.volume_mm3 = 3;
    PrintPlan whole = source;
    planTemperatures(whole, p, true, {0, 0});

    PrintPlan growing;
    TemperatureSteps steps(p, true, {0, 0});
    std::vector<std::size_t> final_counts;
    std::vector<std::vector<PlanStep>> seen_final;  // each layer as it was when it became final
    for (const PlannedLayer& l : source.layers) {
        growing.layers.push_back(l);
        const std::size_t final_count = steps.add(growing);
        final_counts.push_back(final_count);
        for (std::size_t i = seen_final.size(); i < final_count; ++i)
            seen_final.push_back(growing.layers[i].steps);
    }
    const std::size_t total = steps.finish(growing);
    for (std::size_t i = seen_final.size(); i < total; ++i)
        seen_final.push_back(growing.layers[i].steps);
    EXPECT_EQ(final_counts, (std::vector<std::size_t>{0, 1, 2, 3, 4}));  // final once the next is added
    EXPECT_EQ(total, 5u);
    ASSERT_EQ(seen_final.size(), whole.layers.size());
    std::size_t temperature_steps = 0;
    for (std::size_t i = 0; i < whole.layers.size(); ++i) {
        const std::vector<PlanStep>& expected = whole.layers[i].steps;
        ASSERT_EQ(seen_final[i].size(), expected.size()) << "layer " << i;
        for (std::size_t k = 0; k < expected.size(); ++k) {
            EXPECT_EQ(seen_final[i][k].kind, expected[k].kind) << "layer " << i << " step " << k;
            EXPECT_EQ(seen_final[i][k].temperature_c, expected[k].temperature_c);
        }
        temperature_steps += expected.size() - source.layers[i].steps.size();
    }
    EXPECT_EQ(temperature_steps, 5u);  // a nozzle step in each of layers 0-3 (flows differ), the bed
}

}  // namespace
}  // namespace mixengine
