#include "planning/CombBoundary.h"

#include "geometry/Point.h"
#include "geometry/PointQueries.h"

#include <algorithm>
#include <cmath>

namespace mixengine {
namespace {

__extension__ typedef __int128 Wide;

int orientation(const Point2& a, const Point2& b, const Point2& c) {
    const Wide cross = Wide(b.X - a.X) * Wide(c.Y - a.Y) - Wide(b.Y - a.Y) * Wide(c.X - a.X);
    return cross > 0 ? 1 : (cross < 0 ? -1 : 0);
}

/// Whether the bounding boxes of segments p–q and a–b overlap (touching counts).
bool boxesMeet(const Point2& p, const Point2& q, const Point2& a, const Point2& b) {
    return std::max(p.X, q.X) >= std::min(a.X, b.X) && std::max(a.X, b.X) >= std::min(p.X, q.X) &&
           std::max(p.Y, q.Y) >= std::min(a.Y, b.Y) && std::max(a.Y, b.Y) >= std::min(p.Y, q.Y);
}

/// Proper crossing: the segments cross at a point interior to both (touching does not count).
/// Segments whose bounding boxes do not meet are rejected before the orientation tests.
bool properlyCross(const Point2& p, const Point2& q, const Point2& a, const Point2& b) {
    if (!boxesMeet(p, q, a, b))
        return false;
    const int o1 = orientation(p, q, a), o2 = orientation(p, q, b);
    const int o3 = orientation(a, b, p), o4 = orientation(a, b, q);
    return o1 * o2 < 0 && o3 * o4 < 0;
}

/// p lies on the segment a–b (the cheap bounding-box test first).
bool onSegment(const Point2& p, const Point2& a, const Point2& b) {
    return std::min(a.X, b.X) <= p.X && p.X <= std::max(a.X, b.X) && std::min(a.Y, b.Y) <= p.Y &&
           p.Y <= std::max(a.Y, b.Y) && orientation(a, b, p) == 0;
}

/// v, known to lie on the line through p and q, lies on the segment p–q and is neither end.
bool strictlyBetween(const Point2& v, const Point2& p, const Point2& q) {
    return v != p && v != q && std::min(p.X, q.X) <= v.X && v.X <= std::max(p.X, q.X) &&
           std::min(p.Y, q.Y) <= v.Y && v.Y <= std::max(p.Y, q.Y);
}

/// The sign of (X − x), X being where the line through a and b (a.Y ≠ b.Y) meets the height y:
/// X = a.X + (y − a.Y)(b.X − a.X)/(b.Y − a.Y), compared without dividing.
int crossingXComparedTo(const Point2& a, const Point2& b, coord_um y, coord_um x) {
    const Wide dy = Wide(b.Y) - Wide(a.Y);
    const Wide scaled = (Wide(a.X) - Wide(x)) * dy + (Wide(y) - Wide(a.Y)) * (Wide(b.X) - Wide(a.X));
    const int sign = scaled > 0 ? 1 : (scaled < 0 ? -1 : 0);
    return dy > 0 ? sign : -sign;
}

double squaredUm(const Point2& a, const Point2& b) {
    const double dx = double(a.X - b.X), dy = double(a.Y - b.Y);
    return dx * dx + dy * dy;
}

/// The distance between segments p–q and a–b (0 when they cross).
double segmentsDistanceUm(const Point2& p, const Point2& q, const Point2& a, const Point2& b) {
    if (properlyCross(p, q, a, b))
        return 0;
    return std::min({distanceUm(nearestOnSegment(a, b, p), p), distanceUm(nearestOnSegment(a, b, q), q),
                     distanceUm(nearestOnSegment(p, q, a), a), distanceUm(nearestOnSegment(p, q, b), b)});
}

}  // namespace

CombBoundary::CombBoundary(const Paths& area) : loops_(area) {
    coord_um min_x = INT64_MAX, min_y = INT64_MAX, max_x = INT64_MIN, max_y = INT64_MIN;
    for (std::uint32_t l = 0; l < loops_.size(); ++l) {
        const Path& loop = loops_[l];
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Point2& a = loop[i];
            const Point2& b = loop[(i + 1) % loop.size()];
            if (a == b)
                continue;
            edges_.push_back({a, b, l, static_cast<std::uint32_t>(i)});
            min_x = std::min(min_x, a.X), max_x = std::max(max_x, a.X);
            min_y = std::min(min_y, a.Y), max_y = std::max(max_y, a.Y);
        }
    }
    if (edges_.empty())
        return;
    // About one edge per cell on average, cells no smaller than 0.5 mm.
    const double width = double(max_x - min_x) + 1, height = double(max_y - min_y) + 1;
    const double cell = std::max(500.0, std::sqrt(width * height / double(edges_.size())));
    cell_um_ = static_cast<coord_um>(cell);
    origin_ = {min_x, min_y};
    columns_ = static_cast<coord_um>(width / cell) + 1;
    rows_ = static_cast<coord_um>(height / cell) + 1;
    cells_.resize(static_cast<std::size_t>(columns_ * rows_));
    for (std::uint32_t e = 0; e < edges_.size(); ++e) {
        const Edge& edge = edges_[e];
        const coord_um c0 = column(std::min(edge.a.X, edge.b.X)), c1 = column(std::max(edge.a.X, edge.b.X));
        const coord_um r0 = row(std::min(edge.a.Y, edge.b.Y)), r1 = row(std::max(edge.a.Y, edge.b.Y));
        for (coord_um r = r0; r <= r1; ++r)
            for (coord_um c = c0; c <= c1; ++c)
                cells_[cellIndex(c, r)].push_back(e);
    }
    anchors_.assign(cells_.size(), kAnchorOnBoundary);
    for (coord_um r = 0; r < rows_; ++r)
        classifyAnchors(r);
}

Point2 CombBoundary::anchor(coord_um c, coord_um r) const {
    return {origin_.X + c * cell_um_ + cell_um_ / 2, origin_.Y + r * cell_um_ + cell_um_ / 2};
}

void CombBoundary::classifyAnchors(coord_um r) {
    // The ray method for every anchor of the row at once: each crossing of the row's centre line is
    // counted in the cell that holds it (as in insideByRay), against that cell's anchor; a prefix of
    // flips then gives each anchor's parity from the grid's left side.
    const coord_um y = anchor(0, r).Y;
    std::vector<std::uint8_t> flips(static_cast<std::size_t>(columns_) + 1, 0);
    for (coord_um c = 0; c < columns_; ++c) {
        const Point2 at = anchor(c, r);
        const coord_um cell_left = origin_.X + c * cell_um_, cell_right = cell_left + cell_um_;
        bool on_boundary = false;
        for (std::uint32_t e : cells_[cellIndex(c, r)]) {
            const Edge& edge = edges_[e];
            on_boundary = on_boundary || onSegment(at, edge.a, edge.b);
            if ((edge.a.Y > y) == (edge.b.Y > y))
                continue;
            const bool from_left = c == 0 || crossingXComparedTo(edge.a, edge.b, y, cell_left) >= 0;
            const bool to_right = c == columns_ - 1 || crossingXComparedTo(edge.a, edge.b, y, cell_right) < 0;
            if (from_left && to_right)
                flips[static_cast<std::size_t>(
                    crossingXComparedTo(edge.a, edge.b, y, at.X) < 0 ? c : c + 1)] ^= 1;
        }
        anchors_[cellIndex(c, r)] = on_boundary ? kAnchorOnBoundary : 0;
    }
    std::uint8_t odd = 0;
    for (coord_um c = 0; c < columns_; ++c) {
        odd ^= flips[static_cast<std::size_t>(c)];
        std::uint8_t& state = anchors_[cellIndex(c, r)];
        if (state != kAnchorOnBoundary)
            state = odd;
    }
}

coord_um CombBoundary::column(coord_um x) const {
    return std::clamp<coord_um>((x - origin_.X) / cell_um_, 0, columns_ - 1);
}

coord_um CombBoundary::row(coord_um y) const {
    return std::clamp<coord_um>((y - origin_.Y) / cell_um_, 0, rows_ - 1);
}

template <typename Visit>
bool CombBoundary::forCellsAlong(const Point2& a, const Point2& b, Visit visit) const {
    const coord_um y_min = std::min(a.Y, b.Y), y_max = std::max(a.Y, b.Y);
    const double slope = a.Y == b.Y ? 0.0 : double(b.X - a.X) / double(b.Y - a.Y);
    auto xAt = [&](coord_um y) { return double(a.X) + double(y - a.Y) * slope; };
    for (coord_um r = row(y_min); r <= row(y_max); ++r) {
        const coord_um band_low = std::max(y_min, origin_.Y + r * cell_um_);
        const coord_um band_high = std::min(y_max, origin_.Y + (r + 1) * cell_um_);
        if (band_low > band_high)
            continue;  // the segment passes beside the grid
        double x_low = a.Y == b.Y ? double(std::min(a.X, b.X)) : xAt(band_low);
        double x_high = a.Y == b.Y ? double(std::max(a.X, b.X)) : xAt(band_high);
        if (x_low > x_high)
            std::swap(x_low, x_high);
        // A micron either side: the cells are a superset of those the segment meets.
        const coord_um c_low = column(static_cast<coord_um>(std::floor(x_low)) - 1);
        const coord_um c_high = column(static_cast<coord_um>(std::ceil(x_high)) + 1);
        for (coord_um c = c_low; c <= c_high; ++c) {
            if (!visit(cells_[cellIndex(c, r)]))
                return false;
        }
    }
    return true;
}

bool CombBoundary::inside(const Point2& p) const {
    if (edges_.empty() || p.Y < origin_.Y || p.Y >= origin_.Y + rows_ * cell_um_ || p.X < origin_.X ||
        p.X >= origin_.X + columns_ * cell_um_)
        return false;
    const coord_um r = row(p.Y), c = column(p.X);
    const std::uint8_t state = anchors_[cellIndex(c, r)];
    if (state == kAnchorOnBoundary)
        return insideByRay(p, r, c);
    // From the cell's anchor to p: every edge the segment meets is in the cell; the parity of its
    // proper crossings is the change of inside (unless it touches a vertex: then the ray decides).
    const Point2 from = anchor(c, r);
    bool odd = state != 0;
    for (std::uint32_t e : cells_[cellIndex(c, r)]) {
        const Edge& edge = edges_[e];
        if (onSegment(p, edge.a, edge.b))
            return true;
        if (!boxesMeet(from, p, edge.a, edge.b))
            continue;
        const int o1 = orientation(from, p, edge.a), o2 = orientation(from, p, edge.b);
        if ((o1 == 0 && onSegment(edge.a, from, p)) || (o2 == 0 && onSegment(edge.b, from, p)))
            return insideByRay(p, r, c);
        if (o1 * o2 < 0 && orientation(edge.a, edge.b, from) * orientation(edge.a, edge.b, p) < 0)
            odd = !odd;
    }
    return odd;
}

bool CombBoundary::insideByRay(const Point2& p, coord_um r, coord_um first) const {
    // The ray runs to the nearer side of the grid, +X or −X: p is inside exactly when either one
    // crosses the boundary an odd number of times (p itself lies on no edge: that returns first).
    const bool rightwards = columns_ - first <= first + 1;
    const coord_um step = rightwards ? 1 : -1, end = rightwards ? columns_ : -1;
    const coord_um leftmost = rightwards ? first : 0, rightmost = rightwards ? columns_ - 1 : first;
    bool odd = false;
    for (coord_um c = first; c != end; c += step) {
        const coord_um cell_left = origin_.X + c * cell_um_;
        const coord_um cell_right = cell_left + cell_um_;
        for (std::uint32_t e : cells_[cellIndex(c, r)]) {
            const Edge& edge = edges_[e];
            if (p.Y < std::min(edge.a.Y, edge.b.Y) || p.Y > std::max(edge.a.Y, edge.b.Y))
                continue;  // neither holds p nor meets the ray
            if (onSegment(p, edge.a, edge.b))
                return true;
            // Half-open rule on Y so a vertex on the ray counts once.
            if ((edge.a.Y > p.Y) == (edge.b.Y > p.Y))
                continue;
            const int side = crossingXComparedTo(edge.a, edge.b, p.Y, p.X);
            if (rightwards ? side < 0 : side > 0)
                continue;  // the edge meets the ray's line on p's other side
            // Count the crossing only in the cell that holds it (edges span several cells); the
            // walk's end cells are open towards p and towards the grid's side.
            const bool from_left = c == leftmost || crossingXComparedTo(edge.a, edge.b, p.Y, cell_left) >= 0;
            const bool to_right = c == rightmost || crossingXComparedTo(edge.a, edge.b, p.Y, cell_right) < 0;
            if (from_left && to_right)
                odd = !odd;
        }
    }
    return odd;
}

bool CombBoundary::crossesEdge(const Point2& p, const Point2& q, const Edge& edge) const {
    if (!boxesMeet(p, q, edge.a, edge.b))
        return false;  // neither a crossing nor a vertex on the travel
    const int side_a = orientation(p, q, edge.a);
    if (side_a == 0)
        return crossesAtVertex(p, q, edge);
    // Through edge.b: that is the next edge's first vertex, counted there.
    if (side_a * orientation(p, q, edge.b) >= 0)
        return false;
    return orientation(edge.a, edge.b, p) * orientation(edge.a, edge.b, q) < 0;
}

bool CombBoundary::crossesAtVertex(const Point2& p, const Point2& q, const Edge& edge) const {
    if (!strictlyBetween(edge.a, p, q))
        return false;
    const Path& loop = loops_[edge.loop];
    const std::size_t n = loop.size();
    // The side the loop comes from: its last vertex before edge.a off the travel's line (the same
    // point repeated skipped); on the line, edge.a is not where its run along the line starts.
    std::size_t k = edge.index;
    for (std::size_t guard = 0; guard < n && loop[k] == edge.a; ++guard)
        k = (k + n - 1) % n;
    const int before = orientation(p, q, loop[k]);
    if (before == 0)
        return false;
    // The side it leaves to: its first vertex after the run along the line; a run reaching an end
    // of the travel or beyond it only touches (the travel ends on the boundary).
    k = edge.index;
    for (std::size_t guard = 0; guard < n; ++guard) {
        k = (k + 1) % n;
        const int after = orientation(p, q, loop[k]);
        if (after != 0)
            return after != before;
        if (loop[k] != edge.a && !strictlyBetween(loop[k], p, q))
            return false;
    }
    return false;
}

bool CombBoundary::straightInside(const Point2& a, const Point2& b) const {
    return inside(a) && inside(b) && straightBetweenInside(a, b);
}

bool CombBoundary::crossesBoundary(const Point2& a, const Point2& b) const {
    if (edges_.empty())
        return false;
    return !forCellsAlong(a, b, [&](const std::vector<std::uint32_t>& cell) {
        for (std::uint32_t e : cell) {
            if (crossesEdge(a, b, edges_[e]))
                return false;
        }
        return true;
    });
}

bool CombBoundary::straightBetweenInside(const Point2& a, const Point2& b) const {
    // The midpoint catches chords between two boundary points that run outside without a
    // proper crossing (e.g. corner to edge across a hole).
    const Point2 middle{a.X + (b.X - a.X) / 2, a.Y + (b.Y - a.Y) / 2};
    return inside(middle) && !crossesBoundary(a, b);
}

std::vector<CombBoundary::Crossing> CombBoundary::crossings(const Point2& a, const Point2& b) const {
    std::vector<Crossing> found;
    std::vector<std::uint32_t> seen;
    forCellsAlong(a, b, [&](const std::vector<std::uint32_t>& cell) {
        for (std::uint32_t e : cell) {
            const Edge& edge = edges_[e];
            if (!crossesEdge(a, b, edge) || std::find(seen.begin(), seen.end(), e) != seen.end())
                continue;
            seen.push_back(e);
            const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
            if (orientation(a, b, edge.a) == 0) {  // through the edge's first vertex: there exactly
                const double t =
                    (double(edge.a.X - a.X) * dx + double(edge.a.Y - a.Y) * dy) / (dx * dx + dy * dy);
                found.push_back({t, edge.a, &edge});
                continue;
            }
            const double ex = double(edge.b.X - edge.a.X), ey = double(edge.b.Y - edge.a.Y);
            const double denominator = dx * ey - dy * ex;
            const double t = (double(edge.a.X - a.X) * ey - double(edge.a.Y - a.Y) * ex) / denominator;
            const Point2 at{a.X + static_cast<coord_um>(std::llround(t * dx)),
                            a.Y + static_cast<coord_um>(std::llround(t * dy))};
            found.push_back({t, at, &edge});
        }
        return true;
    });
    std::sort(found.begin(), found.end(), [](const Crossing& x, const Crossing& y) { return x.t < y.t; });
    return found;
}

Path CombBoundary::aroundLoop(const Crossing& from, const Crossing& to) const {
    const Path& loop = loops_[from.edge->loop];
    const std::size_t n = loop.size();
    // Edge i runs from loop[i] to loop[i + 1]; the two crossings lie on different edges i and j
    // (a straight line crosses an edge once). Forward: loop[i+1] … loop[j]; backward: loop[i] …
    // loop[j+1].
    const std::size_t i = from.edge->index, j = to.edge->index;
    auto walk = [&](bool forward) {
        Path points{from.at};
        std::size_t k = forward ? (i + 1) % n : i;
        const std::size_t last = forward ? j : (j + 1) % n;
        points.push_back(loop[k]);
        for (std::size_t guard = 0; k != last && guard < n; ++guard) {
            k = forward ? (k + 1) % n : (k + n - 1) % n;
            points.push_back(loop[k]);
        }
        points.push_back(to.at);
        return points;
    };
    auto length = [](const Path& p) {
        double sum = 0;
        for (std::size_t m = 1; m < p.size(); ++m)
            sum += distanceUm(p[m], p[m - 1]);
        return sum;
    };
    Path forward = walk(true), backward = walk(false);
    return length(forward) <= length(backward) ? forward : backward;
}

Path CombBoundary::shortened(const Point2& start, const Path& points) const {
    constexpr std::size_t kLookAhead = 48;
    std::vector<bool> point_inside(points.size());  // each point's test once, not once per shortcut tried
    for (std::size_t k = 0; k < points.size(); ++k)
        point_inside[k] = inside(points[k]);
    Path result;
    Point2 current = start;
    bool current_inside = inside(start);
    std::size_t i = 0;
    while (i < points.size()) {
        std::size_t best = i;
        const std::size_t last = std::min(points.size() - 1, i + kLookAhead);
        for (std::size_t j = last; j > i && current_inside; --j) {
            if (point_inside[j] && straightBetweenInside(current, points[j])) {
                best = j;
                break;
            }
        }
        current = points[best];
        current_inside = point_inside[best];
        result.push_back(current);
        i = best + 1;
    }
    return result;
}

std::optional<Path> CombBoundary::route(const Point2& a, const Point2& b) const {
    if (!inside(a) || !inside(b))
        return std::nullopt;
    const std::vector<Crossing> found = crossings(a, b);
    if (found.empty())
        return Path{b};
    if (found.size() % 2 != 0)
        return std::nullopt;
    Path points;
    for (std::size_t k = 0; k + 1 < found.size(); k += 2) {
        if (found[k].edge->loop != found[k + 1].edge->loop)
            return std::nullopt;  // leaves through one loop and comes back through another: other island
        const Path around = aroundLoop(found[k], found[k + 1]);
        points.insert(points.end(), around.begin(), around.end());
    }
    points.push_back(b);
    return shortened(a, points);
}

std::optional<Point2> CombBoundary::entryToward(const Point2& from, const Point2& toward,
                                                coord_um nudge_um) const {
    if (edges_.empty())
        return std::nullopt;
    const std::vector<Crossing> found = crossings(from, toward);
    const double dx = double(toward.X - from.X), dy = double(toward.Y - from.Y);
    const double length = std::hypot(dx, dy);
    if (found.empty() || length <= 0)
        return std::nullopt;
    const Point2& at = found.front().at;
    const Point2 nudged{at.X + static_cast<coord_um>(std::llround(dx / length * double(nudge_um))),
                        at.Y + static_cast<coord_um>(std::llround(dy / length * double(nudge_um)))};
    if (!inside(nudged))
        return std::nullopt;
    return nudged;
}

std::optional<Point2> CombBoundary::moveInside(const Point2& p, coord_um max_distance_um,
                                               coord_um nudge_um) const {
    if (inside(p))
        return p;
    if (edges_.empty())
        return std::nullopt;
    const coord_um c0 = column(p.X - max_distance_um), c1 = column(p.X + max_distance_um);
    const coord_um r0 = row(p.Y - max_distance_um), r1 = row(p.Y + max_distance_um);
    double best = double(max_distance_um);
    std::optional<Point2> nearest;
    for (coord_um r = r0; r <= r1; ++r) {
        for (coord_um c = c0; c <= c1; ++c) {
            for (std::uint32_t e : cells_[cellIndex(c, r)]) {
                const Point2 q = nearestOnSegment(edges_[e].a, edges_[e].b, p);
                const double d = distanceUm(q, p);
                if (d <= best)
                    best = d, nearest = q;
            }
        }
    }
    if (!nearest || best <= 0)
        return std::nullopt;
    // Where the area is thinner than the nudge (a narrow tip), a smaller nudge, down to none.
    for (coord_um nudge = nudge_um; nudge >= 0; nudge = nudge > 1 ? nudge / 2 : nudge - 1) {
        const double k = double(nudge) / best;
        const Point2 moved{nearest->X + static_cast<coord_um>(std::llround(double(nearest->X - p.X) * k)),
                           nearest->Y + static_cast<coord_um>(std::llround(double(nearest->Y - p.Y) * k))};
        if (inside(moved))
            return moved;
    }
    return std::nullopt;
}

std::vector<Point2> CombBoundary::exitsToward(const Point2& from, const Point2& close_to, coord_um reach_um,
                                              coord_um nudge_um) const {
    std::vector<std::pair<double, Point2>> scored;
    std::vector<std::uint32_t> seen;
    forCellsAlong(from, close_to, [&](const std::vector<std::uint32_t>& cell) {
        for (std::uint32_t e : cell) {
            const Edge& edge = edges_[e];
            if (std::find(seen.begin(), seen.end(), e) != seen.end())
                continue;
            seen.push_back(e);
            if (segmentsDistanceUm(from, close_to, edge.a, edge.b) > double(reach_um))
                continue;
            const Point2 on = nearestOnSegment(edge.a, edge.b, close_to);
            const double length = distanceUm(edge.a, edge.b);
            const coord_um nx =
                static_cast<coord_um>(std::llround(-double(edge.b.Y - edge.a.Y) / length * nudge_um));
            const coord_um ny =
                static_cast<coord_um>(std::llround(double(edge.b.X - edge.a.X) / length * nudge_um));
            const Point2 left{on.X + nx, on.Y + ny}, right{on.X - nx, on.Y - ny};
            const std::optional<Point2> inner =
                inside(left) ? std::optional<Point2>(left)
                             : (inside(right) ? std::optional<Point2>(right) : std::nullopt);
            if (inner)
                scored.emplace_back(squaredUm(on, close_to) + squaredUm(on, from) / 10, *inner);
        }
        return true;
    });
    std::sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<Point2> points;
    for (const auto& [score, point] : scored)
        points.push_back(point);
    return points;
}

}  // namespace mixengine
