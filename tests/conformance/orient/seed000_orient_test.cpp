// Seed 000's published case and derived numbers (shared/seeds/README.md, section 000):
// two 60 × 30 × 30 mm boxes side by side, nozzle offset 35 mm along X.
#include <gtest/gtest.h>

#include <sstream>

#include "common/Error.h"
#include "orient/Orienter.h"
#include "unit/orient/OrientMeshes.h"

namespace mixengine::orient {
namespace {

using test::boxMesh;

class OrientSeed000 : public ::testing::Test {
  protected:
    Mesh a = boxMesh({0, 0, 0}, {60, 30, 30}, "red");
    Mesh b = boxMesh({0, 30, 0}, {60, 30, 30}, "blue");
    std::ostringstream messages;
    Log log{messages};
};

TEST_F(OrientSeed000, GridFirstOptimumIsLatitude0Longitude60) {
    OrientOptions options;
    options.method = Method::Grid;
    const OrientResult r = optimiseOrientation(a, b, {35, 0, 0}, options, log);
    ASSERT_TRUE(r.exact);
    EXPECT_EQ(r.map.rows, 36);
    EXPECT_EQ(r.evaluations, 1296u);
    EXPECT_EQ(r.angles.latitude_deg, 0.0);
    EXPECT_EQ(r.angles.longitude_deg, 60.0);
    EXPECT_NEAR(r.v_after_mm3, 0.0, 1e-6);
    EXPECT_NEAR(r.v_before_mm3, 45000.0, 1e-3);
    // The derived table: both boxes, latitude 0, longitude 0..60 (cm³ × 1000).
    const double table[] = {45000.0, 36646.7, 29327.3, 22266.8, 14939.6, 7174.5, 0.0};
    for (int lon = 0; lon <= 6; ++lon)
        EXPECT_NEAR(r.map.values[lon], table[lon], 0.1) << "longitude " << lon * 10;
    EXPECT_GT(r.map.values[5], 7000.0);  // longitude 50 is not zero
    // Along longitude 0 the same values for latitudes 0..50, and latitude 60 is zero too.
    for (int lat = 0; lat <= 6; ++lat)
        EXPECT_NEAR(r.map.values[lat * 36], table[lat], 0.1) << "latitude " << lat * 10;
    EXPECT_TRUE(messages.str().empty());
}

TEST_F(OrientSeed000, VoxelMeasureAgreesWithTheExactGrid) {
    OrientOptions options;
    options.method = Method::Grid;
    const OrientResult r = optimiseOrientation(a, b, {35, 0, 0}, options, log);
    EXPECT_NEAR(r.v_after_estimate_mm3, 0.0, 1.0);
    EXPECT_NEAR(r.v_before_estimate_mm3, 45000.0, 450.0);
}

TEST_F(OrientSeed000, SphereFindsZeroWithAFlatFaceAndLowHeight) {
    const OrientResult r = optimiseOrientation(a, b, {35, 0, 0}, OrientOptions{}, log);
    ASSERT_TRUE(r.exact);
    EXPECT_NEAR(r.v_after_mm3, 0.0, 1e-6);
    EXPECT_NEAR(r.v_before_mm3, 45000.0, 1e-3);
    EXPECT_NEAR(r.score.contact_mm2, 3600.0, 1e-3);  // the 60 × 60 bottom of both boxes
    EXPECT_NEAR(r.score.height_mm, 30.0, 1e-6);
    EXPECT_GE(r.map.rows, 180);  // 2° map or finer
    // The direction seen from the boxes: the 35 mm offset crosses the 30 mm side.
    EXPECT_NEAR(std::abs(r.direction.y), 1.0, 1e-6);
}

TEST_F(OrientSeed000, AllMaterialMeasureCountsTheOtherPart) {
    OrientOptions options;
    options.method = Method::Grid;
    options.measure = Measure::AllMaterial;
    options.grid_step_deg = 30;
    const OrientResult r = optimiseOrientation(a, b, {35, 0, 0}, options, log);
    // At identity the boxes lie side by side along Y: shifting by 35 along X adds nothing from the
    // other box (no overlap in y), so V equals the own-part value.
    EXPECT_NEAR(r.v_before_mm3, 45000.0, 1e-3);
    // Longitude 270 turns B (y > 30) to the +x side of A: u = +y, A + 35y overlaps B by 25 mm, and
    // B − 35y overlaps A by 25 mm: 2 × 60 × 25 × 30. Longitude 90 puts B on the other side: 0.
    EXPECT_NEAR(r.map.values[9], 2 * 60.0 * 25 * 30, 1e-3);
    EXPECT_NEAR(r.map.values[3], 0.0, 1e-6);
}

TEST_F(OrientSeed000, OpenPartWarnsAndUsesTheVoxelMeasure) {
    const Mesh open = test::openBox({0, 0, 0}, {60, 30, 30});
    OrientOptions options;
    options.method = Method::Grid;
    options.grid_step_deg = 30;
    const OrientResult r = optimiseOrientation(open, b, {35, 0, 0}, options, log);
    EXPECT_FALSE(r.exact);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("open"), std::string::npos);
    EXPECT_NE(messages.str().find("voxel measure"), std::string::npos);
    EXPECT_NEAR(r.v_before_mm3, 45000.0, 450.0);  // bridged by the voxeliser: still the box
}

TEST_F(OrientSeed000, ZeroOffsetIsAnInputError) {
    EXPECT_THROW(optimiseOrientation(a, b, {0, 0, 0}, OrientOptions{}, log), InputError);
}

}  // namespace
}  // namespace mixengine::orient
