// Slicing conformance (test-corpus.md §8.1, CuraEngine's SlicePhase tests, seed 003).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "conformance/slicing/TestMeshes.h"
#include "slicing/Slicer.h"

namespace mixengine {
namespace {

using test::box;

/// `actual` equals `expected` as a cyclic sequence (any start vertex, same direction).
bool sameCycle(const Path& actual, const Path& expected) {
    if (actual.size() != expected.size())
        return false;
    for (std::size_t shift = 0; shift < actual.size(); ++shift) {
        bool all = true;
        for (std::size_t i = 0; i < actual.size() && all; ++i) {
            all = actual[(i + shift) % actual.size()] == expected[i];
        }
        if (all)
            return true;
    }
    return false;
}

std::string describe(const Path& path) {
    std::ostringstream out;
    for (const Point2& p : path)
        out << '(' << p.X << ',' << p.Y << ") ";
    return out.str();
}

double totalArea(const Paths& paths) {
    double area = 0;
    for (const Path& path : paths)
        area += ClipperLib::Area(path);
    return area;
}

/// Area of the symmetric difference (Clipper xor) of two polygons.
double xorArea(const Path& a, const Path& b) {
    ClipperLib::Clipper clipper;
    clipper.AddPath(a, ClipperLib::ptSubject, true);
    clipper.AddPath(b, ClipperLib::ptClip, true);
    Paths difference;
    clipper.Execute(ClipperLib::ctXor, difference, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    double area = 0;
    for (const Path& p : difference)
        area += std::abs(ClipperLib::Area(p));
    return area;
}

std::vector<SlicedLayer> sliceCuraStyle(const Mesh& mesh,
                                        SlicingTolerance tolerance = SlicingTolerance::Middle) {
    std::ostringstream sink;
    Log log(sink);
    SliceOptions options;
    options.tolerance = tolerance;
    return sliceMesh(mesh, computeLayerHeights(mesh.bounds().max.z, 200, 100), options, log);
}

TEST(SlicingConformance, TenMillimetreCubeGivesTheExactSquareInEveryLayer) {
    const Mesh cube = box({0, 0, 0}, {10'000, 10'000, 10'000});
    const std::vector<SlicedLayer> layers = sliceCuraStyle(cube);
    ASSERT_EQ(layers.size(), 99U);
    const Path expected{{0, 0}, {10'000, 0}, {10'000, 10'000}, {0, 10'000}};
    for (const SlicedLayer& layer : layers) {
        ASSERT_EQ(layer.outlines.size(), 1U) << "z " << layer.slice_z;
        EXPECT_TRUE(sameCycle(layer.outlines[0], expected))
            << "z " << layer.slice_z << ": " << describe(layer.outlines[0]);
        EXPECT_TRUE(layer.open_polylines.empty());
    }
}

TEST(SlicingConformance, OffCentreCubeKeepsItsCornersAndCounterClockwiseOrder) {
    const Mesh cube = box({-3'000, 7'000, 0}, {7'000, 17'000, 10'000});
    const std::vector<SlicedLayer> layers = sliceCuraStyle(cube, SlicingTolerance::Inclusive);
    const Path expected{{-3'000, 7'000}, {7'000, 7'000}, {7'000, 17'000}, {-3'000, 17'000}};
    for (const SlicedLayer& layer : layers) {
        ASSERT_EQ(layer.outlines.size(), 1U);
        EXPECT_TRUE(sameCycle(layer.outlines[0], expected)) << describe(layer.outlines[0]);
    }
}

TEST(SlicingConformance, ThousandGonCylinderMatchesTheCircle) {
    const coord_um radius = 10'000;
    const Mesh cylinder = test::cylinder(1000, radius, 10'000);
    ASSERT_EQ(cylinder.faces.size(), 4000U);
    const Path ideal = test::regularPolygon(1000, radius);
    const double circle = std::numbers::pi * static_cast<double>(radius) * static_cast<double>(radius);
    const double ideal_area = ClipperLib::Area(ideal);
    const std::vector<SlicedLayer> layers = sliceCuraStyle(cylinder);
    ASSERT_EQ(layers.size(), 99U);
    for (const SlicedLayer& layer : layers) {
        ASSERT_EQ(layer.outlines.size(), 1U) << "z " << layer.slice_z;
        EXPECT_NEAR(ClipperLib::Area(layer.outlines[0]) / circle, 1.0, 0.002) << "z " << layer.slice_z;
        EXPECT_LE(xorArea(layer.outlines[0], ideal) / ideal_area, 0.002) << "z " << layer.slice_z;
    }
}

TEST(SlicingConformance, CubeCutExactlyAtItsVertexHeightsIncludingTheTop) {
    const Mesh cube = box({0, 0, 0}, {20'000, 20'000, 20'000}, 2'000);
    ASSERT_EQ(cube.faces.size(), 4U + 4U * 10U * 2U);
    const SliceOptions options;
    for (coord_um z = 2'000; z <= 20'000; z += 2'000) {
        const SlicedLayer layer = slicePlane(cube, z, options);
        ASSERT_EQ(layer.outlines.size(), 1U) << "z " << z;
        EXPECT_DOUBLE_EQ(ClipperLib::Area(layer.outlines[0]), 400e6) << "z " << z;
        EXPECT_EQ(layer.outlines[0].size(), 4U);
        EXPECT_TRUE(layer.open_polylines.empty());
    }
    // The bottom-tangent plane does not count (a downward-facing face in the plane is outside).
    EXPECT_TRUE(slicePlane(cube, 0, options).outlines.empty());
    EXPECT_TRUE(slicePlane(cube, 20'001, options).outlines.empty());
}

TEST(SlicingConformance, VertexHeightsThroughSliceMeshToo) {
    const Mesh cube = box({0, 0, 0}, {20'000, 20'000, 20'000}, 2'000);
    std::vector<LayerZ> layers;
    for (coord_um z = 2'000; z <= 20'000; z += 2'000)
        layers.push_back({z, z - 2'000, z});
    std::ostringstream sink;
    Log log(sink);
    for (SlicingTolerance tolerance :
         {SlicingTolerance::Middle, SlicingTolerance::Inclusive, SlicingTolerance::Exclusive}) {
        SliceOptions options;
        options.tolerance = tolerance;
        const std::vector<SlicedLayer> sliced = sliceMesh(cube, layers, options, log);
        for (std::size_t i = 0; i < sliced.size(); ++i) {
            // As CuraEngine 4.13: exclusive intersects layer 0 with the cut through the cube's bottom
            // face (nothing) and leaves the last layer empty.
            if (tolerance == SlicingTolerance::Exclusive && (i == 0 || i + 1 == sliced.size())) {
                EXPECT_TRUE(sliced[i].outlines.empty()) << i;
                continue;
            }
            ASSERT_EQ(sliced[i].outlines.size(), 1U) << "z " << sliced[i].print_z;
            EXPECT_DOUBLE_EQ(ClipperLib::Area(sliced[i].outlines[0]), 400e6);
        }
    }
}

TEST(SlicingConformance, OctahedronCutThroughItsEquatorVertices) {
    const coord_um r = 10'000;
    const Mesh octahedron = test::octahedron({0, 0, r}, r);
    const SlicedLayer layer = slicePlane(octahedron, r, SliceOptions{});
    ASSERT_EQ(layer.outlines.size(), 1U);
    EXPECT_TRUE(sameCycle(layer.outlines[0], Path{{r, 0}, {0, r}, {-r, 0}, {0, -r}}))
        << describe(layer.outlines[0]);
    EXPECT_TRUE(layer.open_polylines.empty());
    // Through one apex only: a single-vertex touch, nothing at all.
    EXPECT_TRUE(slicePlane(octahedron, 2 * r, SliceOptions{}).outlines.empty());
    EXPECT_TRUE(slicePlane(octahedron, 0, SliceOptions{}).outlines.empty());
}

TEST(SlicingConformance, TotalAreaOfAPyramidFollowsTheTolerance) {
    const coord_um half = 10'000;
    const Mesh pyramid = test::pyramid(half, 10'000);
    const auto side_at = [&](coord_um z) { return 2.0 * half * (1.0 - static_cast<double>(z) / 10'000); };
    const std::vector<SlicedLayer> middle = sliceCuraStyle(pyramid, SlicingTolerance::Middle);
    const std::vector<SlicedLayer> inclusive = sliceCuraStyle(pyramid, SlicingTolerance::Inclusive);
    const std::vector<SlicedLayer> exclusive = sliceCuraStyle(pyramid, SlicingTolerance::Exclusive);
    const std::vector<LayerZ> heights = computeLayerHeights(10'000, 200, 100);
    ASSERT_EQ(middle.size(), heights.size());
    for (std::size_t i = 0; i + 1 < heights.size(); ++i) {
        const double relative = 1e-3;
        const double at_middle = std::pow(side_at(heights[i].slice_z), 2);
        const double at_bottom = std::pow(side_at(heights[i].bottom_z), 2);
        const double at_top = std::pow(side_at(heights[i].print_z), 2);
        EXPECT_NEAR(totalArea(middle[i].outlines), at_middle, at_middle * relative) << i;
        // Inclusive layer 0: the cut through the base at z = 0 is empty, so the top cut is all.
        const double inclusive_area = i == 0 ? at_top : at_bottom;
        EXPECT_NEAR(totalArea(inclusive[i].outlines), inclusive_area, inclusive_area * relative) << i;
        EXPECT_NEAR(totalArea(exclusive[i].outlines), at_top, at_top * relative) << i;
    }
    EXPECT_TRUE(exclusive.back().outlines.empty());  // the top slab ends at the apex
}

}  // namespace
}  // namespace mixengine
