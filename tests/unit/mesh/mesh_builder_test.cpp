#include <gtest/gtest.h>

#include <limits>

#include "mesh/build/MeshBuilder.h"
#include "unit/mesh/MeshTestFiles.h"

namespace mixengine {
namespace {

using test::contains;
using test::cubeTriangles;
using test::inputErrorOf;

TriangleSoup cubeSoup(double size = 10.0) {
    TriangleSoup soup;
    soup.name = "cube";
    soup.triangles = cubeTriangles(size);
    return soup;
}

TEST(MeshBuilder, WeldsCubeSoupToEightVertices) {
    MeshBuildStats stats;
    const Mesh mesh = buildMesh(cubeSoup(), Matrix3{}, &stats);
    EXPECT_EQ(mesh.name, "cube");
    EXPECT_EQ(mesh.vertices.size(), 8U);
    EXPECT_EQ(mesh.faces.size(), 12U);
    EXPECT_EQ(stats.input_triangles, 12U);
    EXPECT_EQ(stats.degenerate_dropped, 0U);
    EXPECT_EQ(stats.duplicates_dropped, 0U);
    EXPECT_EQ(stats.welded_vertices, 8U);
    // First face of the soup is (0,0,0) (10,10,0) (10,0,0): vertices numbered in order of first use.
    EXPECT_EQ(mesh.vertices[0], (Point3{0, 0, 0}));
    EXPECT_EQ(mesh.vertices[1], (Point3{10000, 10000, 0}));
    EXPECT_EQ(mesh.vertices[2], (Point3{10000, 0, 0}));
    EXPECT_EQ(mesh.faces[0].v, (std::array<std::uint32_t, 3>{0, 1, 2}));
}

TEST(MeshBuilder, WeldsPointsThatRoundToTheSameMicron) {
    TriangleSoup soup;
    soup.triangles = {{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}},
                      {Vec3{1.0004, 0, 0}, Vec3{0.0001, 0.9996, 0}, Vec3{1, 1, 0}}};
    MeshBuildStats stats;
    const Mesh mesh = buildMesh(soup, Matrix3{}, &stats);
    EXPECT_EQ(mesh.vertices.size(), 4U);
    EXPECT_EQ(mesh.faces.size(), 2U);
    EXPECT_EQ(mesh.faces[1].v, (std::array<std::uint32_t, 3>{1, 2, 3}));
}

TEST(MeshBuilder, DropsDegenerateFaces) {
    TriangleSoup soup = cubeSoup();
    soup.triangles.push_back({Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{5, 5, 5}});  // repeated corner
    soup.triangles.push_back({Vec3{0, 0, 0}, Vec3{1, 1, 1}, Vec3{3, 3, 3}});  // collinear
    soup.triangles.push_back(
        {Vec3{50, 0, 0}, Vec3{50.0001, 0, 0}, Vec3{50, 0.0002, 0}});  // collapses in microns
    MeshBuildStats stats;
    const Mesh mesh = buildMesh(soup, Matrix3{}, &stats);
    EXPECT_EQ(mesh.faces.size(), 12U);
    EXPECT_EQ(mesh.vertices.size(), 8U);  // the degenerate faces' own points are not kept
    EXPECT_EQ(stats.input_triangles, 15U);
    EXPECT_EQ(stats.degenerate_dropped, 3U);
    EXPECT_EQ(stats.duplicates_dropped, 0U);
}

TEST(MeshBuilder, DropsDuplicateFacesInAnyOrderOrWinding) {
    TriangleSoup soup = cubeSoup();
    const auto first = soup.triangles[0];
    soup.triangles.push_back(first);                           // exact copy
    soup.triangles.push_back({first[1], first[2], first[0]});  // rotated
    soup.triangles.push_back({first[0], first[2], first[1]});  // flipped winding
    MeshBuildStats stats;
    const Mesh mesh = buildMesh(soup, Matrix3{}, &stats);
    EXPECT_EQ(mesh.faces.size(), 12U);
    EXPECT_EQ(stats.duplicates_dropped, 3U);
    EXPECT_EQ(stats.degenerate_dropped, 0U);
    EXPECT_EQ(stats.welded_vertices, 8U);
}

TEST(MeshBuilder, AppliesScaleAndRotation) {
    Matrix3 transform;  // scale x by 2, then swap: x' = -y, y' = 2x, z' = 0.5 z
    transform.m[0][0] = 0;
    transform.m[0][1] = -1;
    transform.m[1][0] = 2;
    transform.m[1][1] = 0;
    transform.m[2][2] = 0.5;
    const Mesh mesh = buildMesh(cubeSoup(), transform, nullptr);
    const AABB3 box = mesh.bounds();
    EXPECT_EQ(box.min, (Point3{-10000, 0, 0}));
    EXPECT_EQ(box.max, (Point3{0, 20000, 5000}));
    EXPECT_EQ(mesh.vertices.size(), 8U);
    EXPECT_EQ(mesh.faces.size(), 12U);
}

TEST(MeshBuilder, RoundsHalfMicronsAwayFromZero) {
    TriangleSoup soup;
    soup.triangles = {{Vec3{0.0004, -0.0006, 0.0015}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}};
    const Mesh mesh = buildMesh(soup, Matrix3{}, nullptr);
    EXPECT_EQ(mesh.vertices[0], (Point3{0, -1, 2}));
}

TEST(MeshBuilder, CoordinateOutsideRangeIsError) {
    TriangleSoup soup = cubeSoup();
    soup.name = "huge";
    soup.triangles[3][2].z = 2e6;
    EXPECT_TRUE(
        contains(inputErrorOf([&] { buildMesh(soup, Matrix3{}, nullptr); }), "huge: vertex coordinate"));
}

TEST(MeshBuilder, NanFromTransformIsError) {
    Matrix3 transform;
    transform.m[1][1] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(contains(inputErrorOf([&] { buildMesh(cubeSoup(), transform, nullptr); }), "cube: "));
}

TEST(MeshBuilder, EmptySoupGivesEmptyMesh) {
    MeshBuildStats stats;
    const Mesh mesh = buildMesh(TriangleSoup{}, Matrix3{}, &stats);
    EXPECT_TRUE(mesh.vertices.empty());
    EXPECT_TRUE(mesh.faces.empty());
    EXPECT_EQ(stats.welded_vertices, 0U);
}

TEST(MeshBuilder, UnweldedSoupGrowsTheTable) {
    TriangleSoup soup;  // 3000 separate triangles: 9000 distinct vertices, well past the first estimate
    for (int i = 0; i < 3000; ++i) {
        const double x = i * 3.0;
        soup.triangles.push_back({Vec3{x, 0, 0}, Vec3{x + 1, 0, 0}, Vec3{x, 1, 0}});
    }
    MeshBuildStats stats;
    const Mesh mesh = buildMesh(soup, Matrix3{}, &stats);
    EXPECT_EQ(mesh.vertices.size(), 9000U);
    EXPECT_EQ(mesh.faces.size(), 3000U);
    EXPECT_EQ(mesh.vertices[8999], (Point3{8997000, 1000, 0}));
}

}  // namespace
}  // namespace mixengine
