// Planning a two-extruder group (planning/PrintPlanner.h): the prime tower printed as CuraEngine does
// (an extruder's rings when it is switched to on the layer, the outermost extruder's on every layer), the
// wipe over the tower, the travel to the end position before a switch, the Prime step at the first use
// of an extruder and the temperature steps around each switch.
#include <gtest/gtest.h>

#include <memory>
#include <set>

#include "../toolpaths/ToolpathTestSupport.h"
#include "planning/PrintPlanner.h"
#include "toolpaths/GroupToolpaths.h"

namespace mixengine {
namespace {

struct Dual {
    ResolvedMachine machine;
    std::vector<Settings> meshes;
    test::Stack a, b;
    GroupToolpaths toolpaths;
    PrintPlan plan;
};

/// Two 10 mm square prisms of 10 layers printed by extruders 0 and 1, a 20 mm prime tower at
/// (150, 100) mm, extruder end positions absolute at (200, 10) mm with a 22 mm nozzle offset for T1.
std::unique_ptr<Dual> dual() {
    auto d = std::make_unique<Dual>();
    const SettingValues train{{"machine_extruder_end_pos_abs", "True"},
                              {"machine_extruder_end_pos_x", "200"},
                              {"machine_extruder_end_pos_y", "10"}};
    SettingValues train1 = train;
    train1["machine_nozzle_offset_x"] = "22";
    d->machine = test::fdmMachine({{"machine_extruder_count", "2"},
                                   {"adhesion_type", "none"},
                                   {"prime_tower_enable", "True"},
                                   {"prime_tower_brim_enable", "False"},
                                   {"prime_tower_size", "20"},
                                   {"prime_tower_position_x", "150"},
                                   {"prime_tower_position_y", "100"}},
                                  {{0, train}, {1, train1}});
    d->meshes = {d->machine.global.with("a", {{"extruder_nr", "0"}}),
                 d->machine.global.with("b", {{"extruder_nr", "1"}})};
    d->a = test::prismStack(10);
    d->b = test::prismStack(10);
    test::fill(d->a, 0, 10, {test::square(50'000, 50'000, 10'000)});
    test::fill(d->b, 0, 10, {test::square(70'000, 50'000, 10'000)});
    ToolpathInput in{&d->machine.global, &d->machine.extruders, d->a.heights, {}, {}};
    in.meshes.push_back({&d->meshes[0], "a", &d->a.layers, std::nullopt, {}});
    in.meshes.push_back({&d->meshes[1], "b", &d->b.layers, std::nullopt, {}});
    d->toolpaths = generateGroupToolpaths(in, 2);
    PlannerState state;
    d->plan = planPrint(d->toolpaths, d->machine.global, d->machine.extruders, state);
    return d;
}

/// The extruders that print prime tower lines on a layer, in order.
std::vector<int> towerPrinters(const PlannedLayer& layer, int extruder) {
    std::vector<int> out;
    bool tower = false;
    for (const PlanStep& s : layer.steps) {
        if (s.kind == PlanStep::Kind::SetExtruder)
            extruder = s.extruder;
        if (s.kind == PlanStep::Kind::SetFeature)
            tower = s.feature == Feature::PrimeTower;
        if (s.kind == PlanStep::Kind::Extrude && tower && (out.empty() || out.back() != extruder))
            out.push_back(extruder);
    }
    return out;
}

TEST(DualPlanning, TowerRingsWhenSwitchedToAndAlwaysForTheOutermost) {
    const auto d = dual();
    ASSERT_EQ(d->plan.layers.size(), 10U);
    // Layer 0: T0 then T1, only T0's filled disc. Odd layers start with T1 (no switch: no rings of its
    // own) and switch to T0 (outermost: rings); even layers start with T0 (rings) and switch to T1 (rings).
    EXPECT_EQ(towerPrinters(d->plan.layers[0], 0), std::vector<int>{0});
    EXPECT_EQ(towerPrinters(d->plan.layers[1], 1), std::vector<int>{0});
    EXPECT_EQ(towerPrinters(d->plan.layers[2], 0), (std::vector<int>{0, 1}));
}

TEST(DualPlanning, EndPositionTravelPrimeOnFirstUseAndWaitAfterEachSwitch) {
    const auto d = dual();
    int primes = 0;
    for (const PlannedLayer& layer : d->plan.layers) {
        const std::vector<PlanStep>& s = layer.steps;
        for (std::size_t i = 1; i + 1 < s.size(); ++i) {
            if (s[i].kind == PlanStep::Kind::Prime)
                ++primes;
            if (s[i].kind != PlanStep::Kind::SetExtruder)
                continue;
            // Before: the old extruder's end position (200, 10) mm plus its nozzle offset.
            ASSERT_EQ(s[i - 1].kind, PlanStep::Kind::Travel);
            const coord_um offset = s[i].extruder == 1 ? 0 : 22'000;
            EXPECT_EQ(s[i - 1].to, (Point2{200'000 + offset, 10'000}));
            // After: M109 for the new extruder (Prime after it on its first use).
            ASSERT_EQ(s[i + 1].kind, PlanStep::Kind::SetNozzleTemperature);
            EXPECT_TRUE(s[i + 1].wait);
            EXPECT_EQ(s[i + 1].extruder, s[i].extruder);
        }
    }
    EXPECT_EQ(primes, 1);  // T1 once; T0 is primed by the start code
}

TEST(DualPlanning, WipeOverTheTowerMiddleAfterTheRingsOfASwitch) {
    const auto d = dual();
    // Layer 2: T1 is switched to and prints its rings, then travels to the tower's middle seen from
    // T0's nozzle: (140, 110) mm − T0's offset + T1's.
    const std::vector<PlanStep>& s = d->plan.layers[2].steps;
    bool t1 = false, tower = false, wiped = false;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        t1 = t1 || (s[i].kind == PlanStep::Kind::SetExtruder && s[i].extruder == 1);
        if (s[i].kind == PlanStep::Kind::SetFeature)
            tower = s[i].feature == Feature::PrimeTower;
        if (t1 && tower && s[i].kind == PlanStep::Kind::Extrude && s[i + 1].kind == PlanStep::Kind::Travel &&
            s[i + 1].to == Point2{162'000, 110'000})
            wiped = true;
    }
    EXPECT_TRUE(wiped);
}

}  // namespace
}  // namespace mixengine
