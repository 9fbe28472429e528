#pragma once
// Seed 000's interference volume for a nozzle offset d (extruder 1 minus extruder 0), evaluated in
// the unrotated parts' frame at the shift v = Rᵀ d = |d| u:
//   own part (seed 000):  V = vol(A ∩ (A + v)) + vol(B ∩ (B − v))
//   all material:         V = own + vol(B ∩ (A + v)) + vol(A ∩ (B − v))
// i.e. the idle nozzle over any material of the layer (A ∪ B, A and B interior-disjoint).
// Two evaluators: the FFT estimate (covariograms of voxel grids, all directions at once) and the
// exact CGAL volume (orient/ExactSolid.h).
#include <optional>
#include <vector>

#include "common/Log.h"
#include "orient/Covariogram.h"
#include "orient/ExactSolid.h"

namespace mixengine::orient {

enum class Measure { OwnPart, AllMaterial };

/// The FFT estimate of V(u) for unit directions u.
class InterferenceModel {
  public:
    InterferenceModel() = default;
    /// Voxelises both parts (about `resolution` cells along the longest side) and correlates them.
    InterferenceModel(const Mesh& a, const Mesh& b, double offset_mm, Measure measure, int resolution,
                      int threads);

    double at(const Vec3& u) const;
    double offsetMm() const { return offset_mm_; }
    double voxelVolumeMm3(int part) const { return part == 0 ? volume_a_ : volume_b_; }
    /// Fraction of the rays whose crossings did not close (open or badly oriented mesh), per part.
    double inconsistentRayShare(int part) const { return part == 0 ? bad_a_ : bad_b_; }
    const GridFrame& frame(int part) const { return part == 0 ? frame_a_ : frame_b_; }

  private:
    double offset_mm_ = 0;
    Measure measure_ = Measure::OwnPart;
    CorrelationField g_a_, g_b_, cross_;
    GridFrame frame_a_, frame_b_;
    double volume_a_ = 0, volume_b_ = 0, bad_a_ = 0, bad_b_ = 0;
};

/// One exact term vol(first ∩ (second + shift)) of V.
struct ExactTerm {
    const ExactSolid* first;
    const ExactSolid* second;
    Vec3 shift_mm;
};

/// The terms whose sum is V at shift v (2 for the own-part measure, 4 for all material), so that
/// callers can compute them in parallel.
std::vector<ExactTerm> exactTerms(const ExactSolid& a, const ExactSolid& b, const Vec3& v_mm,
                                  Measure measure);

/// The exact V at shift v (mm); nullopt when a solid is not exact or CGAL failed.
std::optional<double> exactInterference(const ExactSolid& a, const ExactSolid& b, const Vec3& v_mm,
                                        Measure measure);

}  // namespace mixengine::orient
