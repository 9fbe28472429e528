#pragma once
// Painted regions of a solid (issue 18): a point of the solid belongs to the region of the nearest
// surface triangle when that triangle is painted and no farther than the depth (mixing_paint_depth);
// otherwise to no region (the object's own colour). So paint is carried inward from the painted
// surface by the depth, and where two paints meet inside, the boundary is the set of points as far
// from the one as from the other. Lookups go through a uniform grid of cells (at least the depth wide,
// at most 96 per axis) listing the triangles within the depth of each cell; the queries of feathered
// edges (mixing_paint_blend, mixing/fields/FeatheredPaint.h) for the nearest triangle of a given region, up
// to the depth plus an extra reach, through a tree per region (mixing/fields/TriangleTree.h).
#include <array>
#include <cstdint>
#include <vector>

#include "geometry/Point.h"
#include "mesh/Mesh.h"
#include "mixing/fields/RegionField.h"
#include "mixing/fields/TriangleTree.h"

namespace mixengine {

/// One region's nearest surface triangle seen from a point: its region (−1: none found), the distance
/// and the nearest point on it (microns, the mesh's frame).
struct NearestPaint {
    int region = -1;
    double distance_um = 0;
    std::array<double, 3> point_um{};
};

/// A point's own region (as regionAt) and the nearest painted triangle of any other region.
struct NearestRegions {
    NearestPaint own;
    NearestPaint other;  ///< region −1: no other painted triangle within the reach
};

class PaintedRegions : public RegionField {
  public:
    /// `face_region[f]`: the region of mesh face f (−1 = not painted); `mesh` is not kept. `extra_reach_um`
    /// (≥ 0): how much farther than the depth the nearest-region queries below must see.
    PaintedRegions(const Mesh& mesh, std::vector<int> face_region, coord_um depth_um,
                   coord_um extra_reach_um = 0);

    /// The region at `p` (microns, the mesh's frame), −1 for none.
    int regionAt(const Point3& p) const override;
    /// `p`'s own region (regionAt's; own.region −1 for none) and, when that is painted, the nearest triangle
    /// painted with another region (not unpainted) within the depth plus the extra reach.
    NearestRegions nearestRegions(const Point3& p) const;
    /// The distances from `p_um` to the nearest triangles of regions `a` and `b` (in that order) within the
    /// depth plus the extra reach; +∞ for a region with none so near. `bound_um`: upper bounds the caller
    /// knows (a nearby point's distance plus the way from it), which let far triangles be skipped; a
    /// region with no triangle within its bound is +∞ too.
    std::array<double, 2> distancesToRegionsUm(const std::array<double, 3>& p_um, int a, int b,
                                               std::array<double, 2> bound_um = {kUnbounded,
                                                                                 kUnbounded}) const;
    static constexpr double kUnbounded = 1e300;
    /// The nearest triangle of painted `region` to `p` (microns) closer than sqrt(`limit_sq`); region −1
    /// when there is none.
    NearestPaint nearestOf(int region, const double p[3], double limit_sq) const;
    int regionCount() const { return region_count_; }
    double reachUm() const { return reach_um_; }

  private:
    struct Triangle {
        double a[3], b[3], c[3];
        double lo[3], hi[3];  ///< its bounding box: a cheap lower bound of the distance to it
    };
    std::vector<Triangle> triangles_;
    std::vector<int> region_;
    double depth_um_;
    double reach_um_;
    int region_count_ = 0;
    double origin_[3] = {0, 0, 0};
    double cell_um_ = 1;
    int dims_[3] = {0, 0, 0};
    std::vector<std::uint32_t> cell_start_;  ///< CSR: triangles of cell i are [start[i], start[i+1])
    std::vector<std::uint32_t> cell_items_;
    std::vector<TriangleTree> region_trees_;      ///< per painted region, with an extra reach only
    std::vector<std::vector<int>> region_faces_;  ///< per painted region: the tree's triangle → face

    void fillGrid();
    void buildTrees();

    bool cellRange(const double lo[3], const double hi[3], int first[3], int last[3]) const;
    std::size_t cellIndex(int x, int y, int z) const;
    /// The grid cell holding `p`, or false outside the grid.
    bool cellOf(const double p[3], std::size_t& cell) const;
    /// The nearest triangle in `cell` to `p` (painted or not), no farther than `limit_um`.
    NearestPaint nearestIn(std::size_t cell, const double p[3], double limit_um) const;
};

/// Squared distance from `p` to the triangle (a, b, c), all in the same unit.
double squaredDistanceToTriangle(const double p[3], const double a[3], const double b[3], const double c[3]);
/// The same, and the nearest point of the triangle in `nearest`.
double squaredDistanceToTriangle(const double p[3], const double a[3], const double b[3], const double c[3],
                                 double nearest[3]);

}  // namespace mixengine
