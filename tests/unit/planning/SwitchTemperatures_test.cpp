// Temperatures around extruder switches (planning/SwitchTemperatures.h) on a plan of two extruders
// taking turns: layer 0 T0 then T1, layer 1 T1 then T0, each run 60 one-second extrusions.
#include "planning/SwitchTemperatures.h"

#include <gtest/gtest.h>

#include "planning/ExtruderRuns.h"

namespace mixengine {
namespace {

constexpr int kMoves = 60;

void addRun(PlannedLayer& l, int moves) {
    for (int i = 1; i <= moves; ++i) {
        PlanStep s;
        s.kind = PlanStep::Kind::Extrude;
        s.to = {(i % 2) * 10'000, 0};  // back and forth, 10 mm at 10 mm/s: 1 s each
        s.speed_mm_s = 10;
        s.volume_mm3 = 2;
        l.steps.push_back(s);
    }
}

PlanStep switchTo(int extruder) {
    PlanStep s;
    s.kind = PlanStep::Kind::SetExtruder;
    s.extruder = extruder;
    return s;
}

PrintPlan takingTurns() {
    PrintPlan plan;
    for (int index = 0; index < 2; ++index) {
        PlannedLayer l;
        l.index = index;
        addRun(l, kMoves);
        l.steps.push_back(switchTo(index == 0 ? 1 : 0));
        addRun(l, kMoves);
        plan.layers.push_back(l);
    }
    return plan;
}

SwitchTemperatureParams params() {
    TrainTemperatureParams t;
    t.nozzle.print_c = 200;
    t.nozzle.layer0_c = 200;
    t.nozzle.heat_up_c_per_s = 1.4;
    t.nozzle.cool_down_c_per_s = 0.8;
    t.nozzle.extrusion_cool_c_per_s = 0.7;
    t.initial_c = 190;
    t.final_c = 185;
    t.standby_c = 100;
    t.min_window_s = 15;
    return {{t, t}, false, {5, 5}};
}

struct Found {
    std::size_t layer, step;
    PlanStep s;
};

std::vector<Found> temperatures(const PrintPlan& plan) {
    std::vector<Found> out;
    for (std::size_t l = 0; l < plan.layers.size(); ++l)
        for (std::size_t i = 0; i < plan.layers[l].steps.size(); ++i)
            if (plan.layers[l].steps[i].kind == PlanStep::Kind::SetNozzleTemperature)
                out.push_back({l, i, plan.layers[l].steps[i]});
    return out;
}

std::size_t switchAt(const PlannedLayer& l) {
    for (std::size_t i = 0; i < l.steps.size(); ++i)
        if (l.steps[i].kind == PlanStep::Kind::SetExtruder)
            return i;
    return l.steps.size();
}

TEST(ExtruderRuns, OneRunPerExtruderPerLayerWithItsTimes) {
    const ExtruderRuns r = extruderRuns(takingTurns(), 0, {0, 0});
    ASSERT_EQ(r.runs.size(), 4U);
    EXPECT_EQ(r.runs[0].extruder, 0);
    EXPECT_EQ(r.runs[1].extruder, 1);
    EXPECT_TRUE(r.runs[1].switched);
    EXPECT_EQ(r.runs[2].extruder, 1);
    EXPECT_FALSE(r.runs[2].switched);
    EXPECT_EQ(r.runs[3].extruder, 0);
    EXPECT_DOUBLE_EQ(r.runs[0].seconds, kMoves);
    EXPECT_DOUBLE_EQ(r.runs[0].volume_mm3, 2.0 * kMoves);
    EXPECT_EQ(r.runs[1].begin, kMoves + 1U);
}

// At each switch: M109 for the new extruder, then the old one set to standby. T1's first run starts at
// its printing temperature; T0, back on layer 1, at its initial temperature (190 °C) and goes to 200 °C at
// its first extrusion. T1 cools to its final temperature (185 °C) before it is left, and T0 is heated
// again, in T1's runs, before it comes back.
TEST(SwitchTemperatures, StandbyPreheatInitialAndFinalTemperatures) {
    PrintPlan plan = takingTurns();
    planSwitchTemperatures(plan, params(), 0, {0, 0});
    const std::vector<Found> t = temperatures(plan);
    const std::size_t first_switch = switchAt(plan.layers[0]);
    const std::size_t second_switch = switchAt(plan.layers[1]);

    auto at = [&](std::size_t layer, std::size_t step) -> const PlanStep& {
        return plan.layers[layer].steps[step];
    };
    // Layer 0: M109 T1 200 right after the switch, then T0 to a standby temperature between 100 and 200.
    EXPECT_TRUE(at(0, first_switch + 1).wait);
    EXPECT_EQ(at(0, first_switch + 1).extruder, 1);
    EXPECT_EQ(at(0, first_switch + 1).temperature_c, 200);
    EXPECT_EQ(at(0, first_switch + 2).extruder, 0);
    EXPECT_GE(at(0, first_switch + 2).temperature_c, 100);
    EXPECT_LT(at(0, first_switch + 2).temperature_c, 200);
    // Layer 1: M109 T0 190 after the switch, and 200 °C before its first extrusion.
    EXPECT_TRUE(at(1, second_switch + 1).wait);
    EXPECT_EQ(at(1, second_switch + 1).extruder, 0);
    EXPECT_EQ(at(1, second_switch + 1).temperature_c, 190);
    EXPECT_EQ(at(1, second_switch + 3).kind, PlanStep::Kind::SetNozzleTemperature);
    EXPECT_EQ(at(1, second_switch + 3).temperature_c, 200);
    EXPECT_EQ(at(1, second_switch + 4).kind, PlanStep::Kind::Extrude);

    bool t1_final = false, t0_preheat = false;
    for (const Found& f : t) {
        const bool before_second_switch = f.layer == 0 ? f.step > first_switch : f.step < second_switch;
        t1_final = t1_final || (f.s.extruder == 1 && f.s.temperature_c == 185 && before_second_switch);
        t0_preheat = t0_preheat ||
                     (f.s.extruder == 0 && f.s.temperature_c == 190 && !f.s.wait && before_second_switch);
    }
    EXPECT_TRUE(t1_final);
    EXPECT_TRUE(t0_preheat);
}

// machine_min_cool_heat_time_window longer than the idle time: the extruder left keeps the temperature
// it needs when it comes back (T0, left on layer 0, starts again at 190 °C on layer 1).
TEST(SwitchTemperatures, ShortIdleTimeKeepsTheTemperature) {
    SwitchTemperatureParams p = params();
    p.trains[0].min_window_s = p.trains[1].min_window_s = 1000;
    PrintPlan plan = takingTurns();
    planSwitchTemperatures(plan, p, 0, {0, 0});
    const std::size_t first_switch = switchAt(plan.layers[0]);
    const PlanStep& standby = plan.layers[0].steps[first_switch + 2];
    EXPECT_EQ(standby.extruder, 0);
    EXPECT_EQ(standby.temperature_c, 190);
}

// An extruder that prints nothing after this layer is switched off when left.
TEST(SwitchTemperatures, ExtruderDoneIsSwitchedOff) {
    SwitchTemperatureParams p = params();
    p.last_layer = {1, 1};
    PrintPlan plan = takingTurns();
    planSwitchTemperatures(plan, p, 0, {0, 0});
    const std::size_t second_switch = switchAt(plan.layers[1]);
    EXPECT_EQ(plan.layers[1].steps[second_switch + 2].extruder, 1);
    EXPECT_EQ(plan.layers[1].steps[second_switch + 2].temperature_c, 0);
}

// One heater: no initial or final temperatures, no standby preheat; the extruder before is set to the
// next one's temperature.
TEST(SwitchTemperatures, SharedHeaterSetsTheNextTemperatureOnTheActiveNozzle) {
    SwitchTemperatureParams p = params();
    p.share_heater = true;
    p.trains[1].nozzle.print_c = 210;
    p.trains[1].nozzle.layer0_c = 0;
    PrintPlan plan = takingTurns();
    planSwitchTemperatures(plan, p, 0, {0, 0});
    for (const Found& f : temperatures(plan)) {
        EXPECT_NE(f.s.temperature_c, 190);
        EXPECT_NE(f.s.temperature_c, 185);
    }
    bool t0_heater_to_210 = false, t1_heater_to_200 = false;
    for (const Found& f : temperatures(plan)) {
        t0_heater_to_210 = t0_heater_to_210 || (f.layer == 0 && f.step < switchAt(plan.layers[0]) &&
                                                f.s.extruder == 0 && f.s.temperature_c == 210);
        t1_heater_to_200 = t1_heater_to_200 || (f.layer == 1 && f.step < switchAt(plan.layers[1]) &&
                                                f.s.extruder == 1 && f.s.temperature_c == 200);
    }
    EXPECT_TRUE(t0_heater_to_210);
    EXPECT_TRUE(t1_heater_to_200);
    EXPECT_EQ(plan.layers[0].steps[switchAt(plan.layers[0]) + 1].temperature_c, 210);
}

}  // namespace
}  // namespace mixengine
