#include <gtest/gtest.h>

#include "mesh/formats/ModelReader.h"
#include "unit/mesh/MeshTestFiles.h"

namespace mixengine {
namespace {

using test::asciiSolid;
using test::contains;
using test::cubeTriangles;
using test::inputErrorOf;
using test::TempDir;

constexpr const char* kOneFacetHead =
    "solid one\n"
    "facet normal 0 0 1\n"
    " outer loop\n"
    "  vertex 0 0 0\n";

std::string errorFor(const std::string& name, const std::string& text) {
    TempDir dir;
    const auto file = dir.write(name, text);
    std::vector<std::string> warnings;
    return inputErrorOf([&] { readModelFile(file, warnings); });
}

TEST(StlAscii, ReadsCube) {
    TempDir dir;
    std::vector<std::string> warnings;
    const auto parts = readModelFile(dir.write("cube.stl", asciiSolid(cubeTriangles())), warnings);
    ASSERT_EQ(parts.size(), 1U);
    EXPECT_EQ(parts[0].name, "cube");
    EXPECT_EQ(parts[0].triangles, cubeTriangles());
    EXPECT_TRUE(warnings.empty());
}

TEST(StlAscii, TwoSolidBlocksAreMergedWithWarning) {
    TempDir dir;
    std::vector<std::string> warnings;
    const auto text = asciiSolid(cubeTriangles(), "a") + asciiSolid(cubeTriangles(20.0), "b");
    const auto parts = readModelFile(dir.write("two.stl", text), warnings);
    ASSERT_EQ(parts.size(), 1U);
    ASSERT_EQ(parts[0].triangles.size(), 24U);
    EXPECT_EQ(parts[0].triangles[12][0].x, 0.0);
    EXPECT_EQ(parts[0].triangles[12][1].x, 20.0);
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_TRUE(contains(warnings[0], "two.stl: 2 solid blocks merged into one part"));
}

TEST(StlAscii, UppercaseKeywordsCrLfAndSignedExponents) {
    TempDir dir;
    std::vector<std::string> warnings;
    const std::string text =
        "SOLID part\r\n FACET NORMAL 0 0 -1\r\n  OUTER LOOP\r\n   VERTEX +1.5e+01 0 0\r\n"
        "   VERTEX 0 2E1 0\r\n   VERTEX 0 0 -3.25\r\n  ENDLOOP\r\n ENDFACET\r\nENDSOLID part\r\n";
    const auto parts = readModelFile(dir.write("upper.stl", text), warnings);
    ASSERT_EQ(parts[0].triangles.size(), 1U);
    EXPECT_EQ(parts[0].triangles[0][0], (Vec3{15.0, 0, 0}));
    EXPECT_EQ(parts[0].triangles[0][1], (Vec3{0, 20.0, 0}));
    EXPECT_EQ(parts[0].triangles[0][2], (Vec3{0, 0, -3.25}));
    EXPECT_TRUE(warnings.empty());
}

TEST(StlAscii, ByteOrderMarkAndTrailingPaddingAreIgnored) {
    TempDir dir;
    std::vector<std::string> warnings;
    const std::string text = "\xEF\xBB\xBF" + asciiSolid(cubeTriangles()) + std::string(3, '\0') + "\x1A";
    const auto parts = readModelFile(dir.write("padded.stl", text), warnings);
    EXPECT_EQ(parts[0].triangles, cubeTriangles());
    EXPECT_TRUE(warnings.empty());
}

TEST(StlAscii, NonNumericCoordinateIsErrorWithLine) {
    const std::string message = errorFor(
        "words.stl", std::string(kOneFacetHead) + "  vertex 1 abc 0\n  vertex 0 1 0\n endloop\nendfacet\n");
    EXPECT_TRUE(
        contains(message, "words.stl: line 5: expected a number for a vertex coordinate, found 'abc'"));
}

TEST(StlAscii, NanCoordinateIsError) {
    const std::string message = errorFor(
        "nan.stl", std::string(kOneFacetHead) + "  vertex 1 nan 0\n  vertex 0 1 0\n endloop\nendfacet\n");
    EXPECT_TRUE(contains(message, "nan.stl: line 5: non-finite vertex coordinate 'nan'"));
}

TEST(StlAscii, InfiniteCoordinateIsError) {
    const std::string message = errorFor(
        "inf.stl", std::string(kOneFacetHead) + "  vertex 1 0 -inf\n  vertex 0 1 0\n endloop\nendfacet\n");
    EXPECT_TRUE(contains(message, "inf.stl: line 5: non-finite vertex coordinate '-inf'"));
}

TEST(StlAscii, NanNormalIsAcceptedWithWarning) {
    TempDir dir;
    std::vector<std::string> warnings;
    std::string text = asciiSolid(cubeTriangles());
    text.replace(text.find("normal 0 0 1"), 12, "normal nan nan nan");
    const auto parts = readModelFile(dir.write("nn.stl", text), warnings);
    EXPECT_EQ(parts[0].triangles, cubeTriangles());
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_TRUE(contains(warnings[0], "nn.stl: 1 facet with a missing or non-finite normal"));
}

TEST(StlAscii, FileEndingInsideFacetIsError) {
    const std::string message = errorFor("cut.stl", std::string(kOneFacetHead) + "  vertex 1 0");
    EXPECT_TRUE(contains(message, "cut.stl: line 5: file ends inside a facet"));
}

TEST(StlAscii, FacetWithTwoVerticesIsError) {
    const std::string message =
        errorFor("two.stl", std::string(kOneFacetHead) + "  vertex 1 0 0\n endloop\nendfacet\nendsolid\n");
    EXPECT_TRUE(contains(message, "two.stl: line 7: facet has 2 vertices, expected 3"));
}

TEST(StlAscii, UnexpectedWordIsError) {
    const std::string message = errorFor("odd.stl", "solid x\nfacet normal 0 0 1\n outer loop\n banana\n");
    EXPECT_TRUE(contains(message, "odd.stl: line 4: expected 'vertex' or 'endfacet', found 'banana'"));
}

TEST(StlAscii, EmptySolidHasNoTriangles) {
    EXPECT_TRUE(contains(errorFor("hollow.stl", "solid hollow\nendsolid hollow\n"),
                         "hollow.stl: contains no triangles"));
}

TEST(StlAscii, MissingEndsolidWarns) {
    TempDir dir;
    std::vector<std::string> warnings;
    std::string text = asciiSolid(cubeTriangles());
    text.resize(text.find("endsolid"));
    const auto parts = readModelFile(dir.write("open.stl", text), warnings);
    EXPECT_EQ(parts[0].triangles.size(), 12U);
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_TRUE(contains(warnings[0], "open.stl: ASCII STL ends without 'endsolid'"));
}

}  // namespace
}  // namespace mixengine
