#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mesh/formats/ModelReader.h"
#include "unit/mesh/MeshTestFiles.h"

namespace mixengine {
namespace {

using test::binaryStl;
using test::contains;
using test::cubeTriangles;
using test::inputErrorOf;
using test::TempDir;

std::vector<TriangleSoup> read(const std::filesystem::path& file, std::vector<std::string>& warnings) {
    return readModelFile(file, warnings);
}

TEST(StlBinary, ReadsCube) {
    TempDir dir;
    std::vector<std::string> warnings;
    const auto parts = read(dir.write("cube.stl", binaryStl(cubeTriangles())), warnings);
    ASSERT_EQ(parts.size(), 1U);
    EXPECT_EQ(parts[0].name, "cube");
    ASSERT_EQ(parts[0].triangles.size(), 12U);
    EXPECT_EQ(parts[0].triangles, cubeTriangles());
    EXPECT_TRUE(warnings.empty());
}

TEST(StlBinary, HeaderStartingWithSolidIsStillBinary) {
    TempDir dir;
    std::vector<std::string> warnings;
    const auto parts =
        read(dir.write("solid.stl", binaryStl(cubeTriangles(), 12, "solid cube exported")), warnings);
    ASSERT_EQ(parts.size(), 1U);
    EXPECT_EQ(parts[0].triangles, cubeTriangles());
    EXPECT_TRUE(warnings.empty());
}

TEST(StlBinary, CounterTooHighWithIntactRecordsWarnsAndReadsRecords) {
    TempDir dir;
    std::vector<std::string> warnings;
    auto four = cubeTriangles();
    four.resize(4);
    const auto parts = read(dir.write("high.stl", binaryStl(four, 66)), warnings);
    ASSERT_EQ(parts[0].triangles.size(), 4U);
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_TRUE(contains(warnings[0], "high.stl"));
    EXPECT_TRUE(contains(warnings[0], "header says 66 triangles, file holds 4"));
}

TEST(StlBinary, CounterTooLowReadsEveryRecord) {
    TempDir dir;
    std::vector<std::string> warnings;
    const auto parts = read(dir.write("low.stl", binaryStl(cubeTriangles(), 2)), warnings);
    ASSERT_EQ(parts[0].triangles.size(), 12U);
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_TRUE(contains(warnings[0], "header says 2 triangles, file holds 12"));
}

TEST(StlBinary, WrongCounterBehindSolidHeaderIsStillBinary) {
    TempDir dir;
    std::vector<std::string> warnings;
    const auto parts = read(dir.write("s.stl", binaryStl(cubeTriangles(), 0, "solid")), warnings);
    ASSERT_EQ(parts[0].triangles.size(), 12U);
    EXPECT_EQ(warnings.size(), 1U);
}

TEST(StlBinary, TrailingByteWarnsAndReadsAllTriangles) {
    TempDir dir;
    std::vector<std::string> warnings;
    std::vector<test::Triangle> many;
    for (int i = 0; i < 24; ++i) {
        for (const auto& t : cubeTriangles(1.0 + i)) {
            many.push_back(t);
        }
    }
    ASSERT_EQ(many.size(), 288U);
    const auto parts = read(dir.write("trail.stl", binaryStl(many) + "x"), warnings);
    ASSERT_EQ(parts[0].triangles.size(), 288U);
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_TRUE(contains(warnings[0], "trail.stl"));
    EXPECT_TRUE(contains(warnings[0], "1 trailing byte"));
}

TEST(StlBinary, TruncatedRecordIsError) {
    TempDir dir;
    std::string bytes = binaryStl(cubeTriangles());
    bytes.resize(84 + 7 * 50 + 23);
    const auto file = dir.write("cut.stl", bytes);
    std::vector<std::string> warnings;
    const std::string message = inputErrorOf([&] { read(file, warnings); });
    EXPECT_TRUE(contains(message, "cut.stl: truncated binary STL: header says 12 triangles, file holds 7"));
}

TEST(StlBinary, EmptyFileIsError) {
    TempDir dir;
    const auto file = dir.write("empty.stl", "");
    std::vector<std::string> warnings;
    EXPECT_TRUE(contains(inputErrorOf([&] { read(file, warnings); }), "empty.stl: empty file"));
}

TEST(StlBinary, FileTooShortForHeaderIsError) {
    TempDir dir;
    const auto file = dir.write("short.stl", std::string(40, '\0'));
    std::vector<std::string> warnings;
    EXPECT_TRUE(contains(inputErrorOf([&] { read(file, warnings); }),
                         "short.stl: too short for a binary STL header: 40 bytes"));
}

TEST(StlBinary, NoTrianglesIsError) {
    TempDir dir;
    const auto file = dir.write("none.stl", binaryStl({}, 0));
    std::vector<std::string> warnings;
    EXPECT_TRUE(contains(inputErrorOf([&] { read(file, warnings); }), "none.stl: contains no triangles"));
}

TEST(StlBinary, NanVertexIsError) {
    TempDir dir;
    auto triangles = cubeTriangles();
    triangles[5][1].y = std::numeric_limits<double>::quiet_NaN();
    const auto file = dir.write("nan.stl", binaryStl(triangles));
    std::vector<std::string> warnings;
    const std::string message = inputErrorOf([&] { read(file, warnings); });
    EXPECT_TRUE(contains(message, "nan.stl"));
    EXPECT_TRUE(contains(message, "triangle 6 has a non-finite vertex coordinate"));
}

TEST(StlBinary, InfiniteVertexIsError) {
    TempDir dir;
    auto triangles = cubeTriangles();
    triangles[0][0].x = std::numeric_limits<double>::infinity();
    const auto file = dir.write("inf.stl", binaryStl(triangles));
    std::vector<std::string> warnings;
    EXPECT_TRUE(contains(inputErrorOf([&] { read(file, warnings); }), "inf.stl"));
}

TEST(StlBinary, NanNormalIsAcceptedWithOneWarning) {
    TempDir dir;
    std::vector<std::string> warnings;
    const auto bytes = binaryStl(cubeTriangles(), 12, "binary", std::numeric_limits<float>::quiet_NaN());
    const auto parts = read(dir.write("normal.stl", bytes), warnings);
    EXPECT_EQ(parts[0].triangles, cubeTriangles());
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_TRUE(contains(warnings[0], "normal.stl: 12 triangles with a non-finite normal"));
}

}  // namespace
}  // namespace mixengine
