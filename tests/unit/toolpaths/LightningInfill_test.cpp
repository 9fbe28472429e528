// Lightning infill (toolpaths/infill/lightning/LightningInfill.h): trees that hold up only what lies
// above them, shrinking as they go down.
#include "toolpaths/infill/lightning/LightningInfill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/infill/InfillPatterns.h"
#include "toolpaths/infill/lightning/LightningForest.h"
#include "toolpaths/infill/lightning/TreePropagation.h"

namespace mixengine {
namespace {

/// Cura's defaults at 0.2 mm layers, 40° angles, 3.2 mm line distance (20 % lightning at 0.4 mm).
LightningParams defaults() {
    LightningParams p;
    p.radius_um = 1'600;
    const coord_um reach = static_cast<coord_um>(200 * std::tan(40 * M_PI / 180));  // 167 µm
    p.wall_reach_um = reach;
    p.prune_um = reach;
    p.straighten_um = reach;
    p.line_width_um = 400;
    return p;
}

/// `count` layers of a 20 mm square (the top layer is the last).
std::vector<Paths> cube(int count) {
    return std::vector<Paths>(static_cast<std::size_t>(count), Paths{test::square(0, 0, 20'000)});
}

/// Squares centred on (50, 50) mm whose half side grows by `step_um` per layer downwards from 5 mm at the
/// top.
std::vector<Paths> pyramid(int count, coord_um step_um) {
    std::vector<Paths> layers;
    for (int i = 0; i < count; ++i) {
        const coord_um half = 5'000 + coord_um(count - 1 - i) * step_um;
        layers.push_back({test::square(50'000 - half, 50'000 - half, 2 * half)});
    }
    return layers;
}

double lengthAt(const LightningInfill& lightning, std::size_t layer) {
    double total = 0;
    for (const LightningTreeLines& tree : lightning.treesAt(layer)) {
        for (const Path& segment : tree.segments)
            total += test::polylineLength(segment);
    }
    return total;
}

double distanceToSegment(Point2 p, const Path& s) {
    const double dx = double(s[1].X - s[0].X), dy = double(s[1].Y - s[0].Y);
    const double l2 = dx * dx + dy * dy;
    const double t =
        l2 <= 0 ? 0.0 : std::clamp((double(p.X - s[0].X) * dx + double(p.Y - s[0].Y) * dy) / l2, 0.0, 1.0);
    return std::hypot(double(s[0].X) + t * dx - double(p.X), double(s[0].Y) + t * dy - double(p.Y));
}

TEST(LightningInfill, TopLayerOfACubeIsHeldEverywhereWithinTheRadius) {
    const LightningInfill lightning(defaults(), cube(60), 1);
    ASSERT_FALSE(lightning.treesAt(59).empty());
    // Every point of the top more than the wall reach from the edge is within the radius of a
    // line (plus the lattice's cell and the half width cut off at junctions).
    const double reach = 1'600 + 1'600.0 / 6 + 200 + 1;
    for (coord_um x = 500; x <= 19'500; x += 500) {
        for (coord_um y = 500; y <= 19'500; y += 500) {
            double nearest = 1e18;
            for (const LightningTreeLines& tree : lightning.treesAt(59)) {
                for (const Path& s : tree.segments)
                    nearest = std::min(nearest, distanceToSegment({x, y}, s));
            }
            EXPECT_LE(nearest, reach) << x << ", " << y;
        }
    }
    // Lines are two-point segments inside the square; every tree is rooted on its edge.
    for (const LightningTreeLines& tree : lightning.treesAt(59)) {
        const bool on_edge =
            tree.root.X <= 1 || tree.root.Y <= 1 || tree.root.X >= 19'999 || tree.root.Y >= 19'999;
        EXPECT_TRUE(on_edge) << tree.root.X << ", " << tree.root.Y;
        for (const Path& s : tree.segments) {
            ASSERT_EQ(s.size(), 2U);
            for (const Point2& p : s)
                EXPECT_TRUE(p.X >= 0 && p.X <= 20'000 && p.Y >= 0 && p.Y <= 20'000);
        }
    }
}

TEST(LightningInfill, LinesShrinkDownwardsAndDieOut) {
    const LightningInfill lightning(defaults(), cube(150), 1);
    // The top needs about as much as lines 3.2 mm apart on the 20 mm square (125 mm).
    EXPECT_GT(lengthAt(lightning, 149), 60'000);
    EXPECT_LT(lengthAt(lightning, 149), 250'000);
    for (std::size_t i = 149; i-- > 0;)
        EXPECT_LE(lengthAt(lightning, i), lengthAt(lightning, i + 1) + 2) << "layer " << i;
    EXPECT_LT(lengthAt(lightning, 139), 0.8 * lengthAt(lightning, 149));
    // Nothing reaches further than 10 mm (half the square) plus branches' bends; 167 µm go per layer,
    // so 120 layers (20 mm) down every tree is gone.
    EXPECT_EQ(lengthAt(lightning, 149 - 120), 0.0);
}

TEST(LightningInfill, NoLinesWhereTheWallsHoldTheLayerAbove) {
    // Each layer 100 µm wider per side than the one above: within the wall reach (167 µm), so only
    // the top needs trees, and those die out going down.
    const LightningInfill steep(defaults(), pyramid(150, 100), 1);
    EXPECT_GT(lengthAt(steep, 149), 0);
    EXPECT_EQ(lengthAt(steep, 40), 0.0);
    EXPECT_EQ(lengthAt(steep, 0), 0.0);
    // 300 µm per side: a ring of 133 µm per layer is held by no wall, so every layer has lines.
    const LightningInfill shallow(defaults(), pyramid(60, 300), 1);
    for (std::size_t i = 0; i < 60; ++i)
        EXPECT_GT(lengthAt(shallow, i), 0) << "layer " << i;
}

TEST(LightningInfill, SteeperPruneAngleShortensTheTreesFaster) {
    LightningParams p = defaults();
    const LightningInfill gentle(p, cube(150), 1);
    p.prune_um = static_cast<coord_um>(200 * std::tan(60 * M_PI / 180));  // 346 µm per layer
    const LightningInfill steep(p, cube(150), 1);
    EXPECT_EQ(lengthAt(gentle, 149), lengthAt(steep, 149));  // the top is the same
    EXPECT_LT(lengthAt(steep, 130), lengthAt(gentle, 130));
}

TEST(LightningInfill, SameTreesOnOneOrTwoThreads) {
    const std::vector<Paths> layers = pyramid(40, 300);
    const LightningInfill one(defaults(), layers, 1), two(defaults(), layers, 2);
    for (std::size_t i = 0; i < layers.size(); ++i) {
        ASSERT_EQ(one.treesAt(i).size(), two.treesAt(i).size());
        for (std::size_t t = 0; t < one.treesAt(i).size(); ++t)
            EXPECT_EQ(one.treesAt(i)[t].segments, two.treesAt(i)[t].segments);
    }
}

TEST(LightningInfill, PruningDrawsBranchEndsBack) {
    LightningForest forest;
    const int root = forest.addRoot({0, 0}, Point2{0, 0});
    const int middle = forest.addChild(root, {1'000, 0});
    forest.addChild(middle, {1'000, 500});  // short branch: gone
    forest.addChild(middle, {3'000, 0});    // long branch: 800 µm shorter
    EXPECT_EQ(pruneTree(forest, root, 800), 800);
    const std::vector<int>& children = forest.nodes[static_cast<std::size_t>(middle)].children;
    ASSERT_EQ(children.size(), 1U);
    EXPECT_EQ(forest.nodes[static_cast<std::size_t>(children[0])].p, (Point2{2'200, 0}));
}

TEST(LightningInfill, PatternPrintsTheTreesRootedInTheArea) {
    std::vector<LightningTreeLines> trees{{{0, 5'000}, {{{0, 5'000}, {4'000, 5'000}}}},
                                          {{30'000, 5'000}, {{{30'000, 5'000}, {26'000, 5'000}}}}};
    InfillParams p;
    p.pattern = infillPatternOf("lightning", "infill_pattern");
    p.line_distance_um = 3'200;
    p.overlap_um = 500;
    p.lightning_trees = &trees;
    const std::vector<ExtrusionPath> paths = generateInfill({test::square(0, 0, 10'000)}, p);
    ASSERT_EQ(paths.size(), 1U);
    EXPECT_EQ(paths[0].points, (Path{{0, 5'000}, {4'000, 5'000}}));
    p.lightning_trees = nullptr;
    EXPECT_TRUE(generateInfill({test::square(0, 0, 10'000)}, p).empty());
}

}  // namespace
}  // namespace mixengine
