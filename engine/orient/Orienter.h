#pragma once
// The dual-nozzle orientation pass (seed 000, issue 7): finds the rotation of two parts (A printed
// by extruder 0, B by extruder 1, rotated together about their common centre) that minimises the
// interference volume V of orient/Interference.h for the nozzle offset d.
//
//   sphere (default): FFT covariograms → V over the whole sphere of directions u = Rᵀd/|d| at ≤ 1°,
//            minima refined; candidates (the minima and the best directions that allow a large flat
//            face on the bed) whose estimate is within 1 % of the parts' volume of the best are
//            verified with exact CGAL volumes (at most `verify` minima); among those tied on V
//            (1 mm³ or 0.1 % of the volume) the spin about d and the candidate are chosen by the
//            secondary objective (orient/FreeSpin.h).
//   grid:    seed 000's method as published: latitude × longitude in `grid_step_deg` steps (10° →
//            1296 rotations, latitude the outer loop, both from 0), exact V for every rotation,
//            the first minimum in storage order; no spin.
// Open, non-manifold or self-intersecting parts cannot be measured exactly: a warning is added and
// the voxel (FFT) measure is used throughout. Throws InputError when d is zero or not horizontal.
#include <optional>
#include <string>
#include <vector>

#include "common/Log.h"
#include "mesh/Mesh.h"
#include "orient/FreeSpin.h"
#include "orient/Interference.h"
#include "orient/Rotation.h"

namespace mixengine::orient {

enum class Method { Sphere, Grid };

struct OrientOptions {
    Method method = Method::Sphere;
    Measure measure = Measure::OwnPart;
    Objective objective = Objective::FlatFace;
    int resolution = 128;            ///< voxels along the longest side of a part
    int verify = 3;                  ///< at most this many minima verified exactly (0: none)
    double grid_step_deg = 10.0;     ///< grid method step
    double overhang_angle_deg = 45;  ///< from the vertical, as support_angle
    int threads = 0;                 ///< 0 = all cores
};

struct CandidateReport {
    Vec3 u;
    LatLon angles;
    std::string source;
    double v_estimate_mm3 = 0;
    std::optional<double> v_exact_mm3;
};

/// V over latitude (rows) × longitude (columns), both from 0 in `step_deg` steps.
struct VMap {
    double step_deg = 0;
    int rows = 0, columns = 0;
    std::vector<double> values;
    bool exact = false;
};

struct OrientTimings {
    double check_s = 0;   ///< building the exact solids (closed / self-intersection checks)
    double voxel_s = 0;   ///< voxelising + FFT
    double search_s = 0;  ///< sphere or grid search
    double exact_s = 0;   ///< exact verification
    double spin_s = 0;    ///< secondary objective
    double total_s = 0;
};

struct OrientResult {
    Method method = Method::Sphere;
    Measure measure = Measure::OwnPart;
    Vec3 offset_mm;
    Vec3 centre_mm;  ///< rotation centre: middle of the parts' common bounding box
    Vec3 direction;  ///< u = Rᵀ d / |d|
    LatLon angles;
    double spin_deg = 0;
    Matrix3 rotation;
    std::string picked_by;  ///< which objective chose the spin (or the grid rule)
    SpinScore score;
    double volume_a_mm3 = 0, volume_b_mm3 = 0;
    bool exact = false;  ///< V values below are exact (CGAL); otherwise voxel estimates
    double v_before_mm3 = 0, v_after_mm3 = 0;
    double v_before_estimate_mm3 = 0, v_after_estimate_mm3 = 0;
    std::string solid_a, solid_b;  ///< describe(SolidStatus)
    std::vector<CandidateReport> candidates;
    std::vector<std::string> warnings;
    std::size_t evaluations = 0;  ///< V evaluations of the search
    VMap map;
    OrientTimings time;
};

OrientResult optimiseOrientation(const Mesh& a, const Mesh& b, const Vec3& offset_mm,
                                 const OrientOptions& options, Log& log);

std::string methodName(Method method);
std::string measureName(Measure measure);

}  // namespace mixengine::orient
