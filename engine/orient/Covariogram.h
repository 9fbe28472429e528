#pragma once
// Set covariograms and cross-covariograms from voxel grids, by FFT (FFTW):
//   c_XY(v) = vol(X ∩ (Y + v)) ≈ Σ_x fX(x) fY(x − v) · cell volume
// for every whole-cell shift v at once; between cells the value is interpolated trilinearly.
// g_X(v) = c_XX(v) is the set covariogram of seed 000's interference volume.
//
// The grids are zero-padded so that shifts up to `reach_mm` (per axis) do not wrap around;
// values farther than the reach are not kept (at() returns 0 there, as it does beyond the solid).
#include <array>
#include <utility>
#include <vector>

#include "orient/VoxelGrid.h"

namespace mixengine::orient {

class CorrelationField {
  public:
    CorrelationField() = default;
    CorrelationField(std::array<double, 3> step_mm, std::array<int, 3> reach_cells, std::vector<float> values)
        : step_mm_(step_mm), reach_(reach_cells), values_(std::move(values)) {}

    /// c(v) for a shift in mm (trilinear between cells, never negative).
    double at(const Vec3& v_mm) const;
    /// The value at whole-cell shift (a, b, c); |a| ≤ reach.
    double atCell(int a, int b, int c) const;
    const std::array<int, 3>& reachCells() const { return reach_; }

  private:
    std::array<double, 3> step_mm_{1, 1, 1};
    std::array<int, 3> reach_{0, 0, 0};
    std::vector<float> values_;
};

/// One correlation to compute: c_XY with X = grids[x], Y = grids[y] (equal frames required).
struct CorrelationPair {
    int x = 0;
    int y = 0;
};

/// Computes every requested field; FFTs run in parallel on `threads` threads. FFTW's planner is
/// not thread-safe: plans are made on the calling thread, so two correlate() calls must not run
/// at the same time. Throws InternalError when a pair's frames differ.
std::vector<CorrelationField> correlate(const std::vector<const VoxelGrid*>& grids,
                                        const std::vector<CorrelationPair>& pairs, double reach_mm,
                                        int threads);

/// The smallest size ≥ n whose only prime factors are 2, 3, 5, 7 (fast FFT sizes).
int fastFftSize(int n);

}  // namespace mixengine::orient
