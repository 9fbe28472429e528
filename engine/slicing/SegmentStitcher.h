#pragma once
// Joins the cut segments of one plane into closed loops (linear time).
//
// Contract:
//   - segments are chained through a hash of their exact end points (PointMultimap): both facets
//     sharing a crossed edge compute the same integer point (slicing/FacetPlane.h), so a closed
//     surface chains without tolerance. Zero-length segments are ignored.
//   - the chaining does not depend on segment direction; where several segments meet at one
//     point it prefers one that continues in facet direction (consistent winding) and, among
//     those, the sharpest turn towards the solid side, so shells touching at a point or an edge
//     come out as separate loops.
//   - open chains whose ends lie within max_gap_um of each other are then joined, nearest ends
//     first (slicing/GapCloser.h); what stays open is returned in `open_polylines`.
//   - a closed loop's vertices are the segments' printed points (CuraEngine's rounding, see
//     FacetSegment), in CuraEngine's order: the first segment's start, then every segment's end
//     (the closing vertex stays unless it repeats the first exactly); open pieces keep the exact
//     points.
//   - every loop records how much of its length follows the facets' direction and how much runs
//     against it; the outline builder uses this to tell a solid nested in a solid from a cavity.
#include <vector>

#include "geometry/Point.h"
#include "slicing/FacetPlane.h"
#include "slicing/PointMultimap.h"

namespace mixengine {

/// A chain of cut segments in microns.
struct StitchedPath {
    Path points;                   ///< for a loop: closed (see above for the closing vertex)
    double along_facets_um = 0;    ///< length of segments traversed in their facet direction
    double against_facets_um = 0;  ///< length of segments traversed against it
};

struct StitchResult {
    std::vector<StitchedPath> loops;   ///< closed loops, any orientation
    Paths open_polylines;              ///< chains that could not be closed
    std::size_t gap_closed_loops = 0;  ///< of `loops`, how many were closed across gaps (open mesh)
};

/// Reusable (keeps its buffers between cuts); not thread-safe.
class SegmentStitcher {
  public:
    StitchResult stitch(const std::vector<FacetSegment>& segments, coord_um max_gap_um);

  private:
    /// Marks and returns an unused segment end at `point`, reached from `came_from` (kNone if
    /// there is none). Walking forward it prefers a segment that starts there, walking backward
    /// one that ends there; among several, the sharpest turn towards the solid side (leftmost
    /// forward, rightmost backward), which keeps loops that touch at a point apart.
    std::int32_t takeEndAt(const Point2& came_from, const Point2& point, bool forward,
                           const std::vector<FacetSegment>& segments);
    /// Like takeEndAt when `point` has two or more unused ends.
    std::int32_t chooseAmongEnds(const Point2& came_from, const Point2& point, bool forward,
                                 const std::vector<FacetSegment>& segments) const;
    /// Appends segments at the back of `path` until it closes (returns true) or runs out.
    bool extendForward(StitchedPath& path, const std::vector<FacetSegment>& segments);
    /// Prepends segments at the front of an open `path` until it runs out.
    void extendBackward(StitchedPath& path, const std::vector<FacetSegment>& segments);

    PointMultimap ends_;
    std::vector<char> used_;
    Path exact_;  ///< the exact points of the chain being extended forward
    Path prefix_;
};

}  // namespace mixengine
