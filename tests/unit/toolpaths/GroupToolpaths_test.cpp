// A whole mesh group (toolpaths/GroupToolpaths.h): several meshes and extruders, support, prime
// tower, ooze shield and adhesion, with fdmprinter's settings.
#include "toolpaths/GroupToolpaths.h"

#include <gtest/gtest.h>

#include <set>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

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
    ToolpathInput in{&g.machine.global, &g.machine.extruders, g.a.heights, {}, {}};
    in.meshes.push_back({&g.meshes[0], "a", &g.a.layers, std::nullopt, {}});
    in.meshes.push_back({&g.meshes[1], "b", &g.b.layers, std::nullopt, {}});
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
        // Centred at (150 − 10, 100 + 10) mm, moved 8 mm towards the origin for its brim (20 lines of
        // 0.4 mm): without adhesion prime_tower_brim_enable resolves to True (Cura's resolve formula).
        const ClipperLib::IntRect box = boundsOf({tower[0].points});
        EXPECT_NEAR((box.left + box.right) / 2.0, 132'000, 2);
        EXPECT_NEAR((box.top + box.bottom) / 2.0, 102'000, 2);
        EXPECT_NEAR(box.right - box.left, 19'600, 2);
    }
    // Layer 0: T0 fills the whole disc with loops 0.4 mm apart (24 or 25 of them), T1 prints none.
    EXPECT_GE(g.paths.prime_tower[0].size(), 24U);
    for (const ExtrusionPath& p : g.paths.prime_tower[0])
        EXPECT_EQ(p.extruder, 0);
    // The tower's brim: 20 loops of T0 around it on layer 0, the outermost 8 mm out (diameter 36 mm);
    // then T1's own lines just outside it until they reach skirt_brim_minimal_length (250 mm: 3 loops).
    ASSERT_EQ(g.paths.adhesion.size(), 23U);
    const ClipperLib::IntRect brim = boundsOf({g.paths.adhesion.front().points});
    EXPECT_NEAR((brim.left + brim.right) / 2.0, 132'000, 2);
    EXPECT_NEAR(brim.right - brim.left, 35'600, 100);
    EXPECT_EQ(g.paths.adhesion.front().feature, Feature::Skirt);
    double t1_mm = 0;
    for (std::size_t i = 0; i < g.paths.adhesion.size(); ++i) {
        const ExtrusionPath& p = g.paths.adhesion[i];
        EXPECT_EQ(p.extruder, i < 20 ? 0 : 1) << i;
        if (p.extruder == 1) {
            EXPECT_GT(boundsOf({p.points}).right - boundsOf({p.points}).left, brim.right - brim.left);
            t1_mm += lengthUm(p.points, true) / 1000.0;
        }
    }
    EXPECT_GE(t1_mm, 250.0);
    EXPECT_LT(t1_mm, 250.0 + 130.0);
    // T0 is outermost and prints its rings on every layer up to the last with both extruders.
    EXPECT_EQ(g.paths.prime_tower_outermost, 0);
    EXPECT_EQ(g.paths.prime_tower_last_forced_layer, 29);
}

TEST(GroupToolpaths, PrimeTowerWithoutItsBrimStaysAndTheModelBrimGoesAroundIt) {
    const Group g = twoMeshes({{"prime_tower_enable", "True"},
                               {"prime_tower_size", "20"},
                               {"prime_tower_position_x", "150"},
                               {"prime_tower_position_y", "100"},
                               {"adhesion_type", "brim"},
                               {"brim_line_count", "2"},
                               {"skirt_brim_minimal_length", "0"}});
    const ClipperLib::IntRect box = boundsOf({g.paths.prime_tower[1].front().points});
    EXPECT_NEAR((box.left + box.right) / 2.0, 140'000, 2);
    EXPECT_NEAR((box.top + box.bottom) / 2.0, 110'000, 2);
    // Brim loops around each mesh and around the tower (as CuraEngine's brim outline includes it).
    bool around_tower = false;
    for (const ExtrusionPath& p : g.paths.adhesion) {
        const ClipperLib::IntRect b = boundsOf({p.points});
        around_tower = around_tower || (b.left < 130'500 && b.right > 149'500 && b.top < 100'500);
    }
    EXPECT_TRUE(around_tower);
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
                                          {"brim_replaces_support", "False"},
                                          {"skirt_brim_minimal_length", "0"}});
    test::Stack s = test::prismStack(60);
    test::fill(s, 0, 50, {rect(50'000, 50'000, 60'000, 60'000)});
    test::fill(s, 50, 60, {rect(40'000, 50'000, 70'000, 60'000)});
    const GroupToolpaths g = test::oneMeshToolpaths(m, s, "tee");
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

TEST(GroupToolpaths, BrimReplacesTheSupportsFirstLayerAroundTheModel) {
    ResolvedMachine m = test::fdmMachine({{"support_enable", "True"},
                                          {"support_pattern", "lines"},
                                          {"adhesion_type", "brim"},
                                          {"brim_line_count", "3"},
                                          {"skirt_brim_minimal_length", "0"}});
    test::Stack s = test::prismStack(60);
    test::fill(s, 0, 50, {rect(50'000, 50'000, 60'000, 60'000)});
    test::fill(s, 50, 60, {rect(40'000, 50'000, 70'000, 60'000)});
    const GroupToolpaths g = test::oneMeshToolpaths(m, s, "tee");
    // 3 lines rounded up to 4 of 0.4 mm: 1.6 mm around the stem (the support reaches to 0.7 mm above).
    const Paths brim_zone{rect(50'000 - 1'599, 50'000 - 1'599, 60'000 + 1'599, 60'000 + 1'599)};
    ASSERT_FALSE(g.support[0].empty());
    for (const ExtrusionPath& p : g.support[0])
        EXPECT_TRUE(clipLines({p.points}, brim_zone).empty());
    // Layer 1 keeps its support next to the stem, where layer 0 has none.
    double on_layer1 = 0;
    for (const ExtrusionPath& p : g.support[1]) {
        for (const Path& piece : clipLines({p.points}, brim_zone))
            on_layer1 += test::polylineLength(piece);
    }
    EXPECT_GT(on_layer1, 0);
    // The brim: around the stem and, apart, around what is left of the support.
    EXPECT_GT(g.adhesion.size(), 5U);
}

TEST(GroupToolpaths, RaftUnderATeeLiftsTheModelAndTakesTheFirstLayersSupport) {
    ResolvedMachine m = test::fdmMachine({{"support_enable", "True"},
                                          {"support_pattern", "lines"},
                                          {"adhesion_type", "raft"},
                                          {"initial_layer_line_width_factor", "150"},
                                          {"speed_support_infill", "40"},
                                          {"speed_print_layer_0", "20"},
                                          {"raft_airgap", "0.3"},
                                          {"layer_0_z_overlap", "0.15"},
                                          {"raft_margin", "5"}});
    test::Stack s = test::prismStack(60);  // 0.3 mm first layer, then 0.1 mm
    test::fill(s, 0, 50, {rect(50'000, 50'000, 60'000, 60'000)});
    test::fill(s, 50, 60, {rect(40'000, 50'000, 70'000, 60'000)});
    const GroupToolpaths g = test::oneMeshToolpaths(m, s, "tee");
    const RaftLayout layout = raftLayout(m.global, &m.extruders);
    EXPECT_TRUE(g.adhesion.empty());  // no skirt or brim under a raft
    EXPECT_TRUE(g.warnings.empty());
    // Raft layers, then the filler layers (0.3 + 0.3 − 0.15 = 0.45 mm: 5 of 0.09 mm) printing the support.
    const int raft_layers = 2 + layout.surface_layers;
    ASSERT_EQ(layout.fillerLayerCount(), 5);
    ASSERT_EQ(g.raft.size(), static_cast<std::size_t>(raft_layers + 5));
    EXPECT_EQ(g.raft.front().index, -layout.extraLayerCount());
    for (int i = 0; i < static_cast<int>(g.raft.size()); ++i)
        EXPECT_EQ(g.raft[static_cast<std::size_t>(i)].index, g.raft.front().index + i);
    const RaftLayer& filler = g.raft.back();
    EXPECT_EQ(filler.index, -1);
    EXPECT_EQ(filler.thickness_um, 90);
    EXPECT_EQ(filler.z_um, layout.totalThicknessUm() + 450);
    EXPECT_LT(filler.fan_ratio, 0);  // cooled as the model's first layer
    ASSERT_FALSE(filler.paths.empty());
    for (const ExtrusionPath& p : filler.paths) {
        EXPECT_EQ(p.feature, Feature::Support);
        EXPECT_EQ(p.width_um, m.global.lengthMicrons(key::support_line_width));  // no first-layer widening
        EXPECT_DOUBLE_EQ(p.speed_mm_s, 40);                                      // no first-layer slow-down
    }
    EXPECT_TRUE(g.support[0].empty());  // the model's first layer prints no support
    EXPECT_FALSE(g.support[1].empty());
    // The raft covers the bar's shadow (the support) with the 5 mm margin.
    const ClipperLib::IntRect box = boundsOf(g.raft_outline);
    EXPECT_NEAR(box.left, 40'000 - 5'000, 1'000);
    EXPECT_NEAR(box.right, 70'000 + 5'000, 1'000);
    // The model is lifted; its layers keep their thickness.
    EXPECT_EQ(g.heights[0].print_z, s.heights[0].print_z + layout.modelLiftUm(0));
    EXPECT_EQ(g.heights[5].print_z, s.heights[5].print_z + layout.modelLiftUm(5));
    EXPECT_EQ(g.heights[5].print_z - g.heights[5].bottom_z, 100);
    EXPECT_EQ(g.heights[0].print_z - g.heights[0].bottom_z, 300);
}

TEST(GroupToolpaths, EmptyBottomLayersAreDroppedAndThePrintStartsAtTheFirstHeight) {
    ResolvedMachine m = test::fdmMachine({{"adhesion_type", "none"}});
    test::Stack s = test::prismStack(30);
    test::fill(s, 3, 30, {square(50'000, 50'000, 10'000)});
    const GroupToolpaths g = test::oneMeshToolpaths(m, s, "late");
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
    const GroupToolpaths g = test::oneMeshToolpaths(m, s, "middle");
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
    const GroupToolpaths g = test::oneMeshToolpaths(m, s, "empty");
    EXPECT_TRUE(g.heights.empty());
    EXPECT_EQ(g.first_sliced_layer, 5U);
}

}  // namespace
}  // namespace mixengine
