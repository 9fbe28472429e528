#pragma once
// Painted regions of a solid (issue 18): a point of the solid belongs to the region of the nearest
// surface triangle when that triangle is painted and no farther than the depth (mixing_paint_depth);
// otherwise to no region (the object's own colour). So paint is carried inward from the painted
// surface by the depth, and where two paints meet inside, the boundary is the set of points as far
// from the one as from the other. Lookups go through a uniform grid of cells (at least the depth
// wide, at most 96 per axis) listing the triangles within the depth of each cell.
#include <cstdint>
#include <vector>

#include "geometry/Point.h"
#include "mesh/Mesh.h"
#include "mixing/RegionField.h"

namespace mixengine {

class PaintedRegions : public RegionField {
  public:
    /// `face_region[f]`: the region of mesh face f (−1 = not painted); `mesh` is not kept.
    PaintedRegions(const Mesh& mesh, std::vector<int> face_region, coord_um depth_um);

    /// The region at `p` (microns, the mesh's frame), −1 for none.
    int regionAt(const Point3& p) const override;

  private:
    struct Triangle {
        double a[3], b[3], c[3];
    };
    std::vector<Triangle> triangles_;
    std::vector<int> region_;
    double depth_um_;
    double origin_[3] = {0, 0, 0};
    double cell_um_ = 1;
    int dims_[3] = {0, 0, 0};
    std::vector<std::uint32_t> cell_start_;  ///< CSR: triangles of cell i are [start[i], start[i+1])
    std::vector<std::uint32_t> cell_items_;

    void fillGrid();
    bool cellRange(const double lo[3], const double hi[3], int first[3], int last[3]) const;
    std::size_t cellIndex(int x, int y, int z) const;
};

/// Squared distance from `p` to the triangle (a, b, c), all in the same unit.
double squaredDistanceToTriangle(const double p[3], const double a[3], const double b[3], const double c[3]);

}  // namespace mixengine
