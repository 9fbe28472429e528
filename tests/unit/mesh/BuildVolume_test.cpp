// The build volume check after placement (mesh/BuildVolume.h).
#include <gtest/gtest.h>

#include <string>

#include "common/Error.h"
#include "mesh/BuildVolume.h"

namespace mixengine {
namespace {

AABB3 box(coord_um x0, coord_um y0, coord_um z0, coord_um x1, coord_um y1, coord_um z1) {
    return {{x0, y0, z0}, {x1, y1, z1}};
}

std::string errorOf(const AABB3& mesh, const BuildVolume& volume) {
    try {
        checkBuildVolume("m.stl", mesh, volume);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const BuildVolume kVolume = machineVolume(100'000, 100'000, 100'000, false);

TEST(BuildVolume, MachineVolumeFromZeroOrCentred) {
    EXPECT_EQ(kVolume.min, (Point3{0, 0, 0}));
    EXPECT_EQ(kVolume.max, (Point3{100'000, 100'000, 100'000}));
    const BuildVolume centred = machineVolume(235'000, 235'000, 250'000, true);
    EXPECT_EQ(centred.min, (Point3{-117'500, -117'500, 0}));
    EXPECT_EQ(centred.max, (Point3{117'500, 117'500, 250'000}));
}

TEST(BuildVolume, InsideIsSilent) {
    EXPECT_EQ(checkBuildVolume("m.stl", box(40'000, 40'000, 0, 60'000, 60'000, 20'000), kVolume), "");
    EXPECT_EQ(checkBuildVolume("m.stl", box(0, 0, 0, 100'000, 100'000, 100'000), kVolume), "");
    EXPECT_EQ(checkBuildVolume("m.stl", AABB3{}, kVolume), "");  // no vertices
}

TEST(BuildVolume, ReachingOutsideIsAWarningNamingTheMesh) {
    const std::string wide = checkBuildVolume("m.stl", box(-25'000, 0, 0, 125'000, 50'000, 10'000), kVolume);
    EXPECT_NE(wide.find("m.stl"), std::string::npos) << wide;
    EXPECT_NE(wide.find("x -25..125"), std::string::npos) << wide;
    const std::string below = checkBuildVolume("m.stl", box(0, 0, -5'000, 10'000, 10'000, 5'000), kVolume);
    EXPECT_NE(below.find("z -5..5 mm"), std::string::npos) << below;
}

TEST(BuildVolume, FarLargerThanTheVolumeIsAnError) {
    EXPECT_EQ(errorOf(box(0, 0, 0, 1'000'000, 1'000'000, 10'000), kVolume),
              "");  // exactly 10 times: a warning
    const std::string error = errorOf(box(0, 0, 0, 10'000, 10'000, 1'000'001), kVolume);
    EXPECT_NE(error.find("m.stl"), std::string::npos) << error;
    EXPECT_NE(error.find("machine_height"), std::string::npos) << error;
}

TEST(BuildVolume, PlacedBeyondOneKilometreIsAnErrorNamingThePlacementSettings) {
    const BuildVolume huge = machineVolume(2'000'000'000, 100'000, 100'000, false);
    const std::string error = errorOf(box(1'000'000'000, 0, 0, 1'000'010'000, 10'000, 10'000), huge);
    EXPECT_NE(error.find("beyond 1 km"), std::string::npos) << error;
    EXPECT_NE(error.find("machine_width"), std::string::npos) << error;
}

}  // namespace
}  // namespace mixengine
