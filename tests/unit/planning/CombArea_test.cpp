// The comb area of a planned layer (planning/PrintPlanner.h combArea): every mesh's sliced outlines
// of that layer, counted from the first sliced layer the toolpath stage kept.
#include <gtest/gtest.h>

#include "planning/PrintPlanner.h"
#include "planning/TravelAreas.h"

namespace mixengine {
namespace {

std::vector<SlicedLayer> layersWith(const std::vector<Paths>& outlines) {
    std::vector<SlicedLayer> layers(outlines.size());
    for (std::size_t i = 0; i < outlines.size(); ++i)
        layers[i].outlines = outlines[i];
    return layers;
}

TEST(CombArea, EveryMeshsOutlinesOfTheSlicedLayerAfterTheDroppedOnes) {
    const Path a0{{0, 0}, {10, 0}, {10, 10}}, a1{{0, 0}, {20, 0}, {20, 20}}, b1{{5, 5}, {7, 5}, {7, 7}};
    const std::vector<SlicedLayer> a = layersWith({{a0}, {a1}});
    const std::vector<SlicedLayer> b = layersWith({{}, {b1}});
    GroupToolpaths toolpaths;
    toolpaths.meshes.resize(2);
    toolpaths.meshes[0].sliced = &a;
    toolpaths.meshes[1].sliced = &b;
    EXPECT_EQ(combArea(toolpaths, 0), (Paths{a0}));
    EXPECT_EQ(combArea(toolpaths, 1), (Paths{a1, b1}));
    toolpaths.first_sliced_layer = 1;
    EXPECT_EQ(combArea(toolpaths, 0), (Paths{a1, b1}));
    EXPECT_TRUE(combArea(toolpaths, 1).empty());  // past the sliced layers
}

}  // namespace
}  // namespace mixengine
