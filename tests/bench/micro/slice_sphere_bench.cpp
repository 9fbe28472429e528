// Slicing speed on a large closed mesh: an 832,048-triangle bumpy sphere (the 832k armadillo's size
// class, ≈ 75 mm tall) in 0.2 mm layers on 2 threads. Prints wall and CPU time; no threshold.
// Its correctness on the same mesh is tested in tests/conformance/slicing/SlicingLargeMesh_test.cpp.
#include <sstream>

#include "bench/micro/Stopwatch.h"
#include "conformance/slicing/TestMeshes.h"
#include "slicing/Slicer.h"

int main() {
    using namespace mixengine;
    const Mesh sphere = test::bumpySphere(645, 646, 37'500);
    const std::vector<LayerZ> heights = computeLayerHeights(sphere.bounds().max.z, 200, 200);
    std::ostringstream sink;
    Log log(sink);
    SliceOptions options;
    options.threads = 2;
    std::size_t layer_count = 0;
    const bench::Timing t =
        bench::timed([&] { layer_count = sliceMesh(sphere, heights, options, log).size(); });
    const std::string what = std::to_string(sphere.faces.size()) + " triangles, " +
                             std::to_string(layer_count) + " layers, 2 threads";
    bench::printTiming("slice_sphere", t, what.c_str());
    return 0;
}
