#pragma once
// Rotations of the orientation pass (seed 000) and the direction they send the nozzle offset to.
//
// Conventions (seed 000 §3; the order of composition is not stated there, this is ours):
//   latitude  = rotation about the Y axis in the left-hand sense (right-hand angle −lat);
//   longitude = rotation about the Z axis in the right-hand sense;
//   R(lat, lon) = Rz(lon) · Ry(−lat): the model is first tilted (latitude), then turned on the bed
//   (longitude). A point p of the model goes to c + R (p − c), c = the common centre of the parts.
// The interference volume depends only on u = Rᵀ d / |d| (the offset seen from the unrotated
// model); rotations that differ by a spin about d share it. Angles are degrees at this interface.
#include "geometry/Matrix3.h"
#include "geometry/Point.h"

namespace mixengine::orient {

Matrix3 identity3();
Matrix3 multiply(const Matrix3& a, const Matrix3& b);
Matrix3 transpose(const Matrix3& a);
/// Right-hand rotation by `angle_deg` about the unit vector `axis`.
Matrix3 rotationAbout(const Vec3& axis, double angle_deg);
/// R(lat, lon) as above.
Matrix3 seedRotation(double latitude_deg, double longitude_deg);
Vec3 normalised(const Vec3& v);

/// u = Rᵀ d̂ for R = seedRotation(lat, lon); `d_unit` must be a unit vector.
Vec3 offsetDirection(double latitude_deg, double longitude_deg, const Vec3& d_unit);

struct LatLon {
    double latitude_deg = 0;   ///< in [0, 360)
    double longitude_deg = 0;  ///< in [0, 360)
};
/// A (lat, lon) whose seedRotation sends d̂ to u (offsetDirection(lat, lon, d̂) == u). `d_unit`
/// must be horizontal (z = 0), as nozzle offsets are.
LatLon latLonOf(const Vec3& u, const Vec3& d_unit);

/// The full rotation for direction u with `spin_deg` about d: rotationAbout(d̂, spin) · R(lat, lon).
Matrix3 spunRotation(const LatLon& angles, const Vec3& d_unit, double spin_deg);

}  // namespace mixengine::orient
