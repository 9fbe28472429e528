// A whole mesh group (toolpaths/GroupToolpaths.h): several meshes and extruders, support, prime
// tower, ooze shield and adhesion, with fdmprinter's settings.
#include "toolpaths/GroupToolpaths.h"

#include <gtest/gtest.h>

#include <set>

#include "ToolpathTestSupport.h"
#include "toolpaths/PolygonOps.h"

namespace mixengine {
namespace {

using test::rect;
using test::square;

struct Group {
    ResolvedMachine machine;
    std::vector<Settings> meshes;
    test::Stack a, b;
    GroupToolpaths paths;
};

/// Two 10 mm square prisms of 30 layers at x = 50 and 70 mm, printed by extruders 0 and 1.
Group twoMeshes(const SettingValues& user) {
    Group g;
    SettingValues values{{"machine_extruder_count", "2"}, {"adhesion_type", "none"}};
    for (const auto& [k, v] : user)
        values[k] = v;
    g.machine = test::fdmMachine(values, {{1, {}}});
    g.meshes = {g.machine.global.with("a", {{"extruder_nr", "0"}}),
                g.machine.global.with("b", {{"extruder_nr", "1"}})};
    g.a = test::prismStack(30);
    g.b = test::prismStack(30);
    test::fill(g.a, 0, 30, {square(50'000, 50'000, 10'000)});
    test::fill(g.b, 0, 30, {square(70'000, 50'000, 10'000)});
    ToolpathInput in{&g.machine.global, &g.machine.extruders, g.a.heights, {}};
    in.meshes.push_back({&g.meshes[0], "a", &g.a.layers});
    in.meshes.push_back({&g.meshes[1], "b", &g.b.layers});
    g.paths = generateGroupToolpaths(in, 2);
    return g;
}

Paths pointsOf(const std::vector<ExtrusionPath>& paths) {
    Paths points;
    for (const ExtrusionPath& p : paths)
        points.push_back(p.points);
    return points;
}

std::set<int> extrudersOf(const std::vector<ExtrusionPath>& paths) {
    std::set<int> used;
    for (const ExtrusionPath& p : paths)
        used.insert(p.extruder);
    return used;
}

TEST(GroupToolpaths, EachMeshPrintsWithItsExtruder) {
    const Group g = twoMeshes({});
    ASSERT_EQ(g.paths.meshes.size(), 2U);
    EXPECT_EQ(g.paths.meshes[1].name, "b");
    const MeshLayerGroups& b = g.paths.meshes[1].layers[10];
    EXPECT_EQ(extrudersOf(b.outer_walls), (std::set<int>{1}));
    EXPECT_EQ(extrudersOf(b.infill), (std::set<int>{1}));
    EXPECT_EQ(extrudersOf(g.paths.meshes[0].layers[10].outer_walls), (std::set<int>{0}));
    EXPECT_TRUE(g.paths.adhesion.empty());
    EXPECT_TRUE(g.paths.prime_tower[5].empty());  // no tower unless enabled
}

TEST(GroupToolpaths, PrimeTowerRingsPerExtruder) {
    const Group g = twoMeshes({{"prime_tower_enable", "True"},
                               {"prime_tower_size", "20"},
                               {"prime_tower_position_x", "150"},
                               {"prime_tower_position_y", "100"},
                               {"prime_tower_min_volume", "6"}});
    ASSERT_EQ(g.paths.prime_tower.size(), 30U);
    for (int layer : {1, 15, 29}) {
        const std::vector<ExtrusionPath>& tower = g.paths.prime_tower[layer];
        // 0.1 mm layers: a ring of ~60 mm holds 2.4 mm³, so three per extruder, outer ones for T0.
        ASSERT_EQ(tower.size(), 6U) << layer;
        for (std::size_t i = 0; i < 6; ++i) {
            EXPECT_EQ(tower[i].extruder, i < 3 ? 0 : 1) << layer;
            EXPECT_EQ(tower[i].feature, Feature::PrimeTower);
        }
        // Centred at (150 − 10, 100 + 10) mm.
        const ClipperLib::IntRect box = boundsOf({tower[0].points});
        EXPECT_NEAR((box.left + box.right) / 2.0, 140'000, 2);
        EXPECT_NEAR((box.top + box.bottom) / 2.0, 110'000, 2);
        EXPECT_NEAR(box.right - box.left, 19'600, 2);
    }
    // Layer 0: T0 fills the whole disc with loops 0.4 mm apart (24 or 25 of them), T1 prints none.
    EXPECT_GE(g.paths.prime_tower[0].size(), 24U);
    for (const ExtrusionPath& p : g.paths.prime_tower[0])
        EXPECT_EQ(p.extruder, 0);
}

TEST(GroupToolpaths, OozeShieldAroundBothMeshes) {
    const Group g = twoMeshes({{"ooze_shield_enabled", "True"}, {"ooze_shield_dist", "2"}});
    for (int layer : {0, 12, 29}) {
        ASSERT_EQ(g.paths.ooze_shield[layer].size(), 2U) << layer;  // the meshes are 10 mm apart
        const ClipperLib::IntRect box = boundsOf({g.paths.ooze_shield[layer][0].points});
        EXPECT_EQ(box.right - box.left, 14'000) << layer;
        EXPECT_EQ(g.paths.ooze_shield[layer][0].extruder, 0);
    }
}

TEST(GroupToolpaths, SupportAndBrimForATee) {
    ResolvedMachine m = test::fdmMachine({{"support_enable", "True"},
                                          {"support_pattern", "lines"},
                                          {"adhesion_type", "brim"},
                                          {"brim_line_count", "3"},
                                          {"skirt_brim_minimal_length", "0"}});
    test::Stack s = test::prismStack(60);
    test::fill(s, 0, 50, {rect(50'000, 50'000, 60'000, 60'000)});
    test::fill(s, 50, 60, {rect(40'000, 50'000, 70'000, 60'000)});
    ToolpathInput in{&m.global, &m.extruders, s.heights, {{&m.global, "tee", &s.layers}}};
    const GroupToolpaths g = generateGroupToolpaths(in, 2);
    const Paths stem{rect(50'000 - 699, 50'000 - 699, 60'000 + 699, 60'000 + 699)};
    for (int i = 0; i < 60; ++i) {
        EXPECT_EQ(!g.support[i].empty(), i < 49) << i;
        for (const ExtrusionPath& p : g.support[i]) {
            EXPECT_EQ(p.feature, Feature::Support);
            EXPECT_TRUE(clipLines({p.points}, stem).empty()) << i;  // never inside the model
        }
    }
    // The brim goes around the stem and the support on layer 0 (0.7 mm apart: the first ring is
    // three loops, the next ones merge): its outermost loop lies 1 mm out of x = 40 … 70 mm.
    ASSERT_EQ(g.adhesion.size(), 5U);
    const ClipperLib::IntRect box = boundsOf({g.adhesion.front().points});
    EXPECT_EQ(box.left, 40'000 - 1'000);
    EXPECT_EQ(box.right, 70'000 + 1'000);
}

TEST(GroupToolpaths, EmptyBottomLayersAreDroppedAndThePrintStartsAtTheFirstHeight) {
    ResolvedMachine m = test::fdmMachine({{"adhesion_type", "none"}});
    test::Stack s = test::prismStack(30);
    test::fill(s, 3, 30, {square(50'000, 50'000, 10'000)});
    ToolpathInput in{&m.global, &m.extruders, s.heights, {{&m.global, "late", &s.layers}}};
    const GroupToolpaths g = generateGroupToolpaths(in, 2);
    EXPECT_EQ(g.first_sliced_layer, 3U);
    ASSERT_EQ(g.heights.size(), 27U);
    EXPECT_EQ(g.heights.front().print_z, s.heights.front().print_z);
    EXPECT_EQ(g.heights.back().print_z, s.heights[26].print_z);
    EXPECT_EQ(g.meshes[0].layers.size(), 27U);
    EXPECT_FALSE(g.meshes[0].layers[0].outer_walls.empty());
    EXPECT_EQ(g.meshes[0].sliced, &s.layers);
    EXPECT_EQ(g.notes, std::vector<std::string>{"removing 3 empty layer(s) at the bottom of the print"});
}

TEST(GroupToolpaths, TheSkirtGoesAroundTheFirstLayerThatPrints) {
    // Layers 0–1 and 28–29 empty (as slicing_tolerance exclusive leaves the last one): the skirt
    // surrounds the square on what becomes layer 0; the empty top layers stay (the writer writes
    // nothing for them, gcode/PlanWriter.h).
    ResolvedMachine m = test::fdmMachine({{"adhesion_type", "skirt"}});
    test::Stack s = test::prismStack(30);
    test::fill(s, 2, 28, {square(50'000, 50'000, 10'000)});
    ToolpathInput in{&m.global, &m.extruders, s.heights, {{&m.global, "middle", &s.layers}}};
    const GroupToolpaths g = generateGroupToolpaths(in, 2);
    EXPECT_EQ(g.first_sliced_layer, 2U);
    ASSERT_EQ(g.heights.size(), 28U);
    EXPECT_EQ(g.meshes[0].layers.size(), 28U);
    EXPECT_FALSE(g.meshes[0].layers[25].outer_walls.empty());
    EXPECT_TRUE(g.meshes[0].layers.back().outer_walls.empty());
    ASSERT_FALSE(g.adhesion.empty());
    const ClipperLib::IntRect box = boundsOf(pointsOf(g.adhesion));
    EXPECT_LT(box.left, 50'000);
    EXPECT_GT(box.right, 60'000);
}

TEST(GroupToolpaths, NothingToPrintDropsEveryLayer) {
    ResolvedMachine m = test::fdmMachine({{"adhesion_type", "none"}});
    test::Stack s = test::prismStack(5);
    ToolpathInput in{&m.global, &m.extruders, s.heights, {{&m.global, "empty", &s.layers}}};
    const GroupToolpaths g = generateGroupToolpaths(in, 2);
    EXPECT_TRUE(g.heights.empty());
    EXPECT_EQ(g.first_sliced_layer, 5U);
}

}  // namespace
}  // namespace mixengine
