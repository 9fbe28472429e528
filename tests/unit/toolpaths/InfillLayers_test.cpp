// Infill arrangement (toolpaths/infill/InfillLayers.h): infill as support, gradual infill, combined layers.
#include "toolpaths/infill/InfillLayers.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::square;

std::vector<Paths> column(int layers, const Paths& area) {
    return std::vector<Paths>(static_cast<std::size_t>(layers), area);
}

double area(const Paths& p) {
    return areaUm2(p);
}

TEST(InfillLayers, PlainInfillIsOneDensityOneLayerThick) {
    const Paths a{square(0, 0, 10'000)};
    const std::vector<LayerInfill> layers = arrangeInfill(column(10, a), {}, 2);
    for (const LayerInfill& l : layers) {
        ASSERT_EQ(l.by_density.size(), 1U);
        ASSERT_EQ(l.by_density[0].size(), 1U);
        EXPECT_NEAR(area(l.by_density[0][0]), 1e8, 1.0);
    }
}

TEST(InfillLayers, CombiningMovesTheLowerLayersInfillUpAsThickerInfill) {
    InfillLayerParams p;
    p.combine_layers = 2;
    const std::vector<LayerInfill> layers = arrangeInfill(column(10, {square(0, 0, 10'000)}), p, 2);
    // Layers 0 … 9, the combined ones at 2, 4, 6, 8 (9 is not divisible, 1 is below the first).
    for (int i : {2, 4, 6, 8}) {
        const LayerInfill& upper = layers[static_cast<std::size_t>(i)];
        ASSERT_EQ(upper.by_density[0].size(), 2U) << i;
        EXPECT_TRUE(upper.by_density[0][0].empty()) << i;
        EXPECT_NEAR(area(upper.by_density[0][1]), 1e8, 1.0) << i;
        EXPECT_TRUE(layers[static_cast<std::size_t>(i - 1)].by_density[0][0].empty()) << i;
    }
    EXPECT_NEAR(area(layers[0].by_density[0][0]), 1e8, 1.0);
    EXPECT_NEAR(area(layers[9].by_density[0][0]), 1e8, 1.0);
}

TEST(InfillLayers, GradualInfillIsDenserBelowTheEndOfTheInfill) {
    InfillLayerParams p;
    p.gradual_steps = 1;
    p.gradual_step_layers = 3;
    const std::vector<LayerInfill> layers = arrangeInfill(column(12, {square(0, 0, 10'000)}), p, 2);
    // Layers with infill on all 3 layers above get a dense part (empty here) and the sparse whole;
    // the last 3 have no infill 3 layers up: a single density, all of it.
    for (int i = 0; i < 9; ++i) {
        ASSERT_EQ(layers[static_cast<std::size_t>(i)].by_density.size(), 2U) << i;
        EXPECT_TRUE(layers[static_cast<std::size_t>(i)].by_density[0][0].empty()) << i;
    }
    for (int i = 9; i < 12; ++i)
        EXPECT_EQ(layers[static_cast<std::size_t>(i)].by_density.size(), 1U) << i;
}

TEST(InfillLayers, GradualInfillWithTheSmallGapsHeuristicLooksAtFewerLayers) {
    InfillLayerParams p;
    p.gradual_steps = 1;
    p.gradual_step_layers = 3;
    p.small_gaps_heuristic = true;  // looks at layer i + 3 only
    std::vector<Paths> areas = column(12, {square(0, 0, 10'000)});
    areas[5].clear();  // a gap the heuristic does not see from layer 3 (it looks at 6)
    const std::vector<LayerInfill> with = arrangeInfill(areas, p, 2);
    EXPECT_TRUE(with[3].by_density[0][0].empty());
    p.small_gaps_heuristic = false;  // layers 4, 5, 6: the gap counts, layer 3 is all dense
    const std::vector<LayerInfill> without = arrangeInfill(areas, p, 2);
    EXPECT_EQ(without[3].by_density.size(), 1U);
}

TEST(InfillLayers, GradualDensePartIsWhereTheInfillEndsAbove) {
    InfillLayerParams p;
    p.gradual_steps = 1;
    p.gradual_step_layers = 2;
    std::vector<Paths> areas = column(10, {square(0, 0, 20'000)});
    for (std::size_t i = 5; i < 10; ++i)
        areas[i] = {square(0, 0, 10'000)};  // the right half stops at layer 5
    const std::vector<LayerInfill> layers = arrangeInfill(areas, p, 2);
    ASSERT_EQ(layers[3].by_density.size(), 2U);
    EXPECT_NEAR(area(layers[3].by_density[0][0]), 20'000.0 * 20'000.0 - 1e8, 1.0);  // dense: the L
    EXPECT_NEAR(area(layers[3].by_density[1][0]), 20'000.0 * 20'000.0, 1.0);
    EXPECT_TRUE(layers[1].by_density[0][0].empty());
}

TEST(InfillLayers, InfillAsSupportKeepsOnlyWhatCarriesTheTopOfAPyramid) {
    // A pyramid's infill: each layer 0.5 mm smaller each side than the one below, less than the
    // 1 mm the layer below can carry at the support angle. Only the infill under the top is kept.
    InfillLayerParams p;
    p.support_only = true;
    p.support_reach_um = 1'000;
    std::vector<Paths> areas;
    for (int i = 0; i < 10; ++i)
        areas.push_back({square(500 * i, 500 * i, 20'000 - 1'000 * i)});
    const std::vector<LayerInfill> layers = arrangeInfill(areas, p, 2);
    for (std::size_t i = 0; i < 10; ++i)
        EXPECT_NEAR(area(layers[i].by_density[0][0]), 11'000.0 * 11'000.0, 1.0) << i;
    // Without it every layer keeps its whole area.
    EXPECT_NEAR(area(arrangeInfill(areas, {}, 2)[0].by_density[0][0]), 4e8, 1.0);
}

TEST(InfillLayers, InfillAsSupportKeepsWhatCarriesAnOverhangingInfillAbove) {
    InfillLayerParams p;
    p.support_only = true;
    p.support_reach_um = 100;
    std::vector<Paths> areas = column(4, {square(0, 0, 10'000)});
    areas[3] = {square(0, 0, 20'000)};  // wider on top: all of layer 2 is needed
    const std::vector<LayerInfill> layers = arrangeInfill(areas, p, 2);
    EXPECT_NEAR(area(layers[2].by_density[0][0]), 1e8, 1.0);
    EXPECT_NEAR(area(layers[0].by_density[0][0]), 1e8, 1.0);
}

TEST(InfillLayers, NoInfillInTheBottomAndTopLayersCounted) {
    InfillLayerParams p;
    p.initial_bottom_layers = 2;
    p.top_layers = 3;
    const std::vector<LayerInfill> layers = arrangeInfill(column(10, {square(0, 0, 10'000)}), p, 1);
    for (int i : {0, 1, 7, 8, 9})
        EXPECT_TRUE(layers[static_cast<std::size_t>(i)].by_density[0][0].empty()) << i;
    for (int i = 2; i < 7; ++i)
        EXPECT_FALSE(layers[static_cast<std::size_t>(i)].by_density[0][0].empty()) << i;
}

}  // namespace
}  // namespace mixengine
