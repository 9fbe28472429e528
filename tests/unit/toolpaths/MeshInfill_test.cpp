// A mesh's infill on a layer (toolpaths/infill/MeshInfill.h): densities, thickness, settings.
#include "toolpaths/infill/MeshInfill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "ToolpathTestSupport.h"

namespace mixengine {
namespace {

using test::square;

InfillParams linesAt(coord_um distance) {
    InfillParams p;
    p.line_distance_um = distance;
    p.angle_degrees = 0;
    return p;
}

TEST(MeshInfill, SkinEdgeSupportWallsTheInfillUnderTheSkinAbove) {
    // skin_edge_support_layers: the left half of a 20 mm square has skin above; as CuraEngine, that piece
    // gets an infill wall (a loop) and lines of its own, the right half its lines alone.
    LayerInfill layer;
    layer.by_density = {{{square(0, 0, 20'000)}}};
    InfillParams params = linesAt(2'000);
    auto loops = [](const std::vector<ExtrusionPath>& paths) {
        return std::count_if(paths.begin(), paths.end(), [](const ExtrusionPath& p) { return p.closed; });
    };
    EXPECT_EQ(loops(meshInfillPaths(layer, params)), 0);
    const SkinEdgeSupport edge{{test::rect(0, 0, 10'000, 20'000)}, {square(0, 0, 20'000)}};
    const std::vector<ExtrusionPath> split = meshInfillPaths(layer, params, edge);
    EXPECT_EQ(loops(split), 1);
    for (const ExtrusionPath& path : split) {
        if (path.closed) {
            for (const Point2& p : path.points)
                EXPECT_LE(p.X, 10'000);  // around the piece under the skin
        }
    }
    // Skin above all of it: nothing is left beside it, so nothing is split.
    EXPECT_EQ(loops(meshInfillPaths(layer, params, {{square(0, 0, 20'000)}, {square(0, 0, 20'000)}})), 0);
}

TEST(MeshInfill, DensitiesTogetherMakeTheBaseSpacing) {
    // Two densities: the sparsest (all of the area) at 2d, the dense part at 2d shifted by d.
    LayerInfill layer;
    layer.by_density = {{{square(500, 500, 9'000)}}, {{square(500, 500, 19'000)}}};
    int dense = 0, sparse = 0;
    for (const ExtrusionPath& path : meshInfillPaths(layer, linesAt(1'000))) {
        const coord_um x = path.points[0].X;
        ASSERT_EQ(x % 1'000, 0);
        if (x % 2'000 == 0) {
            ++sparse;  // x = 2, 4, …, 18 mm, the whole height
            EXPECT_NEAR(test::pathLength(path), 19'000.0, 1.0);
        } else {
            ++dense;  // x = 1, 3, …, 9 mm, in the dense part only
            EXPECT_NEAR(test::pathLength(path), 9'000.0, 1.0);
        }
    }
    EXPECT_EQ(sparse, 9);
    EXPECT_EQ(dense, 5);
}

TEST(MeshInfill, ThickerInfillComesFirstWithMoreFlow) {
    LayerInfill layer;
    layer.by_density = {{{square(0, 0, 10'000)}, {square(20'000, 0, 10'000)}}};
    InfillParams base = linesAt(2'000);
    base.flow = 0.9;
    const std::vector<ExtrusionPath> paths = meshInfillPaths(layer, base);
    ASSERT_FALSE(paths.empty());
    EXPECT_GE(paths.front().points[0].X, 20'000);
    for (const ExtrusionPath& path : paths)
        EXPECT_DOUBLE_EQ(path.flow, path.points[0].X >= 20'000 ? 1.8 : 0.9);
}

TEST(MeshInfill, SettingsGiveOriginAngleAndArrangement) {
    const ResolvedMachine m = test::fdmMachine({{"infill_offset_x", "2"},
                                                {"infill_offset_y", "-1"},
                                                {"infill_pattern", "lines"},
                                                {"layer_height", "0.1"},
                                                {"infill_sparse_thickness", "0.3"},
                                                {"infill_wall_line_count", "1"},
                                                {"gradual_infill_steps", "2"}});
    const InfillParams p = meshInfillParams(m.global, 7, 800, FeatureStyle{}, {100'000, 50'000});
    EXPECT_EQ(p.origin_um, Point2(102'000, 49'000));
    EXPECT_EQ(p.wall_count, 1);
    // Three layers print as one, so the 45°/135° alternation counts layer / 3.
    EXPECT_EQ(p.angle_degrees, 45.0);
    EXPECT_EQ(meshInfillParams(m.global, 4, 500, FeatureStyle{}, {0, 0}).angle_degrees, 135.0);
    const InfillLayerParams a = infillLayerParams(m.global);
    EXPECT_EQ(a.combine_layers, 3);
    EXPECT_EQ(a.gradual_steps, 2);
}

}  // namespace
}  // namespace mixengine

namespace mixengine {
namespace {

TEST(MeshInfill, RandomStartIsTheStartOfALineAndRepeatable) {
    std::vector<ExtrusionPath> lines;
    for (int i = 0; i < 20; ++i) {
        ExtrusionPath p;
        p.points = {{i * 1'000, 0}, {i * 1'000, 5'000}};
        lines.push_back(p);
    }
    std::set<coord_um> starts;
    for (int layer = 0; layer < 10; ++layer) {
        const std::optional<Point2> start = randomInfillStart(lines, layer);
        ASSERT_TRUE(start.has_value());
        EXPECT_EQ(start->Y, 0);
        EXPECT_EQ(start, randomInfillStart(lines, layer));
        starts.insert(start->X);
    }
    EXPECT_GT(starts.size(), 3U);  // it moves from layer to layer
    EXPECT_FALSE(randomInfillStart({}, 3).has_value());
}

}  // namespace
}  // namespace mixengine
