#pragma once
// Point queries on areas used by tree support (toolpaths/support/TreeSupport.h): inside tests, the
// nearest point of an outline, moving a point into or out of an area, and the minimum spanning
// tree of a set of points. Areas follow geometry/Point.h (outer contours counter-clockwise, holes
// clockwise); all lengths in microns.
#include <cstddef>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

/// Whether `p` lies in the area (an odd number of its loops around it); on an edge counts as
/// inside when `border_inside`.
bool insideArea(const Paths& area, Point2 p, bool border_inside);

/// The point of segment a–b nearest to `p` (rounded to microns).
Point2 nearestOnSegment(Point2 a, Point2 b, Point2 p);

/// Whether `p` lies inside the single loop `loop` (either orientation), its edge included.
bool insideLoop(const Path& loop, Point2 p);

struct NearestOnOutline {
    Point2 point{0, 0};
    Point2 edge_from{0, 0}, edge_to{0, 0};  ///< the edge it lies on, in the loop's direction
    double distance2_um2 = -1;              ///< < 0: the area has no edge
};

/// The point of the area's loops nearest to `p`.
NearestOnOutline nearestOnOutline(const Paths& area, Point2 p);

/// Moves `p`, when it lies in `area`, to just outside it: `margin_um` beyond the nearest outline
/// point, across that edge, provided that point is at most sqrt(`max_move2_um2`) away. Returns
/// whether it moved.
bool moveOutOf(const Paths& area, Point2& p, coord_um margin_um, double max_move2_um2);

/// Moves `p`, when it lies outside `loop`, onto the loop's nearest point provided that is at most
/// sqrt(`max_move2_um2`) away (a negative limit: any distance).
void moveOntoLoop(const Path& loop, Point2& p, double max_move2_um2);

/// The minimum spanning tree of `points` (Euclidean): for each point the indices of its
/// neighbours in the tree. Equal points are joined at distance 0.
std::vector<std::vector<std::size_t>> spanningTreeNeighbours(const std::vector<Point2>& points);

inline double distance2(Point2 a, Point2 b) {
    const double dx = double(a.X - b.X), dy = double(a.Y - b.Y);
    return dx * dx + dy * dy;
}

}  // namespace mixengine
