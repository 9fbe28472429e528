// The nearest-triangle tree (mixing/fields/TriangleTree.h) against a scan of every triangle.
#include "mixing/fields/TriangleTree.h"

#include <gtest/gtest.h>

#include <random>

#include "mixing/fields/PaintedRegions.h"

namespace mixengine {
namespace {

TEST(TriangleTree, FindsWhatAScanOfEveryTriangleFinds) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> where(0, 100), size(-3, 3);
    std::vector<TriangleTree::Corners> triangles;
    for (int i = 0; i < 500; ++i) {
        const double x = where(random), y = where(random), z = where(random);
        triangles.push_back({x, y, z, x + size(random), y + size(random), z + size(random), x + size(random),
                             y + size(random), z + size(random)});
    }
    const TriangleTree tree(triangles);
    for (int q = 0; q < 300; ++q) {
        const double p[3] = {where(random), where(random), where(random)};
        double best = 1e300;
        for (const auto& t : triangles)
            best = std::min(best, squaredDistanceToTriangle(p, &t[0], &t[3], &t[6]));
        const auto [d, index] = tree.nearest(p, 1e300);
        ASSERT_GE(index, 0);
        EXPECT_EQ(d, best);
        const auto& t = triangles[static_cast<std::size_t>(index)];
        EXPECT_EQ(squaredDistanceToTriangle(p, &t[0], &t[3], &t[6]), best);
        EXPECT_EQ(tree.nearest(p, best).second, -1);  // nothing strictly nearer than the nearest
    }
    EXPECT_EQ(TriangleTree({}).nearest(triangles[0].data(), 1e300).second, -1);
}

}  // namespace
}  // namespace mixengine
