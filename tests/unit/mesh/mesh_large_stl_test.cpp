// A large binary STL (832,050 triangles) loads and builds into the indexed mesh it describes. Its
// speed is measured, not asserted: tests/bench/micro/mesh_load_bench.cpp (tests/bench/micro.sh).
#include <gtest/gtest.h>

#include "mesh/build/MeshBuilder.h"
#include "mesh/formats/ModelReader.h"
#include "unit/mesh/MeshTestFiles.h"

namespace mixengine {
namespace {

TEST(MeshLargeStl, LargeBinaryStlLoadsAndBuilds) {
    test::TempDir dir;
    const auto file = dir.write("grid.stl", test::binaryStl(test::wavyGridTriangles()));
    ASSERT_EQ(std::filesystem::file_size(file), 84U + 50U * 832050U);

    std::vector<std::string> warnings;
    const auto parts = readModelFile(file, warnings);
    MeshBuildStats stats;
    const Mesh mesh = buildMesh(parts.at(0), Matrix3{}, &stats);

    EXPECT_EQ(stats.input_triangles, 832050U);
    EXPECT_EQ(mesh.faces.size(), 832050U);
    EXPECT_EQ(mesh.vertices.size(), 646U * 646U);
    EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace mixengine
