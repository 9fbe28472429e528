#include "orient/Rotation.h"

#include <algorithm>
#include <cmath>

#include "geometry/Angles.h"

namespace mixengine::orient {
namespace {

double wrapDegrees(double a) {
    double r = std::fmod(a, 360.0);
    if (r < 0)
        r += 360.0;
    return r >= 360.0 ? 0.0 : r;
}

}  // namespace

Matrix3 identity3() {
    return Matrix3{};
}

Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
    Matrix3 r;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
        }
    }
    return r;
}

Matrix3 transpose(const Matrix3& a) {
    Matrix3 r;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            r.m[i][j] = a.m[j][i];
    }
    return r;
}

Vec3 normalised(const Vec3& v) {
    const double len = length(v);
    return len > 0 ? v * (1.0 / len) : v;
}

Matrix3 rotationAbout(const Vec3& axis, double angle_deg) {
    const Vec3 k = normalised(axis);
    const double c = std::cos(angle_deg * kRadiansPerDegree), s = std::sin(angle_deg * kRadiansPerDegree),
                 t = 1 - c;
    Matrix3 r;
    r.m[0][0] = c + k.x * k.x * t;
    r.m[0][1] = k.x * k.y * t - k.z * s;
    r.m[0][2] = k.x * k.z * t + k.y * s;
    r.m[1][0] = k.y * k.x * t + k.z * s;
    r.m[1][1] = c + k.y * k.y * t;
    r.m[1][2] = k.y * k.z * t - k.x * s;
    r.m[2][0] = k.z * k.x * t - k.y * s;
    r.m[2][1] = k.z * k.y * t + k.x * s;
    r.m[2][2] = c + k.z * k.z * t;
    return r;
}

Matrix3 seedRotation(double latitude_deg, double longitude_deg) {
    return multiply(rotationAbout({0, 0, 1}, longitude_deg), rotationAbout({0, 1, 0}, -latitude_deg));
}

Vec3 offsetDirection(double latitude_deg, double longitude_deg, const Vec3& d_unit) {
    return transpose(seedRotation(latitude_deg, longitude_deg)).apply(d_unit);
}

LatLon latLonOf(const Vec3& u_in, const Vec3& d_unit) {
    // u = Ry(lat) · Rz(−lon) · d̂. Rz(−lon) d̂ = (cos β, sin β, 0) with β = α − lon (α = angle of d̂);
    // Ry(lat) keeps y and turns (cos β, 0) in the xz-plane: u = (cos β cos lat, sin β, −cos β sin lat).
    const Vec3 u = normalised(u_in);
    const double alpha = std::atan2(d_unit.y, d_unit.x);
    const double beta = std::asin(std::clamp(u.y, -1.0, 1.0));
    const double latitude = std::hypot(u.x, u.z) < 1e-12 ? 0.0 : std::atan2(-u.z, u.x);
    return {wrapDegrees(latitude / kRadiansPerDegree), wrapDegrees((alpha - beta) / kRadiansPerDegree)};
}

Matrix3 spunRotation(const LatLon& angles, const Vec3& d_unit, double spin_deg) {
    return multiply(rotationAbout(d_unit, spin_deg), seedRotation(angles.latitude_deg, angles.longitude_deg));
}

}  // namespace mixengine::orient
