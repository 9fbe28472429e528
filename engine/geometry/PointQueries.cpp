#include "geometry/PointQueries.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mixengine {
namespace {

void nearestOnLoop(const Path& loop, Point2 p, NearestOnOutline& best) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point2 a = loop[i];
        const Point2 b = loop[(i + 1) % loop.size()];
        const Point2 q = nearestOnSegment(a, b, p);
        const double d2 = distance2(p, q);
        if (best.distance2_um2 < 0 || d2 < best.distance2_um2)
            best = {q, a, b, d2};
    }
}

}  // namespace

Point2 nearestOnSegment(Point2 a, Point2 b, Point2 p) {
    const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
    const double length2 = dx * dx + dy * dy;
    if (length2 <= 0)
        return a;
    const double t = std::clamp((double(p.X - a.X) * dx + double(p.Y - a.Y) * dy) / length2, 0.0, 1.0);
    return {a.X + std::llround(t * dx), a.Y + std::llround(t * dy)};
}

bool insideLoop(const Path& loop, Point2 p) {
    return loop.size() >= 3 && ClipperLib::PointInPolygon(p, loop) != 0;
}

bool insideArea(const Paths& area, Point2 p, bool border_inside) {
    int crossings = 0;
    for (const Path& loop : area) {
        if (loop.size() < 3)
            continue;
        const int where = ClipperLib::PointInPolygon(p, loop);
        if (where < 0)
            return border_inside;
        crossings += where;
    }
    return crossings % 2 == 1;
}

NearestOnOutline nearestOnOutline(const Paths& area, Point2 p) {
    NearestOnOutline best;
    for (const Path& loop : area)
        nearestOnLoop(loop, p, best);
    return best;
}

bool moveOutOf(const Paths& area, Point2& p, coord_um margin_um, double max_move2_um2) {
    if (!insideArea(area, p, true))
        return false;
    const NearestOnOutline near = nearestOnOutline(area, p);
    if (near.distance2_um2 < 0 || near.distance2_um2 > max_move2_um2)
        return false;
    // Across the edge: its right-hand side is outside the area (outer loops CCW, holes CW).
    const double dx = double(near.edge_to.X - near.edge_from.X),
                 dy = double(near.edge_to.Y - near.edge_from.Y);
    const double length = std::hypot(dx, dy);
    if (length <= 0)
        return false;
    p = {near.point.X + std::llround(dy / length * double(margin_um)),
         near.point.Y - std::llround(dx / length * double(margin_um))};
    return true;
}

void moveOntoLoop(const Path& loop, Point2& p, double max_move2_um2) {
    if (insideLoop(loop, p))
        return;
    NearestOnOutline near;
    nearestOnLoop(loop, p, near);
    if (near.distance2_um2 >= 0 && (max_move2_um2 < 0 || near.distance2_um2 <= max_move2_um2))
        p = near.point;
}

std::vector<std::vector<std::size_t>> spanningTreeNeighbours(const std::vector<Point2>& points) {
    const std::size_t n = points.size();
    std::vector<std::vector<std::size_t>> neighbours(n);
    if (n < 2)
        return neighbours;
    // Prim's algorithm, O(n²): the nearest point outside the tree joins it, one at a time.
    std::vector<double> best(n, std::numeric_limits<double>::infinity());
    std::vector<std::size_t> via(n, 0);
    std::vector<bool> in_tree(n, false);
    std::size_t next = 0;
    for (std::size_t added = 0; added < n; ++added) {
        const std::size_t current = next;
        in_tree[current] = true;
        if (added > 0) {
            neighbours[current].push_back(via[current]);
            neighbours[via[current]].push_back(current);
        }
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < n; ++i) {
            if (in_tree[i])
                continue;
            const double d2 = distance2(points[current], points[i]);
            if (d2 < best[i]) {
                best[i] = d2;
                via[i] = current;
            }
            if (best[i] < nearest) {
                nearest = best[i];
                next = i;
            }
        }
    }
    return neighbours;
}

}  // namespace mixengine
