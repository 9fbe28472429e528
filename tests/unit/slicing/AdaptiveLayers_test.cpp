// Adaptive layer heights (slicing/AdaptiveLayers.h): steep walls take the largest height, a shallow
// slope the smallest, heights change by at most one step upwards, and the first layer is
// layer_height_0.
#include "slicing/AdaptiveLayers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/Error.h"

namespace mixengine {
namespace {

AdaptiveLayerParams params() {
    AdaptiveLayerParams p;
    p.layer_height_um = 200;
    p.layer_height_0_um = 200;
    p.variation_um = 100;
    p.step_um = 50;
    p.threshold_um = 200;
    return p;
}

TEST(AdaptiveLayers, VerticalWallsTakeTheLargestHeight) {
    const std::vector<FaceSlope> walls{{0, 3'000, std::numbers::pi / 2}};
    const std::vector<LayerZ> layers = adaptiveLayerHeights(walls, params());
    ASSERT_GE(layers.size(), 2U);
    EXPECT_EQ(layers[0].print_z, 200);
    for (std::size_t i = 1; i < layers.size(); ++i) {
        // from 200 µm up by one step a layer: 250, then 300 µm
        const coord_um expected = i == 1 ? 250 : 300;
        EXPECT_EQ(layers[i].print_z - layers[i - 1].print_z, expected) << i;
        EXPECT_EQ(layers[i].slice_z, layers[i].print_z);  // cut at the layer's top
        EXPECT_EQ(layers[i].bottom_z, layers[i - 1].print_z);
    }
    EXPECT_GE(layers.back().print_z, 3'000);
}

TEST(AdaptiveLayers, ShallowSlopeTakesTheSmallestHeight) {
    // A face 5° off the horizontal: every height leaves a step of h / tan(5°) > 200 µm, so the layer
    // takes the smallest height, 100 µm, at once (a fall of more than one step is allowed).
    const std::vector<FaceSlope> slope{{0, 2'000, 5.0 * std::numbers::pi / 180}};
    const std::vector<LayerZ> layers = adaptiveLayerHeights(slope, params());
    ASSERT_GT(layers.size(), 10U);
    for (std::size_t i = 1; i < layers.size(); ++i)
        EXPECT_EQ(layers[i].print_z - layers[i - 1].print_z, 100) << i;
}

TEST(AdaptiveLayers, HorizontalFacesDoNotCount) {
    // A horizontal face (angle π) next to a vertical one: the vertical one decides.
    const std::vector<FaceSlope> faces{{0, 3'000, std::numbers::pi / 2}, {1'000, 1'000, std::numbers::pi}};
    const std::vector<LayerZ> layers = adaptiveLayerHeights(faces, params());
    EXPECT_EQ(layers[2].print_z - layers[1].print_z, 300);
}

TEST(AdaptiveLayers, NonPositiveStepIsAnInputError) {
    AdaptiveLayerParams p = params();
    p.step_um = 0;
    EXPECT_THROW(adaptiveLayerHeights({}, p), InputError);
}

}  // namespace
}  // namespace mixengine
