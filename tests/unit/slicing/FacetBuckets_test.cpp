#include "slicing/FacetBuckets.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/Error.h"

namespace mixengine {
namespace {

Mesh threeFacets() {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {10, 0, 100}, {0, 10, 50}, {5, 5, 300}, {0, 0, 300}, {9, 9, 300}};
    mesh.faces = {{{0, 1, 2}}, {{1, 2, 3}}, {{3, 4, 5}}};  // z-ranges [0,100], [50,300], [300,300]
    return mesh;
}

TEST(SlicingBuckets, EachPlaneListsExactlyTheFacetsSpanningIt) {
    const Mesh mesh = threeFacets();
    const std::vector<coord_um> planes{-10, 0, 50, 50, 100, 200, 300, 400};
    const FacetBuckets buckets(mesh, planes);
    ASSERT_EQ(buckets.planeCount(), planes.size());
    const std::vector<std::vector<std::uint32_t>> expected{{}, {0}, {0, 1}, {0, 1}, {0, 1}, {1}, {1, 2}, {}};
    std::size_t entries = 0;
    for (std::size_t p = 0; p < planes.size(); ++p) {
        const auto span = buckets.facetsAt(p);
        EXPECT_EQ(std::vector<std::uint32_t>(span.begin(), span.end()), expected[p]) << "plane " << p;
        entries += expected[p].size();
    }
    EXPECT_EQ(buckets.entryCount(), entries);
}

TEST(SlicingBuckets, RejectsUnsortedPlanes) {
    EXPECT_THROW(FacetBuckets(threeFacets(), {100, 0}), InternalError);
}

}  // namespace
}  // namespace mixengine
