// Tree support (toolpaths/support/TreeSupport.h, TreeNodes.h, TreePointOps.h) under a plate on a stem.
#include "toolpaths/support/TreeSupport.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"
#include "geometry/PointQueries.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::rect;

TEST(TreePointOps, SpanningTreeJoinsNearestNeighbours) {
    const std::vector<Point2> points{{0, 0}, {3'000, 0}, {1'000, 0}, {10'000, 0}};
    const auto tree = spanningTreeNeighbours(points);
    EXPECT_EQ(tree[0], (std::vector<std::size_t>{2}));
    EXPECT_EQ(tree[2].size(), 2u);
    EXPECT_EQ(tree[3], (std::vector<std::size_t>{1}));
}

TEST(TreePointOps, MovesAPointOutOfAnAreaAcrossTheNearestEdge) {
    Point2 p{9'000, 5'000};
    ASSERT_TRUE(moveOutOf({rect(0, 0, 10'000, 10'000)}, p, 300, 4e6));
    EXPECT_EQ(p, (Point2{10'300, 5'000}));
    Point2 far{5'000, 5'000};  // 5 mm from every edge: more than the 2 mm allowed
    EXPECT_FALSE(moveOutOf({rect(0, 0, 10'000, 10'000)}, far, 300, 4e6));
    EXPECT_TRUE(insideArea({rect(0, 0, 10'000, 10'000)}, {10'000, 5'000}, true));
    EXPECT_FALSE(insideArea({rect(0, 0, 10'000, 10'000)}, {10'000, 5'000}, false));
}

/// A 10 mm stem (x, y in 0 … 10 mm) on layers 0 … 49 and a 30 mm wide plate on layers 50 … 59
/// (0.1 mm layers): the plate's arms overhang on both sides.
struct Tee {
    test::Stack stack = test::prismStack(60, 100, 100);
    std::vector<Paths> model;
    Overhangs overhangs;

    Tee() {
        test::fill(stack, 0, 50, {rect(0, 0, 10'000, 10'000)});
        test::fill(stack, 50, 60, {rect(-10'000, 0, 20'000, 10'000)});
        for (const SlicedLayer& layer : stack.layers)
            model.push_back(layer.outlines);
        overhangs = detectOverhangs(stack.layers, stack.heights, 50, 1);
    }

    std::vector<SupportLayerAreas> tree(const SettingValues& extra = {}) const {
        SettingValues values{{"support_enable", "True"},
                             {"support_structure", "tree"},
                             {"layer_height", "0.1"},
                             {"layer_height_0", "0.1"}};
        for (const auto& [k, v] : extra)
            values[k] = v;
        const ResolvedMachine m = test::fdmMachine(values);
        const TreeMesh mesh{&m.global, &overhangs.basic, boundsOf(model[55])};
        return treeSupportAreas(m.global, {mesh}, model, 2);
    }
};

double supportArea(const SupportLayerAreas& a) {
    return areaUm2(a.support) + areaUm2(a.roof) + areaUm2(a.floor);
}

TEST(TreeSupport, BranchesGoFromUnderTheArmsToThePlateOutsideTheStem) {
    const Tee tee;
    const std::vector<SupportLayerAreas> areas = tee.tree();
    ASSERT_EQ(areas.size(), 60u);
    // support_top_distance 0.2 mm: contacts 3 layers under the plate (layer 47), 48 and 49 empty.
    EXPECT_EQ(supportArea(areas[48]) + supportArea(areas[49]), 0);
    EXPECT_GT(supportArea(areas[47]), 0);
    // The branches come together on the way down: the bottom is far smaller than the top.
    EXPECT_LT(supportArea(areas[0]), 0.7 * supportArea(areas[44]));
    EXPECT_GT(supportArea(areas[0]), 0);
    const Paths stem = {rect(0, 0, 10'000, 10'000)};
    for (std::size_t i = 0; i < 45; ++i) {  // below the flattened tips nothing touches the stem
        const Paths all = unionOf(unionOf(areas[i].support, areas[i].roof), areas[i].floor);
        EXPECT_TRUE(intersectAll(all, stem).empty()) << i;
    }
    for (std::size_t i = 50; i < 60; ++i)
        EXPECT_EQ(supportArea(areas[i]), 0) << i;
}

TEST(TreeSupport, TheTopOfEachBranchIsRoofWhenRoofIsOn) {
    const Tee tee;
    const auto with_roof = tee.tree({{"support_roof_enable", "True"}, {"support_roof_height", "0.3"}});
    for (std::size_t i = 45; i <= 47; ++i) {  // 0.3 mm: the top 3 layers of each branch
        EXPECT_GT(areaUm2(with_roof[i].roof), 0) << i;
        EXPECT_TRUE(with_roof[i].support.empty()) << i;
    }
    EXPECT_TRUE(with_roof[44].roof.empty());
    const auto without = tee.tree({{"support_roof_enable", "False"}});
    EXPECT_TRUE(without[47].roof.empty());
    EXPECT_FALSE(without[47].support.empty());
}

TEST(TreeSupport, EverySubSettingChangesTheBranches) {
    const Tee tee;
    auto total = [](const std::vector<SupportLayerAreas>& areas) {
        double sum = 0;
        for (const SupportLayerAreas& a : areas)
            sum += supportArea(a);
        return sum;
    };
    const double base = total(tee.tree());
    EXPECT_GT(total(tee.tree({{"support_tree_branch_diameter", "4"}})), base * 1.2);
    EXPECT_GT(total(tee.tree({{"support_tree_branch_diameter_angle", "15"}})), base);
    EXPECT_LT(total(tee.tree({{"support_tree_branch_distance", "4"}})), base);
    EXPECT_NE(total(tee.tree({{"support_tree_angle", "70"}})), base);
    EXPECT_NE(total(tee.tree({{"support_tree_collision_resolution", "0.6"}})), base);
}

}  // namespace
}  // namespace mixengine
