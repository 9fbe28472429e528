#pragma once
// The rotation about d that V leaves free, used for the secondary objectives seed 000 names as
// future work: a flat face on the bed, a low build height, little overhang (support).
//
// For each spin (every 1°, plus the exact spins that put a large flat face on the bed) the parts,
// rotated together, are scored by
//   contact_mm2  — area of facets lying on the bed (normal within 0.5° of −z, all corners within
//                  0.05 mm of the lowest point);
//   height_mm    — build height;
//   overhang_mm2 — projected area of down-facing facets steeper than the overhang angle (from
//                  the vertical, as Cura's support_angle) that are not on the bed.
// The objective orders the three (the chosen one first, the others break ties, each with a small
// tolerance); `picked_by` names the last criterion that ruled options out.
#include <string>
#include <vector>

#include "mesh/Mesh.h"
#include "orient/Rotation.h"

namespace mixengine::orient {

enum class Objective { FlatFace, LowHeight, LowOverhang };

struct SpinScore {
    double spin_deg = 0;
    double contact_mm2 = 0;
    double height_mm = 0;
    double overhang_mm2 = 0;
};

/// The parts' facets in mm, prepared once (normals unit length, areas in mm²).
class SurfaceSample {
  public:
    SurfaceSample(const std::vector<const Mesh*>& meshes);
    SpinScore score(const Matrix3& rotation, double overhang_angle_deg) const;
    /// Normals of flat regions whose area is at least `min_share` of the surface, largest first
    /// (at most `count`).
    std::vector<Vec3> flatNormals(double min_share, int count) const;
    double surfaceAreaMm2() const { return total_area_; }

  private:
    std::vector<Vec3> vertices_;
    std::vector<std::array<std::uint32_t, 3>> faces_;
    std::vector<Vec3> normals_;
    std::vector<double> areas_;
    double total_area_ = 0;
};

/// One option: a direction candidate (index) with a spin and its score.
struct SpinOption {
    int candidate = 0;
    SpinScore score;
};

/// The spins to try for direction `angles`: every 1° and those that put a flat normal on the bed.
std::vector<double> spinsToTry(const LatLon& angles, const Vec3& d_unit,
                               const std::vector<Vec3>& flat_normals);

/// The best option by the objective; `picked_by` receives "flat face", "low height" or
/// "low overhang".
SpinOption chooseOption(const std::vector<SpinOption>& options, Objective objective, std::string& picked_by);

std::string objectiveName(Objective objective);

}  // namespace mixengine::orient
