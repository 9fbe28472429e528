// A large closed mesh, the 832k-triangle armadillo's size class (≈ 75 mm tall, 0.2 mm layers),
// slices into closed outlines on every layer. Its speed is measured, not asserted:
// tests/bench/micro/slice_sphere_bench.cpp (tests/bench/micro.sh).
#include <gtest/gtest.h>

#include <sstream>

#include "conformance/slicing/TestMeshes.h"
#include "slicing/Slicer.h"

namespace mixengine {
namespace {

TEST(SlicingLargeMesh, BumpySphereOf832kTrianglesSlicesIntoClosedOutlines) {
    const Mesh sphere = test::bumpySphere(645, 646, 37'500);
    ASSERT_EQ(sphere.faces.size(), 832'048U);
    const std::vector<LayerZ> heights = computeLayerHeights(sphere.bounds().max.z, 200, 200);
    std::ostringstream sink;
    Log log(sink);
    SliceOptions options;
    options.threads = 2;
    const std::vector<SlicedLayer> layers = sliceMesh(sphere, heights, options, log);
    std::size_t with_outline = 0;
    for (const SlicedLayer& layer : layers) {
        EXPECT_TRUE(layer.open_polylines.empty());
        with_outline += layer.outlines.empty() ? 0 : 1;
    }
    EXPECT_GE(with_outline + 2, layers.size());
}

}  // namespace
}  // namespace mixengine
