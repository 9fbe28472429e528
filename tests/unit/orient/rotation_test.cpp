// Rotation conventions of the orientation pass (orient/Rotation.h).
#include <gtest/gtest.h>

#include "orient/Rotation.h"

namespace mixengine::orient {
namespace {

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(OrientRotation, LatitudeIsLeftHandedAboutY) {
    // Left-hand rule about +Y: +X turns towards +Z (a right-hand turn would send it to −Z).
    expectNear(seedRotation(90, 0).apply({1, 0, 0}), {0, 0, 1});
    expectNear(seedRotation(90, 0).apply({0, 1, 0}), {0, 1, 0});
}

TEST(OrientRotation, LongitudeIsRightHandedAboutZ) {
    expectNear(seedRotation(0, 90).apply({1, 0, 0}), {0, 1, 0});
    expectNear(seedRotation(0, 90).apply({0, 0, 1}), {0, 0, 1});
}

TEST(OrientRotation, LatitudeFirstThenLongitude) {
    // R = Rz(lon) · Ry(−lat): +X tilted up to +Z stays there when turned about Z.
    expectNear(seedRotation(90, 90).apply({1, 0, 0}), {0, 0, 1});
    expectNear(seedRotation(90, 90).apply({0, 0, 1}), {0, -1, 0});
}

TEST(OrientRotation, LatLonOfInvertsOffsetDirection) {
    const Vec3 d = normalised({3, 4, 0});
    for (double lat = 0; lat < 360; lat += 37) {
        for (double lon = 0; lon < 360; lon += 41) {
            const Vec3 u = offsetDirection(lat, lon, d);
            const LatLon back = latLonOf(u, d);
            expectNear(offsetDirection(back.latitude_deg, back.longitude_deg, d), u, 1e-9);
        }
    }
}

TEST(OrientRotation, SpinAboutTheOffsetKeepsTheDirection) {
    const Vec3 d{1, 0, 0};
    const LatLon angles{20, 70};
    const Vec3 u = offsetDirection(angles.latitude_deg, angles.longitude_deg, d);
    for (const double spin : {0.0, 33.0, 90.0, 271.0})
        expectNear(transpose(spunRotation(angles, d, spin)).apply(d), u);
    // and it is a proper rotation: columns orthonormal
    const Matrix3 r = spunRotation(angles, d, 33);
    const Matrix3 rtr = multiply(transpose(r), r);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(rtr.m[i][j], i == j ? 1.0 : 0.0, 1e-12);
    }
}

}  // namespace
}  // namespace mixengine::orient
