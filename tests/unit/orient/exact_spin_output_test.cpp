// Exact volumes (orient/ExactSolid.h), the free spin (orient/FreeSpin.h), the rotation of meshes,
// the STL writer and the PNG renderer.
#include <gtest/gtest.h>

#include <cstring>

#include "orient/ExactSolid.h"
#include "orient/FreeSpin.h"
#include "orient/MeshRotation.h"
#include "orient/VMapPng.h"
#include "unit/orient/OrientMeshes.h"

namespace mixengine::orient {
namespace {

using test::boxMesh;

TEST(OrientExact, BoxIntersectionIsTheAnalyticCovariogram) {
    const Vec3 size{60, 30, 30};
    const ExactSolid box(boxMesh({0, 0, 0}, size));
    ASSERT_TRUE(box.exact());
    EXPECT_NEAR(box.volumeMm3(), 54000.0, 1e-6);
    for (const Vec3& v : {Vec3{35, 0, 0}, Vec3{30.3109, 17.5, 0}, Vec3{20, -20, 20.6155}, Vec3{0, 0, 35}}) {
        const double analytic = test::boxCovariogram(size, v);
        const auto exact = box.intersectionVolumeMm3(box, v);
        ASSERT_TRUE(exact.has_value());
        EXPECT_NEAR(*exact, analytic, 1e-6 * 54000.0 + 0.01 * analytic);
    }
    EXPECT_EQ(*box.intersectionVolumeMm3(box, {61, 0, 0}), 0.0);
}

TEST(OrientExact, DefectsAreReportedNotMeasured) {
    const ExactSolid open(test::openBox({0, 0, 0}, {10, 10, 10}));
    EXPECT_EQ(open.status(), SolidStatus::Open);
    EXPECT_FALSE(open.intersectionVolumeMm3(open, {1, 0, 0}).has_value());
    const ExactSolid crossing(test::overlappingBoxes());
    EXPECT_EQ(crossing.status(), SolidStatus::SelfIntersecting);
    EXPECT_EQ(describe(SolidStatus::SelfIntersecting), "self-intersecting");
}

TEST(OrientExact, InvertedWindingIsOrientedFirst) {
    Mesh box = boxMesh({0, 0, 0}, {10, 10, 10});
    for (Face& f : box.faces)
        std::swap(f.v[1], f.v[2]);
    const ExactSolid solid(box);
    ASSERT_TRUE(solid.exact());
    EXPECT_NEAR(solid.volumeMm3(), 1000.0, 1e-6);
}

TEST(OrientSpin, FlatFaceObjectivePutsTheLargestFaceDown) {
    const Mesh box = boxMesh({0, 0, 0}, {60, 30, 10});
    const SurfaceSample surface({&box});
    const std::vector<Vec3> flats = surface.flatNormals(0.02, 6);
    ASSERT_EQ(flats.size(), 6u);
    EXPECT_NEAR(std::abs(flats[0].z), 1.0, 1e-12);  // the 60 × 30 faces are the largest
    const Vec3 d{1, 0, 0};
    const LatLon angles{0, 0};  // u = d: the 60 mm edge along d, spin turns about it
    std::vector<SpinOption> options;
    for (const double spin : spinsToTry(angles, d, flats)) {
        SpinOption o{0, surface.score(spunRotation(angles, d, spin), 45)};
        o.score.spin_deg = spin;
        options.push_back(o);
    }
    std::string picked_by;
    const SpinOption best = chooseOption(options, Objective::FlatFace, picked_by);
    EXPECT_NEAR(best.score.contact_mm2, 1800.0, 1e-6);
    EXPECT_NEAR(best.score.height_mm, 10.0, 1e-6);
    EXPECT_EQ(best.score.overhang_mm2, 0.0);
    EXPECT_EQ(picked_by, "flat face");  // spins 0 and 180 tie on everything; contact ruled out the rest
    const SpinOption tall = chooseOption(options, Objective::LowOverhang, picked_by);
    EXPECT_EQ(tall.score.overhang_mm2, 0.0);
}

TEST(OrientSpin, OverhangCountsDownFacingFacetsOffTheBed) {
    const Mesh box = boxMesh({0, 0, 0}, {10, 10, 10});
    const SurfaceSample surface({&box});
    const SpinScore flat = surface.score(Matrix3{}, 45);
    EXPECT_NEAR(flat.contact_mm2, 100.0, 1e-9);
    EXPECT_EQ(flat.overhang_mm2, 0.0);
    const SpinScore tilted = surface.score(rotationAbout({1, 0, 0}, 30), 45);
    EXPECT_EQ(tilted.contact_mm2, 0.0);
    EXPECT_NEAR(tilted.overhang_mm2, 100.0 * std::cos(30 * 3.14159265358979 / 180), 1e-6);
}

TEST(OrientMeshes, RotateTogetherKeepsTheLowestPoint) {
    Mesh a = boxMesh({0, 0, 5}, {60, 30, 30}), b = boxMesh({0, 30, 5}, {60, 30, 30});
    rotateTogether({&a, &b}, rotationAbout({1, 0, 0}, 90), {30, 30, 20});
    const AABB3 ba = a.bounds(), bb = b.bounds();
    EXPECT_EQ(std::min(ba.min.z, bb.min.z), 5000);
    EXPECT_EQ(ba.max.x - ba.min.x, 60000);
    EXPECT_EQ(ba.max.z - ba.min.z, 30000);  // y extent turned into z
    const Mesh both = concatenated({&a, &b}, "both");
    EXPECT_EQ(both.faces.size(), 24u);
    EXPECT_EQ(both.faces[12].v[0], a.faces[0].v[0] + 8);
}

TEST(OrientOutput, BinaryStlLayout) {
    const std::string stl = binaryStl(boxMesh({0, 0, 0}, {1, 2, 3}));
    ASSERT_EQ(stl.size(), 84u + 12u * 50u);
    std::uint32_t count = 0;
    std::memcpy(&count, stl.data() + 80, 4);
    EXPECT_EQ(count, 12u);
}

TEST(OrientOutput, PngHasItsSignatureAndSize) {
    VMap map;
    map.step_deg = 10;
    map.rows = map.columns = 36;
    for (int i = 0; i < 36 * 36; ++i)
        map.values.push_back(i % 37);
    const std::string png = renderVMapPng(map, {0, 60});
    ASSERT_GT(png.size(), 33u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
    EXPECT_EQ(png.substr(12, 4), "IHDR");
    const auto be32 = [&](std::size_t at) {
        return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
               (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
    };
    EXPECT_EQ(be32(16), 48 + 36 * 15 + 24 + 24 + 80);  // width: margin + 36 cells of 15 px + bar
    EXPECT_EQ(be32(20), 28 + 36 * 15 + 40);
}

}  // namespace
}  // namespace mixengine::orient
