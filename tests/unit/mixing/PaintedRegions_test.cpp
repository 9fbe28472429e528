// Painted regions (mixing/fields/PaintedRegions.h) and cutting moves where the region changes
// (mixing/fields/RegionSplit.h), on a 20 mm cube whose faces are painted by side.
#include "mixing/fields/PaintedRegions.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mixing/fields/RegionSplit.h"

namespace mixengine {
namespace {

/// A 20 mm cube (0..20000 µm); faces 0..11, two per side, in the order -x, +x, -y, +y, -z, +z.
Mesh cube() {
    Mesh m;
    for (int i = 0; i < 8; ++i)
        m.vertices.push_back({(i & 1) * 20000, ((i >> 1) & 1) * 20000, ((i >> 2) & 1) * 20000});
    const int quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                             {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    for (const auto& q : quads) {
        m.faces.push_back({{std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2])}});
        m.faces.push_back({{std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])}});
    }
    return m;
}

TEST(PaintedRegions, DistanceToATriangle) {
    const double a[3] = {0, 0, 0}, b[3] = {10, 0, 0}, c[3] = {0, 10, 0};
    const double above[3] = {2, 2, 3}, beyond_edge[3] = {10, 10, 0}, past_corner[3] = {-3, -4, 0};
    EXPECT_DOUBLE_EQ(squaredDistanceToTriangle(above, a, b, c), 9.0);
    EXPECT_NEAR(squaredDistanceToTriangle(beyond_edge, a, b, c), 50.0, 1e-9);
    EXPECT_DOUBLE_EQ(squaredDistanceToTriangle(past_corner, a, b, c), 25.0);
}

TEST(PaintedRegions, PaintReachesTheDepthFromItsFace) {
    // -x side painted region 0, +x side region 1, the rest unpainted; depth 3 mm.
    std::vector<int> regions(12, -1);
    regions[0] = regions[1] = 0;
    regions[2] = regions[3] = 1;
    const PaintedRegions painted(cube(), regions, 3000);
    EXPECT_EQ(painted.regionAt({1000, 10000, 10000}), 0);
    EXPECT_EQ(painted.regionAt({2900, 10000, 10000}), 0);
    EXPECT_EQ(painted.regionAt({3100, 10000, 10000}), -1);  // deeper than the paint
    EXPECT_EQ(painted.regionAt({19000, 10000, 10000}), 1);
    EXPECT_EQ(painted.regionAt({1000, 10000, 500}), -1);  // nearer the unpainted bottom than the -x side
    EXPECT_EQ(painted.regionAt({10000, 10000, 10000}), -1);
}

TEST(RegionSplit, AMoveAcrossTwoRegionsIsCutAtTheBoundary) {
    // The whole -x half (x < 10 mm) region 0, the +x half region 1: every face painted by its side,
    // depth beyond the middle.
    std::vector<int> regions(12, -1);
    regions[0] = regions[1] = 0;
    regions[2] = regions[3] = 1;
    const Mesh m = cube();
    const PaintedRegions painted(m, regions, 30000);
    // only the ±x sides are painted: the middle plane x = 10 mm is where they are equally far
    PrintPlan plan;
    PlannedLayer layer;
    layer.z = 10100;
    layer.thickness = 200;
    PlanStep mesh_step;
    mesh_step.kind = PlanStep::Kind::SetMesh;
    mesh_step.mesh_index = 0;
    PlanStep travel;
    travel.kind = PlanStep::Kind::Travel;
    travel.to = {2000, 10000};
    PlanStep extrude;
    extrude.kind = PlanStep::Kind::Extrude;
    extrude.to = {18000, 10000};  // y = 10 mm: the ±y sides are 10 mm away, farther than ±x near the ends
    extrude.volume_mm3 = 1.6;
    layer.steps = {mesh_step, travel, extrude};
    plan.layers.push_back(layer);
    const auto result = splitAtRegions(plan, {{&painted, 0}});
    // Regions: x < 10 mm → 0 (−x side nearest); the ±y sides (10 mm away) tie with ±x only at the ends.
    ASSERT_EQ(plan.layers[0].steps.size(), 4u);
    const PlanStep& first = plan.layers[0].steps[2];
    const PlanStep& second = plan.layers[0].steps[3];
    EXPECT_NEAR(static_cast<double>(first.to.X), 10000.0, 5.0);
    EXPECT_EQ(second.to, (Point2{18000, 10000}));
    EXPECT_NEAR(first.volume_mm3, 0.8, 1e-3);
    EXPECT_NEAR(first.volume_mm3 + second.volume_mm3, 1.6, 1e-12);
    EXPECT_EQ(result[0][2], 0);
    EXPECT_EQ(result[0][3], 1);
    EXPECT_EQ(result[0][1], -1);  // the travel
}

}  // namespace
}  // namespace mixengine
