// Issue 15's shape modes in the toolpath stage: spiralize (toolpaths/surface/Spiralize.h), fuzzy skin
// (toolpaths/surface/FuzzySkin.h), make overhang printable (toolpaths/surface/ConicalOverhang.h) and mold
// (toolpaths/surface/Mold.h), on hand-made outlines with figures worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/surface/ConicalOverhang.h"
#include "toolpaths/surface/FuzzySkin.h"
#include "toolpaths/surface/Mold.h"
#include "toolpaths/surface/Spiralize.h"

namespace mixengine {
namespace {

using test::square;

SpiralSliceParams sliceParams() {
    SpiralSliceParams p;
    p.style.width_um = 400;
    p.style.speed_mm_s = 30;
    p.style.flow = 1.0;
    return p;
}

TEST(Spiralize, FirstSeamIsNearestTheHintThenFollowsTheLayerBelow) {
    const Path wall = square(10'000, 10'000, 20'000);  // corners (10,10) (30,10) (30,30) (10,30) mm
    const std::vector<Path> walls{wall, wall, {}, wall};
    const std::vector<std::size_t> seams = spiralSeams(walls, {0, 0}, 250);
    EXPECT_EQ(seams[0], 0U);  // (0, 0) is nearest the edge that starts at (10, 10)
    EXPECT_EQ(seams[1], 0U);  // the same vertex above it (distance 0: no look-ahead)
    EXPECT_EQ(seams[2], 0U);  // no wall
    EXPECT_EQ(seams[3], 0U);
    const std::vector<std::size_t> back = spiralSeams({wall}, {31'000, 29'000}, 250);
    EXPECT_EQ(back[0], 1U);  // the hint is nearest the edge from (30, 10) to (30, 30)
}

TEST(Spiralize, SeamMovesOnWhenTheNextVertexLiesBehind) {
    // Below: the seam at (30, 10), inward normal (−1, 1). Above, the vertex nearest to it is (29.8, 10),
    // 0.2 mm away, and the vertex after that, (29, 10.9), lies behind the seam along that normal
    // (−1 + 0.9 < 0): the seam moves on to it. With 0.25 mm resolution the nearest vertex is kept.
    const Path below = square(10'000, 10'000, 20'000);
    const Path above{
        {10'000, 10'000}, {29'800, 10'000}, {29'000, 10'900}, {29'000, 30'000}, {10'000, 30'000}};
    const std::vector<std::size_t> seams = spiralSeams({below, above}, {31'000, 11'000}, 100);
    ASSERT_EQ(seams[0], 1U);  // (30, 10)
    EXPECT_EQ(seams[1], 2U);
    EXPECT_EQ(spiralSeams({below, above}, {31'000, 11'000}, 250)[1], 1U);
}

TEST(Spiralize, SliceStartsWhereTheLayerBelowEndedAndGoesOnceRound) {
    const Path wall = square(0, 0, 10'000);
    SpiralSliceParams p = sliceParams();
    const std::vector<ExtrusionPath> paths = spiralSlice(wall, 2, {&wall, 1}, p);
    ASSERT_EQ(paths.size(), 1U);
    const ExtrusionPath& spiral = paths[0];
    EXPECT_TRUE(spiral.spiral && spiral.fixed_start && !spiral.closed);
    EXPECT_EQ(spiral.points.front(), wall[1]);  // the seam of the layer below
    EXPECT_EQ(spiral.points.back(), wall[2]);   // its own seam, exactly
    // smoothing off: first a join from (10, 0) to the nearest point of the edge after the seam, (10, 10)
    EXPECT_EQ(spiral.points[1], (Point2{10'000, 10'000}));
    EXPECT_EQ(spiral.points.size(), 2U + wall.size());
    EXPECT_EQ(spiral.spiral_flat_tail, 0U);
    for (std::size_t k = 1; k < spiral.flows.size(); ++k)
        EXPECT_DOUBLE_EQ(spiral.flows[k], 1.0);
}

TEST(Spiralize, BottomLayerFlowRisesFromAQuarter) {
    const Path wall = square(0, 0, 10'000);
    SpiralSliceParams p = sliceParams();
    p.bottom = true;
    const ExtrusionPath spiral = spiralSlice(wall, 0, {}, p).at(0);
    ASSERT_EQ(spiral.points.size(), 5U);  // the seam, then the four corners round to it
    EXPECT_DOUBLE_EQ(spiral.flows[1], 0.25 + 0.75 * 0.25);
    EXPECT_DOUBLE_EQ(spiral.flows[2], 0.25 + 0.75 * 0.5);
    EXPECT_DOUBLE_EQ(spiral.flows[4], 1.0);
}

TEST(Spiralize, TopLayerTapersFlatAfterTheLoop) {
    const Path wall = square(0, 0, 10'000);  // 40 mm round
    SpiralSliceParams p = sliceParams();
    p.top = true;
    p.min_layer_time_s = 5;  // 40 mm at 30 mm/s = 1.33 s < 5 s: slowed by 1.33 / min(2.33, 5)
    const ExtrusionPath spiral = spiralSlice(wall, 0, {&wall, 0}, p).at(0);
    // the tapering round: flows 0.75, 0.5, 0.25 (quantised to 1/20), then 0 for 10 mm at most
    ASSERT_EQ(spiral.spiral_flat_tail, 4U);
    const std::size_t tail = spiral.points.size() - 4;
    EXPECT_DOUBLE_EQ(spiral.flows[tail], 0.75);
    EXPECT_DOUBLE_EQ(spiral.flows[tail + 1], 0.5);
    EXPECT_DOUBLE_EQ(spiral.flows[tail + 2], 0.25);
    EXPECT_DOUBLE_EQ(spiral.flows[tail + 3], 0.0);
    EXPECT_NEAR(spiral.speed_mm_s, 30.0 * (40.0 / 30.0) / (40.0 * 1.75 / 30.0), 1e-9);
}

TEST(FuzzySkin, PointsStayWithinTheThicknessAndRepeat) {
    FuzzySkinParams p;
    p.enabled = true;
    p.thickness_um = 300;
    p.point_dist_um = 800;
    const Path loop = square(0, 0, 20'000);
    const Path fuzzy = fuzzyLoop(loop, p, 42);
    EXPECT_EQ(fuzzy, fuzzyLoop(loop, p, 42));  // seeded: reproducible
    EXPECT_NE(fuzzy, fuzzyLoop(loop, p, 43));
    // 80 mm round at 0.6 … 1.0 mm apart
    EXPECT_GE(fuzzy.size(), 80U);
    EXPECT_LE(fuzzy.size(), 134U);
    for (const Point2& q : fuzzy) {
        const coord_um off =
            std::min({std::llabs(q.X), std::llabs(q.X - 20'000), std::llabs(q.Y), std::llabs(q.Y - 20'000)});
        EXPECT_LE(off, 300) << q.X << "," << q.Y;
    }
    p.outside_only = true;
    const Path hole{{5'000, 5'000}, {5'000, 15'000}, {15'000, 15'000}, {15'000, 5'000}};  // clockwise
    EXPECT_EQ(fuzzyLoop(hole, p, 1), hole);
    EXPECT_NE(fuzzyLoop(loop, p, 1), loop);
}

std::vector<SlicedLayer> layersOf(const std::vector<Paths>& outlines) {
    std::vector<SlicedLayer> layers(outlines.size());
    for (std::size_t i = 0; i < outlines.size(); ++i)
        layers[i].outlines = outlines[i];
    return layers;
}

TEST(ConicalOverhang, LayersBelowGrowTowardsTheOverhang) {
    // 10 × 10 mm at the bottom, 30 × 30 mm on top: with 45° and 0.2 mm layers each layer below the top
    // reaches 0.2 mm less far out.
    std::vector<SlicedLayer> layers = layersOf(
        {{square(10'000, 10'000, 10'000)}, {square(10'000, 10'000, 10'000)}, {square(0, 0, 30'000)}});
    applyConicalOverhang(layers, {45.0, 0.0, 200});
    EXPECT_NEAR(areaUm2(layers[1].outlines), 29'600.0 * 29'600.0, 1e6);
    EXPECT_NEAR(areaUm2(layers[0].outlines), 29'200.0 * 29'200.0, 1e6);
}

TEST(ConicalOverhang, SmallCoveredHolesStayHoles) {
    Path hole = square(10'000, 10'000, 2'000);
    std::reverse(hole.begin(), hole.end());
    const Paths with_hole{square(0, 0, 22'000), hole};
    std::vector<SlicedLayer> kept = layersOf({with_hole, {square(0, 0, 22'000)}});
    applyConicalOverhang(kept, {45.0, 5.0, 200});  // 4 mm² < 5 mm²: kept
    EXPECT_NEAR(areaUm2(kept[0].outlines), 22'000.0 * 22'000 - 2'000.0 * 2'000, 1e3);
    std::vector<SlicedLayer> filled = layersOf({with_hole, {square(0, 0, 22'000)}});
    applyConicalOverhang(filled, {45.0, 3.0, 200});  // 4 mm² ≥ 3 mm²: the cone fills it
    EXPECT_NEAR(areaUm2(filled[0].outlines), 22'000.0 * 22'000, 1e3);
}

TEST(Mold, ModelBecomesTheCavityOfAWallMoldWidthThick) {
    const Settings s = test::fdmMachine({{"mold_enabled", "True"},
                                         {"mold_width", "5"},
                                         {"mold_roof_height", "0"},
                                         {"mold_angle", "90"},
                                         {"layer_height", "0.2"}})
                           .global;
    std::vector<SlicedLayer> layers = layersOf({{square(0, 0, 10'000)}, {square(0, 0, 10'000)}});
    applyMolds({{&layers, &s}}, 200);
    for (const SlicedLayer& layer : layers) {
        // a 20 × 20 mm square with round corners (r = 5 mm) less the 10 × 10 mm model
        const double outside = 10'000.0 * 10'000 + 4 * 10'000.0 * 5'000 + M_PI * 5'000.0 * 5'000;
        EXPECT_NEAR(areaUm2(layer.outlines), outside - 10'000.0 * 10'000, 5e5);
    }
}

}  // namespace
}  // namespace mixengine
