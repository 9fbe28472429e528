// The mixing stage (mixing/MixingPass.h): every extrusion step gets the mix of its mesh's schedule
// at the layer height, per mesh height and settings; non-mesh steps use the group; single mode
// leaves the plan alone; the chamber delay shifts mixes earlier.
#include "mixing/MixingPass.h"

#include <gtest/gtest.h>

#include "../SettingsTestSupport.h"

#include <list>
#include <sstream>
#include <tuple>
#include <utility>

#include "common/Error.h"
#include "mixing/color/KubelkaMunk.h"

namespace mixengine {
namespace {

/// A MixingGroup with the settings it points at.
class TestGroup {
  public:
    explicit TestGroup(const SettingValues& values) : group_settings_(test::defaultsWith("global", values)) {
        group_.settings = &group_settings_;
    }
    void addMesh(coord_um bottom_um, coord_um top_um, SettingValues values) {
        mesh_settings_.push_back(group_settings_.with("mesh", values));
        group_.meshes.push_back({&mesh_settings_.back(), "mesh", bottom_um, top_um});
    }
    const MixingGroup& group() const { return group_; }

  private:
    Settings group_settings_;
    std::list<Settings> mesh_settings_;  // stable addresses
    MixingGroup group_;
};

PlanStep extrusion(double volume_mm3) {
    PlanStep s;
    s.kind = PlanStep::Kind::Extrude;
    s.volume_mm3 = volume_mm3;
    return s;
}

PlanStep meshMarker(int mesh) {
    PlanStep s;
    s.kind = PlanStep::Kind::SetMesh;
    s.mesh_index = mesh;
    return s;
}

/// Layers at 2, 4, …, 20 mm; in each: one non-mesh extrusion, then one per mesh.
PrintPlan tenLayers(int meshes) {
    PrintPlan plan;
    for (int i = 1; i <= 10; ++i) {
        PlannedLayer layer;
        layer.index = i - 1;
        layer.z = 2000 * i;
        layer.steps.push_back(extrusion(1.0));
        for (int m = 0; m < meshes; ++m) {
            layer.steps.push_back(meshMarker(m));
            layer.steps.push_back(extrusion(1.0));
        }
        plan.layers.push_back(layer);
    }
    return plan;
}

double shareB(const PrintPlan& plan, int layer, int step) {
    const PlanStep& s = plan.layers[static_cast<std::size_t>(layer)].steps[static_cast<std::size_t>(step)];
    EXPECT_GE(s.mix, 0);
    return plan.mixes[static_cast<std::size_t>(s.mix)][1];
}

TEST(MixingPass, SingleModeLeavesThePlanAlone) {
    TestGroup group(SettingValues{});
    group.addMesh(0, 20000, {});
    PrintPlan plan = tenLayers(1);
    std::ostringstream err;
    Log log(err);
    assignMixes(plan, group.group(), log);
    EXPECT_TRUE(plan.mixes.empty());
    for (const PlannedLayer& l : plan.layers)
        for (const PlanStep& s : l.steps)
            EXPECT_EQ(s.mix, -1);
}

TEST(MixingPass, EachMeshFollowsItsOwnHeightAndSettings) {
    TestGroup group(SettingValues{{"mixing_mode", "gradient"}});
    // Mesh 0: 0..20 mm, the seed's 20/80. Mesh 1: 0..10 mm, whole height. Mesh 2: 10 mm in mm units
    // from its bottom at 4 mm.
    group.addMesh(
        0, 20000,
        {{"mixing_mode", "gradient"}, {"mixing_gradient_start", "20"}, {"mixing_gradient_end", "80"}});
    group.addMesh(0, 10000, {{"mixing_mode", "gradient"}});
    group.addMesh(4000, 14000,
                  {{"mixing_mode", "gradient"},
                   {"mixing_gradient_unit", "mm"},
                   {"mixing_gradient_start", "2"},
                   {"mixing_gradient_end", "6"}});
    PrintPlan plan = tenLayers(3);
    std::ostringstream err;
    Log log(err);
    assignMixes(plan, group.group(), log);
    // Layer 4 (z = 10 mm): mesh 0 at 50 % → (50 − 20) / 60; mesh 1 at 100 %; mesh 2 at 6 mm above
    // its bottom → its end; non-mesh over 0..20 mm at 50 % with the group's 0..100 → 0.5.
    EXPECT_DOUBLE_EQ(shareB(plan, 4, 0), 0.5);
    EXPECT_DOUBLE_EQ(shareB(plan, 4, 2), 0.5);
    EXPECT_DOUBLE_EQ(shareB(plan, 4, 4), 1.0);
    EXPECT_DOUBLE_EQ(shareB(plan, 4, 6), 1.0);
    // Layer 1 (z = 4 mm): mesh 0 at 20 % → A only; mesh 1 at 40 %; mesh 2 at its bottom → A only.
    EXPECT_EQ(shareB(plan, 1, 2), 0.0);
    EXPECT_DOUBLE_EQ(shareB(plan, 1, 4), 0.4);
    EXPECT_EQ(shareB(plan, 1, 6), 0.0);
    // Layer 2 (z = 6 mm): mesh 2 is 2 mm above its bottom = its start; layer 3 (8 mm): half way.
    EXPECT_EQ(shareB(plan, 2, 6), 0.0);
    EXPECT_DOUBLE_EQ(shareB(plan, 3, 6), 0.5);
    // Mixes are stored once each.
    for (std::size_t i = 0; i < plan.mixes.size(); ++i)
        for (std::size_t j = i + 1; j < plan.mixes.size(); ++j)
            EXPECT_FALSE(plan.mixes[i] == plan.mixes[j]);
}

TEST(MixingPass, DualModeFixedRatioPerMesh) {
    TestGroup group(SettingValues{{"mixing_mode", "dual"}});
    group.addMesh(0, 20000, {{"mixing_mode", "dual"}, {"mixing_ratio", "0.3:0.7"}});
    group.addMesh(0, 20000, {{"mixing_mode", "dual"}, {"mixing_ratio", "1:0"}});
    PrintPlan plan = tenLayers(2);
    std::ostringstream err;
    Log log(err);
    assignMixes(plan, group.group(), log);
    for (int layer = 0; layer < 10; ++layer) {
        EXPECT_DOUBLE_EQ(shareB(plan, layer, 0), 0.5);  // non-mesh: the group's default 0.5:0.5
        EXPECT_DOUBLE_EQ(shareB(plan, layer, 2), 0.7);
        EXPECT_EQ(shareB(plan, layer, 4), 0.0);
    }
    EXPECT_EQ(plan.mixes.size(), 3u);
}

TEST(MixingPass, ColorModeSolvesEachMeshsTargetAndWarnsOnceOutOfGamut) {
    const SettingValues global{{"mixing_mode", "color"}, {"mixing_channel_colors", "#ffff00,#0000ff"}};
    const PigmentModel model({Rgb{255, 255, 0}, Rgb{0, 0, 255}});
    MixVector quarter = MixVector::only(0, 2);
    quarter[0] = 0.75;
    quarter[1] = 0.25;
    const std::string in_gamut = hexOf(model.predictRgb(quarter));
    TestGroup group(global);
    SettingValues first = global, second = global;
    first["mixing_target_color"] = in_gamut;
    second["mixing_target_color"] = "#ff0000";  // red: no yellow/blue mix comes near
    group.addMesh(0, 20000, first);
    group.addMesh(0, 20000, second);
    PrintPlan plan = tenLayers(2);
    std::ostringstream err;
    Log log(err);
    assignMixes(plan, group.group(), log);
    for (int layer = 0; layer < 10; ++layer)
        EXPECT_NEAR(shareB(plan, layer, 2), 0.25, 0.01) << in_gamut;
    const std::string text = err.str();
    const auto first_warning = text.find("[warning]");
    ASSERT_NE(first_warning, std::string::npos) << text;
    EXPECT_EQ(text.find("[warning]", first_warning + 1), std::string::npos) << text;
    EXPECT_NE(text.find("[warning] mixing: 'mesh': target colour #ff0000 is outside the gamut"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("(dE00 "), std::string::npos) << text;
}

TEST(MixingPass, ChamberDelayCommandsTheNextLayersMixEarlier) {
    TestGroup group(SettingValues{{"mixing_mode", "gradient"}, {"mixing_chamber_volume", "1.5"}});
    group.addMesh(0, 20000, {{"mixing_mode", "gradient"}});
    PrintPlan plan = tenLayers(1);  // two 1 mm³ extrusions per layer
    std::ostringstream err;
    Log log(err);
    assignMixes(plan, group.group(), log);
    // Extrusion k (midpoint k + 0.5) commands the target at k + 2.0: one layer ahead.
    for (int layer = 0; layer < 9; ++layer) {
        EXPECT_DOUBLE_EQ(shareB(plan, layer, 0), 0.1 * (layer + 2)) << layer;
        EXPECT_DOUBLE_EQ(shareB(plan, layer, 2), 0.1 * (layer + 2)) << layer;
    }
    EXPECT_DOUBLE_EQ(shareB(plan, 9, 2), 1.0);  // past the end: the last target
}

TEST(MixingPass, BadSettingsThrowBeforeAnythingIsWritten) {
    TestGroup group(SettingValues{{"mixing_mode", "dual"}});
    group.addMesh(0, 20000, {{"mixing_mode", "dual"}, {"mixing_ratio", "0.5:0.6"}});
    PrintPlan plan = tenLayers(1);
    std::ostringstream err;
    Log log(err);
    EXPECT_THROW(assignMixes(plan, group.group(), log), InputError);
}

TEST(MixingPass, TheRaftIsPrintedWithTheRaftRatio) {
    // Two raft layers below a mesh (z 0.3 and 0.6 mm, the mesh from 1 to 21 mm): the raft's features take
    // mixing_raft_ratio (filament A by default), the mesh its gradient from its own bottom.
    for (const auto& [raft_ratio, raft_b] : {std::pair<std::string, double>{"", 0.0}, {"0.2:0.8", 0.8}}) {
        SettingValues values{
            {"mixing_mode", "gradient"}, {"mixing_gradient_start", "0"}, {"mixing_gradient_end", "100"}};
        if (!raft_ratio.empty())
            values["mixing_raft_ratio"] = raft_ratio;
        TestGroup group(values);
        group.addMesh(1000, 21000, values);
        PrintPlan plan;
        for (const auto& [index, z, f] :
             {std::tuple{-2, 300, Feature::RaftBase}, std::tuple{-1, 600, Feature::RaftSurface}}) {
            PlannedLayer layer;
            layer.index = index;
            layer.z = z;
            PlanStep feature;
            feature.kind = PlanStep::Kind::SetFeature;
            feature.feature = f;
            layer.steps = {feature, extrusion(1.0)};
            plan.layers.push_back(layer);
        }
        PlannedLayer model;
        model.z = 11000;  // halfway up the mesh
        model.steps = {meshMarker(0), extrusion(1.0)};
        plan.layers.push_back(model);
        std::ostringstream err;
        Log log(err);
        assignMixes(plan, group.group(), log);
        EXPECT_DOUBLE_EQ(shareB(plan, 0, 1), raft_b) << raft_ratio;
        EXPECT_DOUBLE_EQ(shareB(plan, 1, 1), raft_b) << raft_ratio;
        EXPECT_DOUBLE_EQ(shareB(plan, 2, 1), 0.5) << raft_ratio;
    }
}

}  // namespace
}  // namespace mixengine
