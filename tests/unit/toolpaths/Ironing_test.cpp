// Ironing (toolpaths/surface/Ironing.h): the top surface, the inset per pattern, the lines' spacing and
// angle, monotonic order, and where MeshToolpaths irons (every top surface or the highest only).
#include "toolpaths/surface/Ironing.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/MeshToolpaths.h"

namespace mixengine {
namespace {

using test::rect;
using test::square;

Settings ironingSettings(const SettingValues& user) {
    SettingValues values{
        {"ironing_enabled", "True"},        {"ironing_line_spacing", "0.1"}, {"ironing_flow", "10"},
        {"ironing_inset", "0.38"},          {"skin_line_width", "0.4"},      {"layer_height", "0.2"},
        {"infill_sparse_thickness", "0.2"}, {"speed_ironing", "16"},         {"speed_print_layer_0", "20"},
        {"speed_slowdown_layers", "2"}};
    for (const auto& [k, v] : user)
        values[k] = v;
    return test::fdmMachine(values).global;
}

TEST(Ironing, TopSurfaceIsWhatTheLayerAboveDoesNotCover) {
    const Paths outline{square(0, 0, 20'000)};
    const Paths above{square(0, 0, 10'000)};
    EXPECT_DOUBLE_EQ(areaUm2(topSurface(outline, above)), 20'000.0 * 20'000 - 10'000.0 * 10'000);
    EXPECT_DOUBLE_EQ(areaUm2(topSurface(outline, {})), 20'000.0 * 20'000);  // the top layer: all of it
    EXPECT_TRUE(topSurface(outline, outline).empty());
}

TEST(Ironing, InsetCompensatedPerPatternAsCuraEngine) {
    // zigzag: 0.38 − 1 × 0.2 + 0.1 × 0.2 + 0.2 = 0.4 mm (the line's edge meets the outer wall's edge)
    EXPECT_EQ(ironingParams(ironingSettings({{"ironing_pattern", "zigzag"}}), 5).inset_um, 400);
    // concentric: the first loop 0.38 + 0.1 × 0.2 = 0.4 mm in
    EXPECT_EQ(ironingParams(ironingSettings({{"ironing_pattern", "concentric"}}), 5).inset_um, 400);
    // lines: ironing_inset as it is
    EXPECT_EQ(ironingParams(ironingSettings({{"ironing_pattern", "lines"}}), 5).inset_um, 380);
    // a thicker sparse infill layer (s = 0.5) moves zigzag out by s·w/2 less: 0.38 − 0.1 + 0.02 + 0.2
    EXPECT_EQ(
        ironingParams(ironingSettings({{"ironing_pattern", "zigzag"}, {"infill_sparse_thickness", "0.4"}}), 5)
            .inset_um,
        500);
}

TEST(Ironing, StyleAngleAndOrderFromTheMeshSettings) {
    const IroningParams odd = ironingParams(ironingSettings({}), 3);
    EXPECT_DOUBLE_EQ(odd.angle_degrees,
                     135 + 90);  // skin_angles default 45/135: perpendicular to the top skin
    EXPECT_DOUBLE_EQ(ironingParams(ironingSettings({}), 4).angle_degrees, 45 + 90);
    EXPECT_DOUBLE_EQ(ironingParams(ironingSettings({{"skin_angles", "[10]"}}), 4).angle_degrees, 100);
    EXPECT_DOUBLE_EQ(
        ironingParams(ironingSettings({{"roofing_layer_count", "1"}, {"roofing_angles", "[30]"}}), 4)
            .angle_degrees,
        120);
    EXPECT_EQ(odd.style.width_um, 400);
    EXPECT_DOUBLE_EQ(odd.style.flow, 0.1);
    EXPECT_DOUBLE_EQ(odd.style.speed_mm_s, 16);
    EXPECT_DOUBLE_EQ(ironingParams(ironingSettings({}), 1).style.speed_mm_s, 18);  // the first layers' ramp
    EXPECT_FALSE(odd.monotonic);
}

TEST(Ironing, LinesOneSpacingApartInsideTheInset) {
    IroningParams p = ironingParams(ironingSettings({{"ironing_pattern", "lines"}}), 0);
    p.angle_degrees = 0;  // lines along Y, on x = k · 0.1 mm
    const std::vector<ExtrusionPath> lines = ironingPaths({square(0, 0, 10'000)}, p);
    ASSERT_EQ(lines.size(), 93U);  // x = 0.4 … 9.6 mm (0.38 mm in, on the 0.1 mm grid)
    for (const ExtrusionPath& line : lines) {
        EXPECT_EQ(line.feature, Feature::Ironing);
        EXPECT_EQ(line.points.front().X, line.points.back().X);
        EXPECT_EQ(line.points.front().X % 100, 0);
        EXPECT_GE(std::min(line.points.front().Y, line.points.back().Y), 380);
        EXPECT_FALSE(line.keep_order);
    }
}

TEST(Ironing, ZigzagAndConcentricCoverTheSurface) {
    const Paths surface{square(0, 0, 10'000)};
    const std::vector<ExtrusionPath> zigzag = ironingPaths(surface, ironingParams(ironingSettings({}), 0));
    ASSERT_FALSE(zigzag.empty());
    EXPECT_LT(zigzag.size(), 5U);  // joined into long polylines
    // 9.2 mm square (0.4 mm in) at 0.1 mm: about 92 lines of 9.2 mm, plus the connections
    EXPECT_NEAR(test::totalLength(zigzag), 92 * 9'200.0, 0.05 * 92 * 9'200.0);
    const std::vector<ExtrusionPath> loops =
        ironingPaths(surface, ironingParams(ironingSettings({{"ironing_pattern", "concentric"}}), 0));
    EXPECT_EQ(loops.size(), 46U);  // 9.2 mm down to nothing, 0.2 mm narrower each
    for (const ExtrusionPath& loop : loops)
        EXPECT_TRUE(loop.closed);
    EXPECT_EQ(boundsOf({loops.front().points}).left, 400);
}

TEST(Ironing, MonotonicKeepsTheLinesInOrderAcrossThem) {
    IroningParams p =
        ironingParams(ironingSettings({{"ironing_pattern", "lines"}, {"ironing_monotonic", "True"}}), 0);
    p.angle_degrees = 0;
    EXPECT_TRUE(p.monotonic);
    // Two islands: the lines of both are sorted by x — falling, along CuraEngine's monotonic vector
    // (−cos 0°, sin 0°) — so they alternate between the islands' rows.
    const std::vector<ExtrusionPath> lines =
        ironingPaths({rect(0, 0, 5'000, 5'000), rect(0, 10'000, 5'000, 15'000)}, p);
    ASSERT_GT(lines.size(), 10U);
    for (std::size_t i = 1; i < lines.size(); ++i) {
        EXPECT_GE(lines[i - 1].points.front().X, lines[i].points.front().X);
        EXPECT_TRUE(lines[i].keep_order);
    }
}

TEST(Ironing, MonotonicZigzagStartsAtTheEndFurthestBack) {
    // A zigzag crosses the surface: monotonic, it starts at the end with the lower projection on
    // CuraEngine's monotonic vector (−cos a, sin a), whichever end the nozzle is nearer.
    IroningParams p = ironingParams(ironingSettings({{"ironing_monotonic", "True"}}), 0);
    p.angle_degrees = 0;  // lines along Y; the vector (−1, 0): from the right
    const std::vector<ExtrusionPath> zigzag = ironingPaths({square(0, 0, 10'000)}, p);
    ASSERT_FALSE(zigzag.empty());
    for (const ExtrusionPath& path : zigzag) {
        EXPECT_TRUE(path.fixed_start);
        EXPECT_GT(path.points.front().X, path.points.back().X);
    }
}

TEST(Ironing, MeshToolpathsIronEveryTopSurfaceOrOnlyTheHighest) {
    // A 20 mm square of 10 layers with a 10 mm square on top for 10 more (0.3 mm, then 0.1 mm layers).
    test::Stack s = test::prismStack(20);
    test::fill(s, 0, 10, {square(10'000, 10'000, 20'000)});
    test::fill(s, 10, 20, {square(10'000, 10'000, 10'000)});
    auto ironed = [&](const SettingValues& user) {
        SettingValues values{{"ironing_enabled", "True"}};
        for (const auto& [k, v] : user)
            values[k] = v;
        const std::vector<MeshLayerGroups> layers =
            generateMeshToolpaths(s.layers, test::fdmMachine(values).global, 2);
        std::vector<int> out;
        for (int i = 0; i < static_cast<int>(layers.size()); ++i) {
            if (!layers[static_cast<std::size_t>(i)].ironing.empty())
                out.push_back(i);
        }
        return out;
    };
    EXPECT_EQ(ironed({}), (std::vector<int>{9, 19}));  // the step's uncovered L and the top
    EXPECT_EQ(ironed({{"ironing_only_highest_layer", "True"}}), (std::vector<int>{19}));
    EXPECT_TRUE(ironed({{"ironing_enabled", "False"}}).empty());
}

}  // namespace
}  // namespace mixengine
