#pragma once
// Degrees to radians, in the two roundings the engine uses (they differ in the last bit for some
// angles, and G-code and reports must not change):
//   radiansFromDegrees(d)  — d · π / 180, multiplied then divided: setting angles (infill, support,
//                            prime tower, Settings::angleRadians) and drawing.
//   kRadiansPerDegree      — π / 180 as one constant, to multiply by: the orientation search and
//                            Python's math.radians (which multiplies by this constant).
#include <numbers>

namespace mixengine {

inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

/// `degrees` · π / 180, evaluated left to right.
constexpr double radiansFromDegrees(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

}  // namespace mixengine
