// Speed on a large closed mesh: the 832k-triangle armadillo's size class (≈ 75 mm tall, 0.2 mm
// layers) must slice well under a second on 2 cores; the limit here is loose (shared CI machines,
// debug builds) and the measured time is printed.
#include <gtest/gtest.h>

#include <chrono>
#include <ctime>
#include <iostream>
#include <sstream>

#include "conformance/slicing/TestMeshes.h"
#include "slicing/Slicer.h"

namespace mixengine {
namespace {

TEST(SlicingPerformance, BumpySphereOf832kTrianglesSlicesQuickly) {
    const Mesh sphere = test::bumpySphere(645, 646, 37'500);
    ASSERT_EQ(sphere.faces.size(), 832'048U);
    const std::vector<LayerZ> heights = computeLayerHeights(sphere.bounds().max.z, 200, 200);
    std::ostringstream sink;
    Log log(sink);
    SliceOptions options;
    options.threads = 2;
    const std::clock_t cpu_start = std::clock();
    const auto start = std::chrono::steady_clock::now();
    const std::vector<SlicedLayer> layers = sliceMesh(sphere, heights, options, log);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    std::cout << "[ timing   ] " << sphere.faces.size() << " triangles, " << layers.size()
              << " layers: " << seconds << " s wall on 2 threads, " << cpu_seconds
              << " s CPU in all threads\n";
    std::size_t with_outline = 0;
    for (const SlicedLayer& layer : layers) {
        EXPECT_TRUE(layer.open_polylines.empty());
        with_outline += layer.outlines.empty() ? 0 : 1;
    }
    EXPECT_GE(with_outline + 2, layers.size());
    EXPECT_LT(seconds, 5.0);
}

}  // namespace
}  // namespace mixengine
