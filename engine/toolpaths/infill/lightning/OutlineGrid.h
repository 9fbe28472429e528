#pragma once
// The edges of a layer's infill outline in a square grid of cells, for the lightning trees
// (toolpaths/infill/lightning/LightningInfill.h): the nearest outline point, whether a straight
// segment touches the outline, and where a segment crosses it. Lengths in microns; every query
// gives the same answer as a search over all edges would (the grid only skips far edges).
#include <optional>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

class OutlineGrid {
  public:
    /// `outlines`: closed loops (any orientation); `cell_um` > 0.
    OutlineGrid(const Paths& outlines, coord_um cell_um);

    bool empty() const { return edges_.empty(); }

    /// The point of the outline nearest to `p`; nothing when there are no edges.
    std::optional<Point2> nearest(Point2 p) const;

    /// Whether segment a–b touches or crosses an edge (touching at an end counts).
    bool touches(Point2 a, Point2 b) const;

    /// Where segment a–b crosses an edge, the crossing nearest to b, provided it is less than
    /// `within_um` from b.
    std::optional<Point2> crossingNearEnd(Point2 a, Point2 b, coord_um within_um) const;

  private:
    struct Edge {
        Point2 a, b;
    };
    struct CellRange {
        long long x0, y0, x1, y1;  ///< inclusive, clamped to the grid
    };
    CellRange cellsOf(coord_um x0, coord_um y0, coord_um x1, coord_um y1) const;
    long long cellX(coord_um x) const;
    long long cellY(coord_um y) const;
    const std::vector<std::size_t>& cell(long long x, long long y) const;
    /// Visits the edges listed in the cells of `range` (an edge may come more than once).
    template <typename Visit>
    void forEdges(const CellRange& range, Visit visit) const;

    coord_um cell_um_;
    Point2 origin_{0, 0};  ///< corner of cell (0, 0)
    long long columns_ = 0, rows_ = 0;
    std::vector<Edge> edges_;
    std::vector<std::vector<std::size_t>> cells_;  ///< row-major
};

}  // namespace mixengine
