// Sliding-window intersections and unions (toolpaths/core/LayerWindows.h) against the direct definition.
#include "toolpaths/core/LayerWindows.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

/// Layer i: a 10 mm square shifted right by i mm (so windows shrink or grow predictably).
std::vector<Paths> sliding(int count) {
    std::vector<Paths> layers;
    for (int i = 0; i < count; ++i)
        layers.push_back({test::square(i * 1'000, 0, 10'000)});
    return layers;
}

TEST(LayerWindows, MatchTheDirectDefinitionForEveryWindow) {
    const std::vector<Paths> layers = sliding(13);
    for (int window = 1; window <= 8; ++window) {  // doubling (2, 4, 8) and blocks (3, 5, 6, 7)
        for (int threads : {1, 2}) {
            const std::vector<Paths> inter = windowIntersections(layers, window, threads);
            const std::vector<Paths> uni = windowUnions(layers, window, threads);
            ASSERT_EQ(inter.size(), layers.size());
            for (std::size_t i = 0; i < layers.size(); ++i) {
                if (i + window > layers.size()) {
                    EXPECT_TRUE(inter[i].empty()) << window << " " << i;
                    EXPECT_TRUE(uni[i].empty()) << window << " " << i;
                    continue;
                }
                // Squares shifted 1 mm per layer: the intersection is (10 − (w − 1)) × 10 mm, the
                // union (10 + (w − 1)) × 10 mm.
                EXPECT_EQ(areaUm2(inter[i]), (10 - (window - 1)) * 10e6) << window << " " << i;
                EXPECT_EQ(areaUm2(uni[i]), (10 + (window - 1)) * 10e6) << window << " " << i;
            }
        }
    }
}

TEST(LayerWindows, EmptyLayerEmptiesEveryWindowThroughIt) {
    std::vector<Paths> layers(7, Paths{test::square(0, 0, 10'000)});
    layers[3].clear();
    const std::vector<Paths> inter = windowIntersections(layers, 3, 2);
    EXPECT_EQ(areaUm2(inter[0]), 100e6);
    for (std::size_t i : {1U, 2U, 3U})
        EXPECT_TRUE(inter[i].empty()) << i;
    EXPECT_EQ(areaUm2(inter[4]), 100e6);
    EXPECT_TRUE(windowIntersections(layers, 0, 1)[0].empty());
}

}  // namespace
}  // namespace mixengine
