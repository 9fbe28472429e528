// Per-feature width, speed, flow and extruder per layer (toolpaths/core/FeatureStyle.h).
#include "toolpaths/core/FeatureStyle.h"

#include <gtest/gtest.h>

#include "../SettingsTestSupport.h"

namespace mixengine {
namespace {

Settings mesh(SettingValues extra = {}) {
    SettingValues v{{"extruder_nr", "1"},
                    {"wall_line_width_0", "0.4"},
                    {"speed_wall_0", "30"},
                    {"wall_0_material_flow", "95"},
                    {"wall_0_extruder_nr", "-1"},
                    {"infill_line_width", "0.5"},
                    {"speed_infill", "80"},
                    {"infill_material_flow", "100"},
                    {"infill_extruder_nr", "0"},
                    {"speed_print_layer_0", "20"},
                    {"speed_slowdown_layers", "4"},
                    {"initial_layer_line_width_factor", "150"},
                    {"material_flow_layer_0", "110"}};
    for (auto& [k, val] : extra)
        v[k] = val;
    return test::defaultsWith("mesh", v);
}

const FeatureKeys kWall{key::wall_line_width_0, key::speed_wall_0, key::wall_0_material_flow,
                        key::wall_0_extruder_nr};
const FeatureKeys kInfill{key::infill_line_width, key::speed_infill, key::infill_material_flow,
                          key::infill_extruder_nr};

TEST(FeatureStyle, FirstLayerWidthSpeedAndFlow) {
    const FeatureStyle s = featureStyle(mesh(), kInfill, 0);
    EXPECT_EQ(s.width_um, 750);  // 0.5 mm × 150 %
    EXPECT_EQ(s.speed_mm_s, 20.0);
    EXPECT_DOUBLE_EQ(s.flow, 1.1);
    EXPECT_EQ(s.extruder, 0);
}

TEST(FeatureStyle, SpeedRampsOverTheSlowdownLayers) {
    // From 20 mm/s on layer 0 to 80 mm/s on layer 4: 35, 50, 65, then 80.
    const double expected[] = {20, 35, 50, 65, 80, 80};
    for (int layer = 0; layer < 6; ++layer)
        EXPECT_DOUBLE_EQ(featureStyle(mesh(), kInfill, layer).speed_mm_s, expected[layer]) << layer;
    EXPECT_EQ(featureStyle(mesh(), kInfill, 1).width_um, 500);
    EXPECT_DOUBLE_EQ(featureStyle(mesh(), kInfill, 1).flow, 1.0);
}

TEST(FeatureStyle, MinusOneMeansTheMeshsExtruder) {
    EXPECT_EQ(featureStyle(mesh(), kWall, 3).extruder, 1);
    EXPECT_DOUBLE_EQ(featureStyle(mesh(), kWall, 3).flow, 0.95);
    EXPECT_EQ(featureStyle(mesh({{"wall_0_extruder_nr", "2"}}), kWall, 3).extruder, 2);
    EXPECT_EQ(ownExtruder(test::defaultsWith("mesh", {})), 0);
}

TEST(FeatureStyle, MeshStylesReadCurasKeys) {
    SettingValues v{{"extruder_nr", "0"}};
    for (const char* k : {"wall_line_width_0", "wall_line_width_x", "skin_line_width", "infill_line_width"})
        v[k] = "0.4";
    for (const char* k : {"speed_wall_0", "speed_wall_x", "speed_topbottom", "speed_infill"})
        v[k] = "50";
    v["speed_wall_0"] = "25";
    v["top_bottom_extruder_nr"] = "1";
    v["roofing_extruder_nr"] = "1";  // its formula: top_bottom_extruder_nr
    const MeshStyles m = meshStyles(test::defaultsWith("mesh", v), 5);
    EXPECT_EQ(m.wall_0.speed_mm_s, 25.0);
    EXPECT_EQ(m.skin.extruder, 1);
    EXPECT_EQ(m.roofing.extruder, 1);
    EXPECT_EQ(m.infill.extruder, 0);
}

TEST(FeatureStyle, LayersBelowTheModelKeepTheFeaturesOwnSpeed) {
    // Raft filler layers (negative): no first-layer speed, width or flow, as CuraEngine.
    const FeatureStyle s = featureStyle(mesh(), kInfill, -2);
    EXPECT_DOUBLE_EQ(s.speed_mm_s, 80);
    EXPECT_EQ(s.width_um, 500);
    EXPECT_DOUBLE_EQ(s.flow, 1.0);
}

}  // namespace
}  // namespace mixengine
