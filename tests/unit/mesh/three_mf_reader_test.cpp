#include <Model/COM/NMR_DLLInterfaces.h>
#include <gtest/gtest.h>
#include <zip.h>

#include "mesh/formats/ModelReader.h"
#include "unit/mesh/MeshTestFiles.h"

namespace mixengine {
namespace {

using test::contains;
using test::inputErrorOf;
using test::TempDir;

/// A lib3mf handle released at scope exit (test-side writer helper).
struct Handle {
    NMR::PLib3MFBase* p = nullptr;
    ~Handle() {
        if (p != nullptr) {
            NMR::lib3mf_release(p);
        }
    }
};

NMR::MODELTRANSFORM transform(float scale, float tx, float ty, float tz) {
    NMR::MODELTRANSFORM t{};
    t.m_fFields[0][0] = t.m_fFields[1][1] = t.m_fFields[2][2] = scale;
    t.m_fFields[0][3] = tx;
    t.m_fFields[1][3] = ty;
    t.m_fFields[2][3] = tz;
    return t;
}

/// Adds a unit cube ([0,1]^3 in model units) as a mesh object named `name`.
void addCube(NMR::PLib3MFBase* model, const char* name, Handle& object) {
    NMR::MODELMESHVERTEX v[8];
    for (int i = 0; i < 8; ++i) {
        v[i].m_fPosition[0] = static_cast<float>((i == 1 || i == 2 || i == 5 || i == 6) ? 1 : 0);
        v[i].m_fPosition[1] = static_cast<float>((i == 2 || i == 3 || i == 6 || i == 7) ? 1 : 0);
        v[i].m_fPosition[2] = static_cast<float>(i >= 4 ? 1 : 0);
    }
    const DWORD f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                            {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    NMR::MODELMESHTRIANGLE t[12];
    for (int i = 0; i < 12; ++i) {
        for (int k = 0; k < 3; ++k) {
            t[i].m_nIndices[k] = f[i][k];
        }
    }
    ASSERT_EQ(NMR::lib3mf_model_addmeshobject(model, &object.p), 0);
    ASSERT_EQ(NMR::lib3mf_object_setnameutf8(object.p, name), 0);
    ASSERT_EQ(NMR::lib3mf_meshobject_setgeometry(object.p, v, 8, t, 12), 0);
}

/// Writes a 3MF in centimetres: build item 1 = cube "box" moved by (5, 0, 0) cm; build item 2 =
/// a components object "pair" holding the cube twice (once scaled by 2, once moved up 3 cm).
void writeThreeMf(const std::filesystem::path& file) {
    Handle model;
    ASSERT_EQ(NMR::lib3mf_createmodel(&model.p), 0);
    ASSERT_EQ(NMR::lib3mf_model_setunit(model.p, NMR::MODELUNIT_CENTIMETER), 0);
    Handle cube;
    addCube(model.p, "box", cube);
    Handle item1;
    NMR::MODELTRANSFORM move = transform(1, 5, 0, 0);
    ASSERT_EQ(NMR::lib3mf_model_addbuilditem(model.p, cube.p, &move, &item1.p), 0);
    Handle pair;
    ASSERT_EQ(NMR::lib3mf_model_addcomponentsobject(model.p, &pair.p), 0);
    ASSERT_EQ(NMR::lib3mf_object_setnameutf8(pair.p, "pair"), 0);
    Handle c1;
    Handle c2;
    NMR::MODELTRANSFORM doubled = transform(2, 0, 0, 0);
    NMR::MODELTRANSFORM raised = transform(1, 0, 0, 3);
    ASSERT_EQ(NMR::lib3mf_componentsobject_addcomponent(pair.p, cube.p, &doubled, &c1.p), 0);
    ASSERT_EQ(NMR::lib3mf_componentsobject_addcomponent(pair.p, cube.p, &raised, &c2.p), 0);
    Handle item2;
    ASSERT_EQ(NMR::lib3mf_model_addbuilditem(model.p, pair.p, nullptr, &item2.p), 0);
    Handle writer;
    ASSERT_EQ(NMR::lib3mf_model_querywriter(model.p, "3mf", &writer.p), 0);
    ASSERT_EQ(NMR::lib3mf_writer_writetofileutf8(writer.p, file.string().c_str()), 0);
}

Vec3 minCorner(const TriangleSoup& soup) {
    Vec3 m{1e300, 1e300, 1e300};
    for (const auto& t : soup.triangles) {
        for (const Vec3& v : t) {
            m = {std::min(m.x, v.x), std::min(m.y, v.y), std::min(m.z, v.z)};
        }
    }
    return m;
}

Vec3 maxCorner(const TriangleSoup& soup) {
    Vec3 m{-1e300, -1e300, -1e300};
    for (const auto& t : soup.triangles) {
        for (const Vec3& v : t) {
            m = {std::max(m.x, v.x), std::max(m.y, v.y), std::max(m.z, v.z)};
        }
    }
    return m;
}

TriangleSoup slice(const TriangleSoup& soup, std::size_t begin, std::size_t end) {
    TriangleSoup part;
    part.triangles.assign(soup.triangles.begin() + static_cast<std::ptrdiff_t>(begin),
                          soup.triangles.begin() + static_cast<std::ptrdiff_t>(end));
    return part;
}

TEST(ThreeMfReader, RoundTripAppliesTransformsComponentsAndUnit) {
    TempDir dir;
    const auto file = dir.path() / "scene.3mf";
    writeThreeMf(file);
    std::vector<std::string> warnings;
    const auto parts = readModelFile(file, warnings);
    ASSERT_EQ(parts.size(), 2U);
    EXPECT_EQ(parts[0].name, "box");
    EXPECT_EQ(parts[0].triangles.size(), 12U);
    EXPECT_EQ(minCorner(parts[0]), (Vec3{50, 0, 0}));  // 5 cm
    EXPECT_EQ(maxCorner(parts[0]), (Vec3{60, 10, 10}));
    EXPECT_EQ(parts[1].name, "pair");
    ASSERT_EQ(parts[1].triangles.size(), 24U);
    EXPECT_EQ(maxCorner(slice(parts[1], 0, 12)), (Vec3{20, 20, 20}));  // scaled by 2
    EXPECT_EQ(minCorner(slice(parts[1], 12, 24)), (Vec3{0, 0, 30}));   // raised by 3 cm
    EXPECT_TRUE(warnings.empty());
}

void addToZip(zip_t* archive, const char* name, const std::string& text) {
    zip_source_t* source = zip_source_buffer(archive, text.data(), text.size(), 0);
    ASSERT_NE(source, nullptr);
    ASSERT_GE(zip_file_add(archive, name, source, ZIP_FL_OVERWRITE), 0);
}

/// A 3MF package zipped by hand (independent of lib3mf's writer), with the model XML given.
void zipThreeMf(const std::filesystem::path& file, const std::string& model_xml) {
    const std::string types =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\">"
        "<Default Extension=\"rels\" "
        "ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/>"
        "<Default Extension=\"model\" "
        "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/>"
        "</Types>";
    const std::string rels =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">"
        "<Relationship Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
        "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>";
    int error = 0;
    zip_t* archive = zip_open(file.string().c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    ASSERT_NE(archive, nullptr);
    addToZip(archive, "[Content_Types].xml", types);
    addToZip(archive, "_rels/.rels", rels);
    addToZip(archive, "3D/3dmodel.model", model_xml);
    ASSERT_EQ(zip_close(archive), 0);
}

TEST(ThreeMfReader, HandWrittenModelFollowsSpecTransformOrderAndInches) {
    // transform "m00 m01 m02 m10 m11 m12 m20 m21 m22 m30 m31 m32": x' = m00 x + m10 y + m20 z + m30.
    // Here x' = -y + 10, y' = x + 20, z' = z + 30 (a quarter turn about z, then a move), in inches.
    const std::string model =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<model unit=\"inch\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">"
        "<resources><object id=\"7\" type=\"model\"><mesh><vertices>"
        "<vertex x=\"1\" y=\"0\" z=\"0\"/><vertex x=\"0\" y=\"1\" z=\"0\"/><vertex x=\"0\" y=\"0\" z=\"1\"/>"
        "</vertices><triangles><triangle v1=\"0\" v2=\"1\" v3=\"2\"/></triangles></mesh></object></resources>"
        "<build><item objectid=\"7\" transform=\"0 1 0 -1 0 0 0 0 1 10 20 30\"/></build></model>";
    TempDir dir;
    const auto file = dir.path() / "inch.3mf";
    zipThreeMf(file, model);
    std::vector<std::string> warnings;
    const auto parts = readModelFile(file, warnings);
    ASSERT_EQ(parts.size(), 1U);
    EXPECT_EQ(parts[0].name, "inch_1");  // unnamed object: file stem and build item number
    ASSERT_EQ(parts[0].triangles.size(), 1U);
    const auto& t = parts[0].triangles[0];
    EXPECT_DOUBLE_EQ(t[0].x, 10 * 25.4);
    EXPECT_DOUBLE_EQ(t[0].y, 21 * 25.4);
    EXPECT_DOUBLE_EQ(t[0].z, 30 * 25.4);
    EXPECT_DOUBLE_EQ(t[1].x, 9 * 25.4);
    EXPECT_DOUBLE_EQ(t[1].y, 20 * 25.4);
    EXPECT_DOUBLE_EQ(t[2].z, 31 * 25.4);
}

TEST(ThreeMfReader, GarbageFileIsError) {
    TempDir dir;
    const auto file = dir.write("junk.3mf", "this is not a zip archive");
    std::vector<std::string> warnings;
    EXPECT_TRUE(contains(inputErrorOf([&] { readModelFile(file, warnings); }), "junk.3mf: cannot read 3MF"));
}

TEST(ThreeMfReader, EmptyFileIsError) {
    TempDir dir;
    const auto file = dir.write("empty.3mf", "");
    std::vector<std::string> warnings;
    EXPECT_TRUE(contains(inputErrorOf([&] { readModelFile(file, warnings); }), "empty.3mf: empty file"));
}

TEST(ThreeMfReader, ModelWithoutBuildItemsHasNoTriangles) {
    const std::string model =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<model unit=\"millimeter\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">"
        "<resources/><build/></model>";
    TempDir dir;
    const auto file = dir.path() / "bare.3mf";
    zipThreeMf(file, model);
    std::vector<std::string> warnings;
    EXPECT_TRUE(
        contains(inputErrorOf([&] { readModelFile(file, warnings); }), "bare.3mf: contains no triangles"));
}

}  // namespace
}  // namespace mixengine
