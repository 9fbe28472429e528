#pragma once
// Basic geometry types. Geometry is carried in integer microns (64-bit), as Clipper expects.
//   Point2  — a 2-D point in microns (ClipperLib::IntPoint: members X, Y).
//   Path    — a closed polygon or an open polyline in microns.
//   Paths   — several of them; for areas, outer contours counter-clockwise, holes clockwise.
//   Box2    — an axis-aligned rectangle in microns (ClipperLib::IntRect: left, top, right, bottom;
//             top is the smaller y).
//   Vec3    — a 3-D point in millimetres (double), used for mesh input before quantisation.
//   Point3  — a 3-D point in microns (int64).
#include <polyclipping/clipper.hpp>

#include <cmath>
#include <cstdint>

namespace mixengine {

using coord_um = ClipperLib::cInt;  ///< a length in microns
using Point2 = ClipperLib::IntPoint;
using Path = ClipperLib::Path;
using Paths = ClipperLib::Paths;
using Box2 = ClipperLib::IntRect;

constexpr double kMicronsPerMm = 1000.0;

inline coord_um mmToMicrons(double mm) {
    return static_cast<coord_um>(std::llround(mm * kMicronsPerMm));
}
inline double micronsToMm(coord_um um) {
    return static_cast<double>(um) / kMicronsPerMm;
}

/// The straight distance between two points in the XY plane, in microns. The squares of integer
/// differences below 2^26 µm (67 m) add up exactly in a double, so the square root is the correctly
/// rounded distance, as std::hypot's, without its cost (it was 2.6 % of a slice's CPU).
inline double distanceUm(const Point2& a, const Point2& b) {
    const auto dx = static_cast<double>(a.X - b.X), dy = static_cast<double>(a.Y - b.Y);
    return std::sqrt(dx * dx + dy * dy);
}

/// The same distance in millimetres.
inline double distanceMm(const Point2& a, const Point2& b) {
    return distanceUm(a, b) / kMicronsPerMm;
}

struct Vec3 {
    double x = 0, y = 0, z = 0;
    Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    bool operator==(const Vec3&) const = default;
};

inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline double length(const Vec3& a) {
    return std::sqrt(dot(a, a));
}

struct Point3 {
    coord_um x = 0, y = 0, z = 0;
    bool operator==(const Point3&) const = default;
};

}  // namespace mixengine
