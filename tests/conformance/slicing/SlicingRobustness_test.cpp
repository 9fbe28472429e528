// Slicing of awkward meshes: cavities, overlapping and touching shells, bad winding, holes.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "common/Error.h"
#include "conformance/slicing/TestMeshes.h"
#include "slicing/Slicer.h"

namespace mixengine {
namespace {

using test::addBox;
using test::MeshAssembler;

std::vector<double> sortedAreas(const Paths& paths) {
    std::vector<double> areas;
    for (const Path& path : paths)
        areas.push_back(ClipperLib::Area(path));
    std::sort(areas.begin(), areas.end());
    return areas;
}

void flipFaces(Mesh& mesh, std::initializer_list<std::size_t> faces) {
    for (std::size_t f : faces)
        std::swap(mesh.faces[f].v[1], mesh.faces[f].v[2]);
}

TEST(SlicingRobustness, CavityShellGivesOneOuterAndOneHole) {
    MeshAssembler m;
    addBox(m, {0, 0, 0}, {20'000, 20'000, 20'000});
    addBox(m, {5'000, 5'000, 5'000}, {15'000, 15'000, 15'000}, /*inverted=*/true);
    const Mesh mesh = m.take("box with cavity");
    const SlicedLayer layer = slicePlane(mesh, 10'000, SliceOptions{});
    EXPECT_EQ(sortedAreas(layer.outlines), (std::vector<double>{-100e6, 400e6}));
    // Outside the cavity's height range there is no hole.
    EXPECT_EQ(sortedAreas(slicePlane(mesh, 2'000, SliceOptions{}).outlines), (std::vector<double>{400e6}));
}

TEST(SlicingRobustness, CavityWithSomeFlippedFacetsIsStillAHole) {
    MeshAssembler m;
    addBox(m, {0, 0, 0}, {20'000, 20'000, 20'000});
    addBox(m, {5'000, 5'000, 5'000}, {15'000, 15'000, 15'000}, true);
    Mesh mesh = m.take("cavity, mixed winding");
    flipFaces(mesh, {16, 17, 20});  // two triangles of one inner side and one of another
    EXPECT_EQ(sortedAreas(slicePlane(mesh, 10'000, SliceOptions{}).outlines),
              (std::vector<double>{-100e6, 400e6}));
}

TEST(SlicingRobustness, OverlappingCubesAreUnited) {
    MeshAssembler m;
    addBox(m, {0, 0, 0}, {10'000, 10'000, 10'000});
    addBox(m, {5'000, 5'000, 0}, {15'000, 15'000, 10'000});
    const SlicedLayer layer = slicePlane(m.take("two cubes"), 5'000, SliceOptions{});
    ASSERT_EQ(layer.outlines.size(), 1U);
    EXPECT_DOUBLE_EQ(ClipperLib::Area(layer.outlines[0]), 175e6);
    EXPECT_EQ(layer.outlines[0].size(), 8U);
}

TEST(SlicingRobustness, CubeNestedInACubeWithOutwardWindingIsUnited) {
    MeshAssembler m;
    addBox(m, {0, 0, 0}, {20'000, 20'000, 20'000});
    addBox(m, {5'000, 5'000, 5'000}, {15'000, 15'000, 15'000});
    EXPECT_EQ(sortedAreas(slicePlane(m.take("nested solids"), 10'000, SliceOptions{}).outlines),
              (std::vector<double>{400e6}));
}

TEST(SlicingRobustness, CubesTouchingAlongAnEdgeStayTwoSquares) {
    MeshAssembler m;
    addBox(m, {0, 0, 0}, {10'000, 10'000, 10'000});
    addBox(m, {10'000, 10'000, 0}, {20'000, 20'000, 10'000});
    const SlicedLayer layer = slicePlane(m.take("touching cubes"), 5'000, SliceOptions{});
    EXPECT_TRUE(layer.open_polylines.empty());
    double total = 0;
    for (const Path& path : layer.outlines)
        total += ClipperLib::Area(path);
    EXPECT_DOUBLE_EQ(total, 200e6);
}

TEST(SlicingRobustness, InconsistentWindingStillGivesOneSquare) {
    Mesh cube = test::box({0, 0, 0}, {10'000, 10'000, 10'000});
    flipFaces(cube, {2, 5, 7, 10});
    for (coord_um z = 50; z < 10'000; z += 700) {
        const SlicedLayer layer = slicePlane(cube, z, SliceOptions{});
        ASSERT_EQ(layer.outlines.size(), 1U) << z;
        EXPECT_DOUBLE_EQ(ClipperLib::Area(layer.outlines[0]), 100e6);
        EXPECT_EQ(layer.outlines[0].size(), 4U);
    }
}

TEST(SlicingRobustness, InsideOutCubeStillGivesOneCounterClockwiseSquare) {
    MeshAssembler m;
    addBox(m, {0, 0, 0}, {10'000, 10'000, 10'000}, true);
    EXPECT_EQ(sortedAreas(slicePlane(m.take("inside out"), 5'000, SliceOptions{}).outlines),
              (std::vector<double>{100e6}));
}

TEST(SlicingRobustness, OpenMeshReportsOpenPiecesOrClosesSmallGaps) {
    Mesh cube = test::box({0, 0, 0}, {10'000, 10'000, 10'000});
    cube.faces.erase(cube.faces.begin() + 4);  // one triangle of a side face
    std::ostringstream messages;
    Log log(messages);
    const std::vector<SlicedLayer> layers = sliceMesh(cube, computeLayerHeights(10'000, 200, 100), {}, log);
    std::size_t closed = 0, open = 0;
    for (const SlicedLayer& layer : layers) {
        EXPECT_TRUE(!layer.outlines.empty() || !layer.open_polylines.empty()) << layer.slice_z;
        if (layer.open_polylines.empty()) {
            ++closed;
            ASSERT_EQ(layer.outlines.size(), 1U);
            EXPECT_NEAR(ClipperLib::Area(layer.outlines[0]), 100e6, 100e6 * 0.01);
        } else {
            ++open;
            EXPECT_TRUE(layer.outlines.empty());  // an open piece never becomes solid
        }
    }
    EXPECT_GT(closed, 0U);  // near the bottom and top the gap is within max_gap_um
    EXPECT_GT(open, 0U);
    EXPECT_NE(messages.str().find("is not closed"), std::string::npos);
    EXPECT_EQ(log.warningCount(), 1);
}

TEST(SlicingRobustness, ResultDoesNotDependOnTheThreadCount) {
    MeshAssembler m;
    addBox(m, {0, 0, 0}, {20'000, 20'000, 20'000});
    addBox(m, {5'000, 5'000, 5'000}, {15'000, 15'000, 15'000}, true);
    const Mesh mesh = m.take("box with cavity");
    std::ostringstream sink;
    Log log(sink);
    const std::vector<LayerZ> heights = computeLayerHeights(20'000, 300, 150);
    SliceOptions one;
    one.threads = 1;
    SliceOptions three;
    three.threads = 3;
    const std::vector<SlicedLayer> a = sliceMesh(mesh, heights, one, log);
    const std::vector<SlicedLayer> b = sliceMesh(mesh, heights, three, log);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].outlines, b[i].outlines);
        EXPECT_EQ(a[i].print_z, heights[i].print_z);
    }
}

TEST(SlicingRobustness, RejectsMeshesBeyondTheExactRange) {
    Mesh cube = test::box({0, 0, 0}, {10'000, 10'000, 10'000});
    cube.vertices[0].x = 2'000'000'000;
    EXPECT_THROW(slicePlane(cube, 5'000, SliceOptions{}), InputError);
    Mesh broken = test::box({0, 0, 0}, {10'000, 10'000, 10'000});
    broken.faces[0].v[0] = 999;
    EXPECT_THROW(slicePlane(broken, 5'000, SliceOptions{}), InternalError);
}

TEST(SlicingRobustness, EmptyMeshAndNoLayers) {
    std::ostringstream sink;
    Log log(sink);
    EXPECT_TRUE(sliceMesh(Mesh{}, computeLayerHeights(1'000, 200, 100), {}, log)[0].outlines.empty());
    EXPECT_TRUE(sliceMesh(test::box({0, 0, 0}, {1'000, 1'000, 1'000}), {}, {}, log).empty());
}

}  // namespace
}  // namespace mixengine
