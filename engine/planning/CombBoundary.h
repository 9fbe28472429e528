#pragma once
// Combing: a travel that stays inside the printed part needs no retraction (Cura's
// retraction_combing). This answers "does the straight travel a→b stay inside `area`?" quickly
// for areas with many thousands of edges: the edges are bucketed in a uniform grid, and each cell's
// centre is classified once (a ray along its row crosses the boundary an odd number of times,
// counted cell by cell, each crossing in the cell that contains it); a point is inside when its
// cell's centre is and the segment between them crosses the boundary an even number of times, or
// the other way round (where that segment touches a vertex, or the centre lies on the boundary, a
// ray from the point to the grid's nearer side decides). A straight travel must cross no edge.
// The tests (inside, straightInside, which edges a travel crosses) are exact: integer coordinates,
// products in 128 bits, no division. Points on the boundary count as inside, touching is not
// crossing; a travel through a corner where the boundary passes from one side of it to the other
// crosses there (as one along the axis of a round hole through its corners does). route()
// constructs the points where a travel crosses a loop: those are interpolated in double precision
// and rounded to the nearest micron (a corner crossed is itself), the crossings are ordered along
// the travel in double precision and the shorter way around a loop is chosen by double-precision
// lengths.
#include <optional>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

class CombBoundary {
  public:
    CombBoundary() = default;
    /// `area`: closed polygons, holes included (even-odd), microns.
    explicit CombBoundary(const Paths& area);

    bool empty() const { return edges_.empty(); }
    bool inside(const Point2& p) const;
    /// Both end points and the midpoint (rounded towards a) inside, and the segment crosses no
    /// boundary edge.
    bool straightInside(const Point2& a, const Point2& b) const;
    /// Whether the segment a–b properly crosses a boundary edge (touching does not count).
    bool crossesBoundary(const Point2& a, const Point2& b) const;
    /// A travel from a to b that stays inside: the straight line where it can, else around each
    /// boundary loop it would cross, along the loop's shorter side, then shortened where a
    /// straight shortcut stays inside. The points after `a`, ending with b; nothing when a and b
    /// are not both inside or lie in different islands.
    std::optional<Path> route(const Point2& a, const Point2& b) const;
    /// Where the straight way from `from` (outside) towards `toward` first enters the area, moved
    /// `nudge_um` further along so that it lies inside; nothing when it does not enter or the
    /// nudged point is not inside.
    std::optional<Point2> entryToward(const Point2& from, const Point2& toward, coord_um nudge_um = 20) const;
    /// `p` when it is inside; else the boundary point nearest to it, if within `max_distance_um`,
    /// moved `nudge_um` on past it (away from `p`) so that it lies inside — less (halved down to
    /// none) where the area is thinner than that; else nothing.
    std::optional<Point2> moveInside(const Point2& p, coord_um max_distance_um, coord_um nudge_um = 20) const;
    /// Where a travel from `from` towards `close_to` may leave the area, as CuraEngine 4.13's comb
    /// chooses it: on every boundary edge that comes within `reach_um` of the segment from–close_to,
    /// the edge's point nearest to close_to, moved `nudge_um` off the edge to its inside (edges
    /// where neither side is inside are left out); best first by |x − close_to|² + |x − from|²/10.
    std::vector<Point2> exitsToward(const Point2& from, const Point2& close_to, coord_um reach_um,
                                    coord_um nudge_um) const;

  private:
    struct Edge {
        Point2 a, b;
        std::uint32_t loop = 0;   ///< index into loops_
        std::uint32_t index = 0;  ///< a = loops_[loop][index]
    };
    struct Crossing {
        double t = 0;  ///< along the travel, 0..1
        Point2 at{};
        const Edge* edge = nullptr;
    };
    /// Whether the travel p–q crosses the boundary at `edge`: properly through its inside, or
    /// through its first vertex (crossesAtVertex).
    bool crossesEdge(const Point2& p, const Point2& q, const Edge& edge) const;
    /// Whether the travel p–q passes through edge.a, strictly between its ends, where the loop goes
    /// from one side of the travel's line to the other (a run of the loop along the line counted at
    /// its first vertex, and only when the run ends before the travel does); a loop that comes back
    /// to the side it came from touches the travel.
    bool crossesAtVertex(const Point2& p, const Point2& q, const Edge& edge) const;
    std::vector<Crossing> crossings(const Point2& a, const Point2& b) const;
    Path aroundLoop(const Crossing& from, const Crossing& to) const;
    Path shortened(const Point2& start, const Path& points) const;
    /// straightInside for end points already known to be inside.
    bool straightBetweenInside(const Point2& a, const Point2& b) const;
    /// visit(cell's edge indices) for every cell the segment a–b meets (and a few beside it), row by
    /// row, until visit returns false; returns false then, else true.
    template <typename Visit>
    bool forCellsAlong(const Point2& a, const Point2& b, Visit visit) const;
    std::size_t cellIndex(coord_um cx, coord_um cy) const {
        return static_cast<std::size_t>(cy) * static_cast<std::size_t>(columns_) +
               static_cast<std::size_t>(cx);
    }
    coord_um column(coord_um x) const;
    coord_um row(coord_um y) const;
    /// The centre of cell (c, r): its inside state is known (anchors_), so inside(p) only looks at
    /// the edges of p's cell.
    Point2 anchor(coord_um c, coord_um r) const;
    /// anchors_ of row r, by the ray method for the whole row at once.
    void classifyAnchors(coord_um r);
    /// inside(p) for p in the grid's cell (first, r), by a ray to the nearer side of the grid.
    bool insideByRay(const Point2& p, coord_um r, coord_um first) const;

    Paths loops_;
    std::vector<Edge> edges_;
    std::vector<std::vector<std::uint32_t>> cells_;  ///< edge indices per cell
    /// Per cell: whether its anchor is inside (1) or not (0), kAnchorOnBoundary when it lies on an edge.
    static constexpr std::uint8_t kAnchorOnBoundary = 2;
    std::vector<std::uint8_t> anchors_;
    Point2 origin_{0, 0};
    coord_um cell_um_ = 1;
    coord_um columns_ = 0, rows_ = 0;
};

}  // namespace mixengine
