#pragma once
// An affine map p' = L * p + t in the layout lib3mf uses for MODELTRANSFORM (rows are output
// coordinates, column 3 is the translation). Identity by default.
#include "geometry/Point.h"

namespace mixengine {

struct Affine3 {
    double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

    Vec3 apply(const Vec3& p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
    }

    /// The map "first `inner`, then this".
    Affine3 after(const Affine3& inner) const {
        Affine3 r;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 4; ++j) {
                double sum = j == 3 ? m[i][3] : 0.0;
                for (int k = 0; k < 3; ++k) {
                    sum += m[i][k] * inner.m[k][j];
                }
                r.m[i][j] = sum;
            }
        }
        return r;
    }
};

}  // namespace mixengine
