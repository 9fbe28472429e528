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

TEST(MeshInfill, SkinEdgeSupportKeepsTheThinRingAnOpeningLeaves) {
    // The 4 mm pin of the parity scene ender3_slivers on layer 35 (CuraEngine 4.13,
    // skin_edge_support_layers=1): its infill area (the inner area opened by half a line width, so a
    // micrometre beyond the inner area at places), the whole inner area under skin on the layer above. The
    // piece under the skin (opened by a line width) ends inside the infill area all round; the thin ring left
    // is kept, so the piece gets the infill wall CuraEngine prints there (its G-code's loop, vertex for
    // vertex).
    const Path inner{{119011, 107847}, {119293, 107963}, {119544, 108156}, {119737, 108407}, {119853, 108689},
                     {119894, 109000}, {119853, 109311}, {119737, 109593}, {119544, 109844}, {119293, 110037},
                     {119011, 110153}, {118700, 110194}, {118389, 110153}, {118107, 110037}, {117856, 109844},
                     {117663, 109593}, {117547, 109311}, {117506, 109000}, {117547, 108689}, {117663, 108407},
                     {117856, 108156}, {118107, 107963}, {118389, 107847}, {118700, 107806}};
    const Path infill{{119010, 107846}, {119292, 107962}, {119544, 108156}, {119738, 108408},
                      {119854, 108690}, {119895, 109000}, {119854, 109310}, {119738, 109592},
                      {119544, 109844}, {119292, 110038}, {119010, 110154}, {118700, 110195},
                      {118390, 110154}, {118108, 110038}, {117856, 109844}, {117662, 109592},
                      {117546, 109310}, {117505, 109000}, {117546, 108690}, {117662, 108408},
                      {117856, 108156}, {118108, 107962}, {118390, 107846}, {118700, 107805}};
    const std::set<std::pair<coord_um, coord_um>> cura_wall{
        {118700, 109992}, {118443, 109959}, {118209, 109862}, {117999, 109701}, {117838, 109491},
        {117741, 109257}, {117708, 109000}, {117741, 108743}, {117838, 108509}, {117999, 108299},
        {118209, 108138}, {118443, 108041}, {118700, 108008}, {118957, 108041}, {119191, 108138},
        {119401, 108299}, {119562, 108509}, {119659, 108743}, {119692, 109000}, {119659, 109257},
        {119562, 109491}, {119401, 109701}, {119191, 109862}, {118957, 109959}};
    LayerInfill layer;
    layer.by_density = {{{infill}}};
    const std::vector<ExtrusionPath> paths = meshInfillPaths(layer, linesAt(4'000), {{inner}, {inner}});
    std::vector<const ExtrusionPath*> loops;
    for (const ExtrusionPath& path : paths) {
        if (path.closed)
            loops.push_back(&path);
    }
    ASSERT_EQ(loops.size(), 1U);
    std::set<std::pair<coord_um, coord_um>> wall;
    for (const Point2& p : loops[0]->points)
        wall.emplace(p.X, p.Y);
    EXPECT_EQ(wall, cura_wall);
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
