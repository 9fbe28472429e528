#pragma once
// Fractional voxelisation of a triangle mesh: each cell holds the fraction of its volume inside
// the solid (0..1). Used for the covariograms of the orientation pass (orient/Covariogram.h).
//
// Method: vertical rays, `samples`² per cell column (exact integer point-in-triangle tests with a
// top-left rule, so a ray through an edge or a vertex counts each surface crossing once); along a
// ray the inside intervals are exact in z, so a cell gets the covered length of its sub-rays.
// Inside = non-zero winding of the crossings (entering through down-facing facets); a ray whose
// crossings do not sum to zero (open or badly oriented mesh) is filled by the facets' orientation
// alone, bridging holes up to the grid's z range, and is counted in `inconsistent_rays`.
#include <array>
#include <cstddef>
#include <vector>

#include "geometry/Point.h"
#include "mesh/Mesh.h"

namespace mixengine::orient {

/// A cell (i, j, k) spans origin + (i, j, k) * step .. origin + (i+1, j+1, k+1) * step (mm).
struct GridFrame {
    Vec3 origin_mm;
    std::array<double, 3> step_mm{1, 1, 1};
    std::array<int, 3> cells{1, 1, 1};

    double cellVolumeMm3() const { return step_mm[0] * step_mm[1] * step_mm[2]; }
    std::size_t cellCount() const {
        return static_cast<std::size_t>(cells[0]) * static_cast<std::size_t>(cells[1]) *
               static_cast<std::size_t>(cells[2]);
    }
};

/// A frame covering `bounds_mm` (min, max) exactly, with about `resolution` cells along its
/// longest side and cells as close to cubes as the box allows (faces of the box on cell faces).
GridFrame frameCovering(const Vec3& min_mm, const Vec3& max_mm, int resolution);

struct VoxelGrid {
    GridFrame frame;
    std::vector<float> fraction;  ///< index (i * cells[1] + j) * cells[2] + k
    std::size_t rays = 0;
    std::size_t inconsistent_rays = 0;

    double volumeMm3() const;
};

/// Bounds of a mesh in millimetres.
std::pair<Vec3, Vec3> boundsMm(const Mesh& mesh);

VoxelGrid voxelise(const Mesh& mesh, const GridFrame& frame, int samples, int threads);

}  // namespace mixengine::orient
