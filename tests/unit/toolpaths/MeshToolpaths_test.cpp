// One mesh's toolpaths on every layer (toolpaths/MeshToolpaths.h) with fdmprinter's settings.
#include "toolpaths/MeshToolpaths.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::square;

/// A 20 mm square prism of 30 layers at (10, 10) mm.
test::Stack cube() {
    test::Stack s = test::prismStack(30);
    test::fill(s, 0, 30, {square(10'000, 10'000, 20'000)});
    return s;
}

std::vector<MeshLayerGroups> toolpaths(const SettingValues& user, int threads = 2) {
    SettingValues values{{"top_layers", "3"},
                         {"bottom_layers", "2"},
                         {"initial_bottom_layers", "2"},
                         {"infill_pattern", "grid"},
                         {"infill_sparse_density", "20"},
                         {"z_seam_type", "back"},
                         {"z_seam_x", "0"},
                         {"z_seam_y", "0"}};
    for (const auto& [k, v] : user)
        values[k] = v;
    const ResolvedMachine m = test::fdmMachine(values, {{1, {}}});
    return generateMeshToolpaths(cube().layers, m.global, threads);
}

TEST(MeshToolpaths, WallsSkinAndInfillPerLayer) {
    const std::vector<MeshLayerGroups> layers = toolpaths({});
    ASSERT_EQ(layers.size(), 30U);
    for (int i = 0; i < 30; ++i) {
        const MeshLayerGroups& g = layers[i];
        EXPECT_EQ(g.outer_walls.size(), 1U) << i;
        EXPECT_EQ(g.inner_walls.size(), 1U) << i;
        const bool solid = i < 2 || i >= 27;
        EXPECT_EQ(!g.skin.empty(), solid) << i;
        EXPECT_EQ(!g.infill.empty(), !solid) << i;
    }
    // Grid at 20 %: lines 4 mm apart both ways in the 18.4 mm inner square grown by 0.04 mm: about
    // 2 × 18.48² / 4 mm of line.
    const double length = test::totalLength(layers[10].infill);
    EXPECT_NEAR(length, 2 * 18'480.0 * 18'480.0 / 4'000.0, 0.03 * length);
    // Skin lines one width apart fill the area inside the skin's own loop.
    EXPECT_NEAR(test::totalLength(layers[28].skin), 18'400.0 * 18'400.0 / 400.0, 0.03 * 846'400.0);
}

TEST(MeshToolpaths, SeamAtTheBackPointIsFixed) {
    const std::vector<MeshLayerGroups> layers = toolpaths({{"z_seam_x", "100"}, {"z_seam_y", "200"}});
    for (const MeshLayerGroups& g : layers) {
        ASSERT_FALSE(g.outer_walls.empty());
        EXPECT_TRUE(g.outer_walls[0].fixed_start);
        EXPECT_EQ(g.outer_walls[0].points.front(), (Point2{29'800, 29'800}));
        EXPECT_EQ(g.inner_walls[0].points.front(), (Point2{29'400, 29'400}));
    }
    for (const MeshLayerGroups& g : toolpaths({{"z_seam_type", "shortest"}}))
        EXPECT_FALSE(g.outer_walls[0].fixed_start);
}

TEST(MeshToolpaths, FeatureExtrudersFromTheirKeys) {
    const std::vector<MeshLayerGroups> layers = toolpaths(
        {{"machine_extruder_count", "2"}, {"wall_0_extruder_nr", "1"}, {"infill_extruder_nr", "1"}});
    for (const MeshLayerGroups& g : layers) {
        for (const ExtrusionPath& p : g.outer_walls)
            EXPECT_EQ(p.extruder, 1);
        for (const ExtrusionPath& p : g.inner_walls)
            EXPECT_EQ(p.extruder, 0);
        for (const ExtrusionPath& p : g.skin)
            EXPECT_EQ(p.extruder, 0);
        for (const ExtrusionPath& p : g.infill)
            EXPECT_EQ(p.extruder, 1);
    }
}

TEST(MeshToolpaths, FirstLayerSlowerAndWider) {
    const std::vector<MeshLayerGroups> layers =
        toolpaths({{"initial_layer_line_width_factor", "120"}, {"speed_print_layer_0", "15"}});
    EXPECT_EQ(layers[0].outer_walls[0].width_um, 480);
    EXPECT_EQ(layers[0].outer_walls[0].speed_mm_s, 15.0);
    EXPECT_EQ(layers[5].outer_walls[0].width_um, 400);
    EXPECT_EQ(layers[5].outer_walls[0].speed_mm_s, 30.0);  // speed_wall_0 after the slow-down layers
}

TEST(MeshToolpaths, SameResultOnOneOrTwoThreads) {
    const std::vector<MeshLayerGroups> a = toolpaths({}, 1), b = toolpaths({}, 2);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i].infill.size(), b[i].infill.size());
        for (std::size_t j = 0; j < a[i].infill.size(); ++j)
            EXPECT_EQ(a[i].infill[j].points, b[i].infill[j].points);
    }
}

TEST(MeshToolpaths, NoInfillAtZeroDensity) {
    for (const MeshLayerGroups& g : toolpaths({{"infill_sparse_density", "0"}}))
        EXPECT_TRUE(g.infill.empty());
}

TEST(MeshToolpaths, CombAreaFollowsTheCombingMode) {
    // As CuraEngine 4.13's comb boundary. A 20 mm square with two 0.4 mm walls; layer 29 is top
    // skin all over, layer 15 is infill inside the walls.
    const auto area = [](const std::string& mode, int layer) {
        return toolpaths({{"retraction_combing", mode}})[static_cast<std::size_t>(layer)].comb_area;
    };
    EXPECT_FALSE(area("off", 15).has_value());
    // all: inside the second wall's centre line, 0.6 mm inside the outline.
    const double second_wall = 18'800.0 * 18'800.0;
    ASSERT_TRUE(area("all", 15).has_value());
    EXPECT_NEAR(areaUm2(*area("all", 15)), second_wall, 1e6);
    // noskin: from the outer wall's inner edge (0.4 mm in) to 10 µm inside the innermost wall
    // (0.8 mm in), and the infill: the whole inside of the outer wall on an infill layer.
    const double outer_edge = 19'200.0 * 19'200.0;
    ASSERT_TRUE(area("noskin", 29).has_value());
    EXPECT_NEAR(areaUm2(*area("noskin", 29)), outer_edge - 18'380.0 * 18'380.0, 1e6);
    EXPECT_NEAR(areaUm2(*area("noskin", 15)), outer_edge, 1e6);
    // infill: the infill area only (none on a top layer).
    const double outline = 400e6;
    EXPECT_TRUE(area("infill", 29)->empty());
    EXPECT_GT(areaUm2(*area("infill", 15)), 0.8 * outline);
    EXPECT_LT(areaUm2(*area("infill", 15)), outline);
    // no_outer_surfaces: as "all" less the skin with air above (layer 29), not the skin under it (27).
    EXPECT_NEAR(areaUm2(*area("no_outer_surfaces", 29)), second_wall - 18'400.0 * 18'400.0, 1e6);
    EXPECT_NEAR(areaUm2(*area("no_outer_surfaces", 27)), second_wall, 1e6);
}

TEST(MeshToolpaths, SurfaceModePrintsTheOutlineOnceAsOuterWall) {
    const std::vector<MeshLayerGroups> layers = toolpaths({{"magic_mesh_surface_mode", "surface"}});
    ASSERT_EQ(layers.size(), 30U);
    for (const MeshLayerGroups& g : layers) {
        ASSERT_EQ(g.outer_walls.size(), 1U);
        EXPECT_TRUE(g.inner_walls.empty() && g.skin.empty() && g.infill.empty());
        EXPECT_DOUBLE_EQ(std::abs(ClipperLib::Area(g.outer_walls[0].points)), 400e6);  // along the outline
        EXPECT_TRUE(g.outer_walls[0].fixed_start);                                     // seam placed
    }
}

TEST(MeshToolpaths, PerimeterGapsAreFilledWithHalfWidthSkinLines) {
    // A 1.0 mm wide wall of a part: room for the outer wall only, the 0.17 mm left inside is a gap
    // filled with lines half an outer wall wide (fill_perimeter_gaps), unless that is off.
    test::Stack strip = test::prismStack(10);
    test::fill(strip, 0, 10, {test::rect(10'000, 10'000, 30'000, 11'000)});
    const auto gapLines = [&](const std::string& mode) {
        const ResolvedMachine m = test::fdmMachine({{"fill_perimeter_gaps", mode}}, {{1, {}}});
        std::size_t count = 0;
        const std::vector<MeshLayerGroups> groups = generateMeshToolpaths(strip.layers, m.global, 2);
        for (const ExtrusionPath& p : groups[5].skin)
            count += p.width_um == 200 && p.feature == Feature::Skin ? 1 : 0;
        return count;
    };
    EXPECT_GT(gapLines("everywhere"), 10U);
    EXPECT_EQ(gapLines("nowhere"), 0U);
}

}  // namespace
}  // namespace mixengine
