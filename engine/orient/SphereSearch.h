#pragma once
// The whole-sphere search of the offset direction u (orient/Rotation.h): V(u) from the FFT model
// on a 1° grid of polar angle × azimuth (≤ 1° apart everywhere), the best separated local minima
// refined by a shrinking pattern search to 0.01°, plus — for each large flat face of the parts —
// the best u on the great circle perpendicular to its normal (those directions let that face lie
// on the bed after the free spin about d).
#include <functional>
#include <string>
#include <vector>

#include "geometry/Point.h"

namespace mixengine::orient {

struct DirectionCandidate {
    Vec3 u;
    double v_estimate_mm3 = 0;
    std::string source;  ///< "local minimum" or "flat face <n>"
    int flat_face = -1;  ///< index into the flat normals for great-circle candidates
};

struct SphereSearchOptions {
    double grid_step_deg = 1.0;
    int minima = 6;                 ///< separated local minima kept
    double separation_deg = 5.0;    ///< minimum angle between kept minima
    bool even = true;               ///< V(u) = V(−u): treat u and −u as one
    double circle_step_deg = 0.25;  ///< sampling of the great circles of flat faces
};

struct SphereSearchStats {
    std::size_t evaluations = 0;
};

using DirectionFunction = std::function<double(const Vec3&)>;

std::vector<DirectionCandidate> searchSphere(const DirectionFunction& v,
                                             const std::vector<Vec3>& flat_normals,
                                             const SphereSearchOptions& options, SphereSearchStats& stats);

/// A unit vector from polar angle (from +z) and azimuth, degrees.
Vec3 sphericalDirection(double polar_deg, double azimuth_deg);

}  // namespace mixengine::orient
