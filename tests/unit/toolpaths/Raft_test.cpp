// The raft (toolpaths/adhesion/RaftLayout.h, toolpaths/adhesion/Raft.h): its layers' numbers and heights, the
// model's lift, the outline and the lines of each raft layer, with the Ender-3's raft values (the numbers
// CuraEngine 4.13 prints for them: layers −6 … −3 at z 0.24, 0.54, 0.74, 0.94 mm, filler layers at
// 1.115 and 1.29 mm, the model's layer 0 at 1.44 mm and layer 1 at 1.49 mm).
#include "toolpaths/adhesion/Raft.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::square;

SettingValues enderRaft() {
    return {{"adhesion_type", "raft"},
            {"layer_height", "0.2"},
            {"layer_height_0", "0.2"},
            {"raft_base_thickness", "0.24"},
            {"raft_interface_thickness", "0.3"},
            {"raft_surface_thickness", "0.2"},
            {"raft_surface_layers", "2"},
            {"raft_airgap", "0.3"},
            {"layer_0_z_overlap", "0.15"},
            {"raft_margin", "15"},
            {"raft_smoothing", "5"},
            {"raft_base_line_width", "0.8"},
            {"raft_base_line_spacing", "1.6"},
            {"raft_interface_line_width", "0.8"},
            {"raft_interface_line_spacing", "1.0"},
            {"raft_surface_line_width", "0.4"},
            {"raft_surface_line_spacing", "0.4"},
            {"raft_base_speed", "18.75"},
            {"raft_interface_speed", "20"},
            {"raft_surface_speed", "25"},
            {"raft_base_fan_speed", "0"},
            {"raft_interface_fan_speed", "50"},
            {"raft_surface_fan_speed", "100"}};
}

TEST(RaftLayout, LayersHeightsAndLiftAsCuraEngine) {
    const ResolvedMachine m = test::fdmMachine(enderRaft());
    const RaftLayout layout = raftLayout(m.global, &m.extruders);
    ASSERT_TRUE(layout.enabled);
    EXPECT_EQ(layout.totalThicknessUm(), 940);  // 0.24 + 0.3 + 2 × 0.2
    EXPECT_EQ(layout.gapUm(), 350);             // 0.3 + 0.2 − 0.15
    EXPECT_EQ(layout.fillerLayerCount(), 2);    // 350 / 200 rounded
    EXPECT_EQ(layout.fillerLayerHeightUm(), 175);
    EXPECT_EQ(layout.extraLayerCount(), 6);  // the base is layer −6
    EXPECT_EQ(layout.modelLiftUm(0), 1240);  // layer 0 at 0.2 + 1.24 = 1.44 mm
    EXPECT_EQ(layout.modelLiftUm(1), 1090);  // layer 1 at 0.4 + 1.09 = 1.49 mm
    EXPECT_EQ(layout.modelLiftUm(7), 1090);
}

TEST(RaftLayout, NothingWithoutARaft) {
    SettingValues values = enderRaft();
    values["adhesion_type"] = "brim";
    const ResolvedMachine m = test::fdmMachine(values);
    const RaftLayout layout = raftLayout(m.global, &m.extruders);
    EXPECT_FALSE(layout.enabled);
    EXPECT_EQ(layout.extraLayerCount(), 0);
    EXPECT_EQ(layout.modelLiftUm(0), 0);
    EXPECT_EQ(layout.totalThicknessUm(), 0);
}

TEST(RaftLayout, NoAirGapNoFillerLayers) {
    SettingValues values = enderRaft();
    values["raft_airgap"] = "0";
    values["layer_0_z_overlap"] = "0.2";
    const ResolvedMachine m = test::fdmMachine(values);
    const RaftLayout layout = raftLayout(m.global, &m.extruders);
    EXPECT_EQ(layout.gapUm(), 0);
    EXPECT_EQ(layout.fillerLayerCount(), 0);
    EXPECT_EQ(layout.extraLayerCount(), 4);
    EXPECT_EQ(layout.modelLiftUm(0), 940);
    EXPECT_EQ(layout.modelLiftUm(1), 740);
}

TEST(Raft, OutlineIsTheMarginAroundTheFirstLayerClosedBySmoothing) {
    // Two 10 mm squares 3 mm apart: a 1 mm margin around each leaves a 1 mm gap between them, which a
    // 2 mm smoothing closes (grown by 2 mm and shrunk back); the outer extent stays the margin's.
    const Paths first{square(0, 0, 10'000), square(13'000, 0, 10'000)};
    const Paths rough = raftOutline(first, 1'000, 0);
    const Paths smooth = raftOutline(first, 1'000, 2'000);
    EXPECT_EQ(rough.size(), 2U);
    ASSERT_EQ(smooth.size(), 1U);
    const Paths across{{{11'500, 4'000}, {11'500, 6'000}}};  // in the gap, 1.5 mm from each square
    EXPECT_TRUE(clipLines(across, rough).empty());
    EXPECT_FALSE(clipLines(across, smooth).empty());
    const ClipperLib::IntRect box = boundsOf(smooth);
    EXPECT_EQ(box.left, -1'000);
    EXPECT_EQ(box.right, 24'000);
    const double filled = areaUm2(smooth) - areaUm2(rough);  // the 1 mm wide gap, less its rounded ends
    EXPECT_GT(filled, 1'000.0 * 8'000);
    EXPECT_LT(filled, 1'000.0 * 12'000);
}

/// The direction (degrees in [0, 180)) of the longest segment of a layer's paths.
double mainDirection(const RaftLayer& layer) {
    double length = 0, angle = -1;
    for (const ExtrusionPath& p : layer.paths) {
        for (std::size_t i = 1; i < p.points.size(); ++i) {
            const double dx = double(p.points[i].X - p.points[i - 1].X);
            const double dy = double(p.points[i].Y - p.points[i - 1].Y);
            if (std::hypot(dx, dy) > length) {
                length = std::hypot(dx, dy);
                angle = std::fmod(std::atan2(dy, dx) * 180.0 / M_PI + 360.0, 180.0);
            }
        }
    }
    return angle;
}

TEST(Raft, BaseInterfaceAndSurfaceLayersAsCuraEnginePrintsThem) {
    const ResolvedMachine m = test::fdmMachine(enderRaft());
    const RaftToolpaths raft = generateRaft({&m.global, &m.extruders, {square(100'000, 100'000, 20'000)}});
    ASSERT_EQ(raft.layers.size(), 4U);
    const ClipperLib::IntRect box = boundsOf(raft.outline);
    EXPECT_EQ(box.left, 85'000);  // 15 mm margin
    EXPECT_EQ(box.right, 135'000);

    const RaftLayer& base = raft.layers[0];
    EXPECT_EQ(base.index, -6);
    EXPECT_EQ(base.z_um, 240);
    EXPECT_EQ(base.thickness_um, 240);
    EXPECT_DOUBLE_EQ(base.fan_ratio, 0.0);
    ASSERT_FALSE(base.paths.empty());
    EXPECT_TRUE(base.paths[0].closed);  // the loop 0.4 mm inside the outline
    EXPECT_EQ(boundsOf({base.paths[0].points}).left, 85'400);
    std::set<coord_um> xs;
    for (std::size_t i = 1; i < base.paths.size(); ++i) {
        const ExtrusionPath& line = base.paths[i];
        EXPECT_FALSE(line.closed);
        EXPECT_EQ(line.points.front().X, line.points.back().X);  // along Y
        EXPECT_EQ(line.points.front().X % 1'600, 0);             // on the plate's 1.6 mm grid
        xs.insert(line.points.front().X);
        EXPECT_EQ(line.feature, Feature::RaftBase);
        EXPECT_EQ(line.width_um, 800);
        EXPECT_DOUBLE_EQ(line.speed_mm_s, 18.75);
        EXPECT_DOUBLE_EQ(line.flow, 1.0);
    }
    EXPECT_EQ(xs.size(), 31U);  // 86.4 … 134.4 mm

    const RaftLayer& interface = raft.layers[1];
    EXPECT_EQ(interface.index, -5);
    EXPECT_EQ(interface.z_um, 540);
    EXPECT_DOUBLE_EQ(interface.fan_ratio, 0.5);
    for (const ExtrusionPath& p : interface.paths) {
        EXPECT_EQ(p.feature, Feature::RaftInterface);
        EXPECT_DOUBLE_EQ(p.speed_mm_s, 20);
    }
    const RaftLayer& surface_1 = raft.layers[2];
    const RaftLayer& surface_2 = raft.layers[3];
    EXPECT_EQ(surface_1.z_um, 740);
    EXPECT_EQ(surface_2.z_um, 940);
    EXPECT_EQ(surface_2.index, -3);
    EXPECT_DOUBLE_EQ(surface_2.fan_ratio, 1.0);
    // Zigzag: each polyline runs mostly along its lines — 45° on the interface, then 90° (along X)
    // and 180° (along Y) on the surface layers.
    EXPECT_NEAR(std::fmod(mainDirection(interface), 90.0), 45.0, 0.5);
    EXPECT_NEAR(std::fmod(mainDirection(surface_1) + 90.0, 180.0), 90.0, 0.5);  // along X
    EXPECT_NEAR(mainDirection(surface_2), 90.0, 0.5);                           // along Y
    EXPECT_NEAR(test::totalLength(surface_1.paths), test::totalLength(surface_2.paths),
                0.01 * test::totalLength(surface_1.paths));
    // A full surface: 0.4 mm lines 0.4 mm apart cover the outline shrunk by half a line.
    const double area = areaUm2(offsetMiter(raft.outline, -200));
    EXPECT_NEAR(test::totalLength(surface_1.paths) * 400.0, area, 0.03 * area);
}

TEST(Raft, NoRaftForOtherAdhesionOrAnEmptyFirstLayer) {
    SettingValues values = enderRaft();
    const ResolvedMachine raft = test::fdmMachine(values);
    EXPECT_TRUE(generateRaft({&raft.global, &raft.extruders, {}}).layers.empty());
    values["adhesion_type"] = "skirt";
    const ResolvedMachine skirt = test::fdmMachine(values);
    EXPECT_TRUE(generateRaft({&skirt.global, &skirt.extruders, {square(0, 0, 10'000)}}).layers.empty());
}

}  // namespace
}  // namespace mixengine
