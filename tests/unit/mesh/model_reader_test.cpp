#include <gtest/gtest.h>

#include "mesh/formats/ModelReader.h"
#include "unit/mesh/MeshTestFiles.h"

namespace mixengine {
namespace {

using test::contains;
using test::inputErrorOf;
using test::TempDir;

TEST(MeshModelReader, DispatchIgnoresExtensionCase) {
    TempDir dir;
    std::vector<std::string> warnings;
    EXPECT_EQ(readModelFile(dir.write("a.STL", test::binaryStl(test::cubeTriangles())), warnings)[0]
                  .triangles.size(),
              12U);
    EXPECT_EQ(readModelFile(dir.write("b.Obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), warnings)[0].name,
              "b");
    EXPECT_TRUE(warnings.empty());
}

TEST(MeshModelReader, UnknownExtensionIsError) {
    TempDir dir;
    const auto file = dir.write("model.ply", "ply\n");
    std::vector<std::string> warnings;
    const std::string message = inputErrorOf([&] { readModelFile(file, warnings); });
    EXPECT_TRUE(
        contains(message, "model.ply: unsupported model file type '.ply'; expected .stl, .obj or .3mf"));
}

TEST(MeshModelReader, MissingExtensionIsError) {
    TempDir dir;
    const auto file = dir.write("model", "solid\n");
    std::vector<std::string> warnings;
    EXPECT_TRUE(contains(inputErrorOf([&] { readModelFile(file, warnings); }),
                         "model: unsupported model file type (no extension)"));
}

TEST(MeshModelReader, MissingFileIsError) {
    TempDir dir;
    std::vector<std::string> warnings;
    const std::string message = inputErrorOf([&] { readModelFile(dir.path() / "ghost.stl", warnings); });
    EXPECT_TRUE(contains(message, "ghost.stl: cannot read model file"));
}

TEST(MeshModelReader, DirectoryIsError) {
    TempDir dir;
    std::filesystem::create_directory(dir.path() / "folder.obj");
    std::vector<std::string> warnings;
    const std::string message = inputErrorOf([&] { readModelFile(dir.path() / "folder.obj", warnings); });
    EXPECT_TRUE(contains(message, "folder.obj: cannot read model file: it is a directory"));
}

}  // namespace
}  // namespace mixengine
