#include <gtest/gtest.h>

#include "mesh/formats/ModelReader.h"
#include "unit/mesh/MeshTestFiles.h"

namespace mixengine {
namespace {

using test::contains;
using test::inputErrorOf;
using test::TempDir;

std::vector<TriangleSoup> readText(const std::string& name, const std::string& text,
                                   std::vector<std::string>& warnings) {
    TempDir dir;
    return readModelFile(dir.write(name, text), warnings);
}

std::string errorFor(const std::string& name, const std::string& text) {
    std::vector<std::string> warnings;
    return inputErrorOf([&] { readText(name, text, warnings); });
}

TEST(ObjReader, GroupsQuadsNegativeIndicesAndSlashForms) {
    const std::string text =
        "# two parts\n"
        "mtllib parts.mtl\n"
        "o plate\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "vt 0 0\nvn 0 0 1\n"
        "usemtl red\ns off\n"
        "f 1/1/1 2/1/1 3/1/1 4/1/1\n"  // quad -> 2 triangles
        "g spike\n"
        "v 0 0 5\nv 2 0 5\nv 0 2 5\n"
        "f -3//1 -2//1 -1//1\n"  // the three vertices just defined
        "f 5/1 6/1 7/1\n";       // the same by absolute index
    std::vector<std::string> warnings;
    const auto parts = readText("parts.obj", text, warnings);
    ASSERT_EQ(parts.size(), 2U);
    EXPECT_EQ(parts[0].name, "plate");
    ASSERT_EQ(parts[0].triangles.size(), 2U);
    EXPECT_EQ(parts[0].triangles[0], (test::Triangle{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}}));
    EXPECT_EQ(parts[0].triangles[1], (test::Triangle{Vec3{0, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}}));
    EXPECT_EQ(parts[1].name, "spike");
    ASSERT_EQ(parts[1].triangles.size(), 2U);
    const test::Triangle spike{Vec3{0, 0, 5}, Vec3{2, 0, 5}, Vec3{0, 2, 5}};
    EXPECT_EQ(parts[1].triangles[0], spike);
    EXPECT_EQ(parts[1].triangles[1], spike);
    EXPECT_TRUE(warnings.empty());
}

TEST(ObjReader, PentagonIsFanTriangulated) {
    std::vector<std::string> warnings;
    const auto parts =
        readText("penta.obj", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n", warnings);
    ASSERT_EQ(parts.size(), 1U);
    ASSERT_EQ(parts[0].triangles.size(), 3U);
    EXPECT_EQ(parts[0].triangles[2][0], (Vec3{0, 0, 0}));
    EXPECT_EQ(parts[0].triangles[2][1], (Vec3{1, 2, 0}));
    EXPECT_EQ(parts[0].triangles[2][2], (Vec3{-1, 1, 0}));
}

TEST(ObjReader, FacesBeforeAnyGroupArePartNamedAfterFile) {
    std::vector<std::string> warnings;
    const auto parts = readText("lonely.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", warnings);
    ASSERT_EQ(parts.size(), 1U);
    EXPECT_EQ(parts[0].name, "lonely");
}

TEST(ObjReader, RepeatedGroupNameContinuesItsPart) {
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
        "g a\nf 1 2 3\ng b\nf 1 2 4\ng a\nf 1 3 4\ng empty\n";
    std::vector<std::string> warnings;
    const auto parts = readText("groups.obj", text, warnings);
    ASSERT_EQ(parts.size(), 2U);
    EXPECT_EQ(parts[0].name, "a");
    EXPECT_EQ(parts[0].triangles.size(), 2U);
    EXPECT_EQ(parts[1].name, "b");
    EXPECT_EQ(parts[1].triangles.size(), 1U);
}

TEST(ObjReader, ForwardReferenceIsAccepted) {
    std::vector<std::string> warnings;
    const auto parts = readText("forward.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", warnings);
    ASSERT_EQ(parts[0].triangles.size(), 1U);
    EXPECT_EQ(parts[0].triangles[0][1], (Vec3{1, 0, 0}));
}

TEST(ObjReader, IndexOutOfRangeIsErrorWithLine) {
    EXPECT_TRUE(contains(errorFor("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n"),
                         "bad.obj: line 5: face vertex index 9 out of range (file defines 3 vertices)"));
}

TEST(ObjReader, NegativeIndexBeforeFirstVertexIsError) {
    EXPECT_TRUE(contains(errorFor("neg.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\n"),
                         "neg.obj: line 3: face vertex index -3 out of range (2 vertices defined so far)"));
}

TEST(ObjReader, ZeroIndexIsError) {
    EXPECT_TRUE(contains(errorFor("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"),
                         "zero.obj: line 4: face vertex index 0"));
}

TEST(ObjReader, NonIntegerIndexIsError) {
    EXPECT_TRUE(contains(errorFor("word.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n"),
                         "word.obj: line 4: bad face vertex index 'two'"));
}

TEST(ObjReader, FaceWithTwoCornersIsError) {
    EXPECT_TRUE(contains(errorFor("thin.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"),
                         "thin.obj: line 3: face has 2 corners, need at least 3"));
}

TEST(ObjReader, NonNumericVertexIsError) {
    EXPECT_TRUE(contains(errorFor("vx.obj", "v 0 0 0\nv 1 zero 0\n"),
                         "vx.obj: line 2: expected a number for a vertex coordinate, found 'zero'"));
}

TEST(ObjReader, NanVertexIsError) {
    EXPECT_TRUE(
        contains(errorFor("vn.obj", "v 0 0 0\nv 1 NaN 0\n"), "vn.obj: line 2: non-finite vertex coordinate"));
}

TEST(ObjReader, NoFacesIsError) {
    EXPECT_TRUE(contains(errorFor("points.obj", "v 0 0 0\nv 1 0 0\n"), "points.obj: contains no triangles"));
}

TEST(ObjReader, EmptyFileIsError) {
    EXPECT_TRUE(contains(errorFor("void.obj", ""), "void.obj: empty file"));
}

TEST(ObjReader, UnsupportedStatementsWarnOnce) {
    std::vector<std::string> warnings;
    const auto parts =
        readText("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\nf 1 2 3 # tail comment\n", warnings);
    EXPECT_EQ(parts[0].triangles.size(), 1U);
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_TRUE(
        contains(warnings[0], "lines.obj: ignoring 2 unsupported OBJ statements (first 'l' on line 4)"));
}

}  // namespace
}  // namespace mixengine
