#pragma once
// A 3x3 linear transform of millimetre points (rotation, scale, mirror).
#include "geometry/Point.h"

namespace mixengine {

/// Row-major 3x3 matrix applied as p' = M * p (Cura's mesh_rotation_matrix, in Cura's axis frame
/// already converted to the engine's: x right, y back, z up).
struct Matrix3 {
    double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    Vec3 apply(const Vec3& p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z, m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z,
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z};
    }
};

}  // namespace mixengine
