#include "slicing/LayerHeights.h"

#include <gtest/gtest.h>

#include "common/Error.h"

namespace mixengine {
namespace {

TEST(LayerHeights, TenMillimetreCubeWithCuraTestSettings) {
    const std::vector<LayerZ> layers = computeLayerHeights(10'000, 200, 100);
    ASSERT_EQ(layers.size(), 99U);  // floor((10 − 0.2) / 0.1) + 1
    EXPECT_EQ(layers[0].print_z, 200);
    EXPECT_EQ(layers[0].bottom_z, 0);
    EXPECT_EQ(layers[0].slice_z, 100);
    EXPECT_EQ(layers[1].print_z, 300);
    EXPECT_EQ(layers[1].bottom_z, 200);
    EXPECT_EQ(layers[1].slice_z, 250);
    EXPECT_EQ(layers.back().print_z, 10'000);
    EXPECT_EQ(layers.back().slice_z, 9'950);
}

// CuraEngine 4.13 counts the cutting planes at or below z_max: the first at h0 − h/2 (its
// initial_slice_z), then every h. That is floor((z_max − h0 + h/2) / h) + 1; test-corpus §8.1's
// floor((z_max − h0) / h) + 1 agrees whenever the fractional part of (z_max − h0) / h is below ½.
TEST(LayerHeights, CountFollowsCuraEnginesFormula) {
    struct Case {
        coord_um max_z, h0, h;
        std::size_t expected;
    };
    const Case cases[] = {
        {200, 200, 100, 1},      {249, 200, 100, 1},      {250, 200, 100, 2},   {300, 200, 100, 2},
        {20'000, 300, 200, 100}, {75'000, 200, 200, 375}, {1'000, 300, 150, 6}, {10'000, 270, 60, 163},
        {150, 200, 100, 1},      {100, 200, 100, 1},      {99, 200, 100, 0},    {1, 200, 100, 0},
    };
    for (const Case& c : cases) {
        const std::vector<LayerZ> layers = computeLayerHeights(c.max_z, c.h0, c.h);
        EXPECT_EQ(layers.size(), c.expected) << c.max_z << ' ' << c.h0 << ' ' << c.h;
        if (!layers.empty()) {
            // The last layer's plane at h0 − h/2 + (n − 1)·h is at or below the top, the next one above.
            const coord_um last_plane = c.h0 - c.h / 2 + static_cast<coord_um>(layers.size() - 1) * c.h;
            if (layers.size() > 1) {
                EXPECT_LE(last_plane, c.max_z);
            }
            EXPECT_GT(last_plane + c.h, c.max_z);
        }
    }
}

TEST(LayerHeights, CorpusFormulaAgreesBelowTheHalfLayer) {
    // test-corpus §8.1: floor((z_max − h0) / h) + 1, e.g. the 10 mm cube (99) and a 20 mm cube.
    EXPECT_EQ(computeLayerHeights(10'000, 200, 100).size(), 99U);
    EXPECT_EQ(computeLayerHeights(20'000, 200, 100).size(), 199U);
    EXPECT_EQ(computeLayerHeights(20'000, 300, 200).size(), (20'000 - 300) / 200 + 2U);  // fraction ½
}

TEST(LayerHeights, SlabsTileWithoutGaps) {
    const std::vector<LayerZ> layers = computeLayerHeights(5'000, 300, 150);
    for (std::size_t i = 1; i < layers.size(); ++i) {
        EXPECT_EQ(layers[i].bottom_z, layers[i - 1].print_z);
        EXPECT_GT(layers[i].slice_z, layers[i].bottom_z);
        EXPECT_LT(layers[i].slice_z, layers[i].print_z);
    }
}

TEST(LayerHeights, EmptyModelAndInvalidHeights) {
    EXPECT_TRUE(computeLayerHeights(0, 200, 100).empty());
    EXPECT_TRUE(computeLayerHeights(-5, 200, 100).empty());
    EXPECT_THROW(computeLayerHeights(1000, 0, 100), InputError);
    EXPECT_THROW(computeLayerHeights(1000, 200, -1), InputError);
}

}  // namespace
}  // namespace mixengine
