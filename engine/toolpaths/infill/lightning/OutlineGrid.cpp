#include "toolpaths/infill/lightning/OutlineGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/PointQueries.h"

namespace mixengine {
namespace {

/// The sign of the turn a → b → c (exact for coordinates below 2^31 µm).
int turn(Point2 a, Point2 b, Point2 c) {
    const long long cross = (b.X - a.X) * (c.Y - a.Y) - (b.Y - a.Y) * (c.X - a.X);
    return (cross > 0) - (cross < 0);
}

bool boxesOverlap(Point2 a, Point2 b, Point2 c, Point2 d) {
    return std::max(a.X, b.X) >= std::min(c.X, d.X) && std::max(c.X, d.X) >= std::min(a.X, b.X) &&
           std::max(a.Y, b.Y) >= std::min(c.Y, d.Y) && std::max(c.Y, d.Y) >= std::min(a.Y, b.Y);
}

bool segmentsTouch(Point2 a, Point2 b, Point2 c, Point2 d) {
    const int o1 = turn(a, b, c), o2 = turn(a, b, d);
    if (o1 * o2 > 0)
        return false;
    const int o3 = turn(c, d, a), o4 = turn(c, d, b);
    if (o3 * o4 > 0)
        return false;
    if (o1 == 0 && o2 == 0)  // on one line: they touch when their extents overlap
        return boxesOverlap(a, b, c, d);
    return true;
}

/// Where segments a–b and c–d cross (parallel ones do not).
std::optional<Point2> crossing(Point2 a, Point2 b, Point2 c, Point2 d) {
    const double rx = double(b.X - a.X), ry = double(b.Y - a.Y);
    const double sx = double(d.X - c.X), sy = double(d.Y - c.Y);
    const double denominator = rx * sy - ry * sx;
    if (denominator == 0)
        return std::nullopt;
    const double qx = double(c.X - a.X), qy = double(c.Y - a.Y);
    const double t = (qx * sy - qy * sx) / denominator;
    const double u = (qx * ry - qy * rx) / denominator;
    if (t < 0 || t > 1 || u < 0 || u > 1)
        return std::nullopt;
    return Point2{a.X + std::llround(t * rx), a.Y + std::llround(t * ry)};
}

long long floorDiv(coord_um a, coord_um b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

}  // namespace

OutlineGrid::OutlineGrid(const Paths& outlines, coord_um cell_um) : cell_um_(std::max<coord_um>(cell_um, 1)) {
    for (const Path& loop : outlines) {
        for (std::size_t i = 0; i < loop.size() && loop.size() >= 2; ++i)
            edges_.push_back({loop[i], loop[(i + 1) % loop.size()]});
    }
    if (edges_.empty())
        return;
    coord_um x0 = edges_[0].a.X, y0 = edges_[0].a.Y, x1 = x0, y1 = y0;
    for (const Edge& e : edges_) {
        x0 = std::min(x0, e.a.X), y0 = std::min(y0, e.a.Y);
        x1 = std::max(x1, e.a.X), y1 = std::max(y1, e.a.Y);
    }
    origin_ = {x0, y0};
    columns_ = (x1 - x0) / cell_um_ + 1;
    rows_ = (y1 - y0) / cell_um_ + 1;
    cells_.resize(static_cast<std::size_t>(columns_ * rows_));
    for (std::size_t i = 0; i < edges_.size(); ++i) {
        const Edge& e = edges_[i];
        const CellRange r = cellsOf(std::min(e.a.X, e.b.X), std::min(e.a.Y, e.b.Y), std::max(e.a.X, e.b.X),
                                    std::max(e.a.Y, e.b.Y));
        for (long long y = r.y0; y <= r.y1; ++y) {
            for (long long x = r.x0; x <= r.x1; ++x)
                cells_[static_cast<std::size_t>(y * columns_ + x)].push_back(i);
        }
    }
}

long long OutlineGrid::cellX(coord_um x) const {
    return floorDiv(x - origin_.X, cell_um_);
}

long long OutlineGrid::cellY(coord_um y) const {
    return floorDiv(y - origin_.Y, cell_um_);
}

OutlineGrid::CellRange OutlineGrid::cellsOf(coord_um x0, coord_um y0, coord_um x1, coord_um y1) const {
    return {std::clamp(cellX(x0), 0LL, columns_ - 1), std::clamp(cellY(y0), 0LL, rows_ - 1),
            std::clamp(cellX(x1), 0LL, columns_ - 1), std::clamp(cellY(y1), 0LL, rows_ - 1)};
}

const std::vector<std::size_t>& OutlineGrid::cell(long long x, long long y) const {
    return cells_[static_cast<std::size_t>(y * columns_ + x)];
}

template <typename Visit>
void OutlineGrid::forEdges(const CellRange& range, Visit visit) const {
    for (long long y = range.y0; y <= range.y1; ++y) {
        for (long long x = range.x0; x <= range.x1; ++x) {
            for (std::size_t e : cell(x, y))
                visit(edges_[e]);
        }
    }
}

std::optional<Point2> OutlineGrid::nearest(Point2 p) const {
    if (edges_.empty())
        return std::nullopt;
    const long long cx = cellX(p.X), cy = cellY(p.Y);
    const long long reach =
        std::max({std::abs(cx), std::abs(cx - columns_ + 1), std::abs(cy), std::abs(cy - rows_ + 1)});
    double best2 = std::numeric_limits<double>::infinity();
    Point2 best{0, 0};
    const auto visit = [&](long long x, long long y) {
        if (x < 0 || y < 0 || x >= columns_ || y >= rows_)
            return;
        for (std::size_t e : cell(x, y)) {
            const Point2 q = nearestOnSegment(edges_[e].a, edges_[e].b, p);
            const double d2 = distance2(p, q);
            if (d2 < best2)
                best2 = d2, best = q;
        }
    };
    for (long long r = 0; r <= reach; ++r) {
        for (long long x = cx - r; x <= cx + r; ++x) {
            visit(x, cy - r);
            if (r > 0)
                visit(x, cy + r);
        }
        for (long long y = cy - r + 1; y <= cy + r - 1; ++y) {
            visit(cx - r, y);
            visit(cx + r, y);
        }
        // Every cell of the next ring is at least r cells away from p.
        const double ring = double(r) * double(cell_um_);
        if (best2 <= ring * ring)
            break;
    }
    return best;
}

bool OutlineGrid::touches(Point2 a, Point2 b) const {
    if (edges_.empty() || (a.X == b.X && a.Y == b.Y))
        return false;
    bool hit = false;
    forEdges(cellsOf(std::min(a.X, b.X), std::min(a.Y, b.Y), std::max(a.X, b.X), std::max(a.Y, b.Y)),
             [&](const Edge& e) { hit = hit || segmentsTouch(a, b, e.a, e.b); });
    return hit;
}

std::optional<Point2> OutlineGrid::crossingNearEnd(Point2 a, Point2 b, coord_um within_um) const {
    if (edges_.empty())
        return std::nullopt;
    const double limit2 = double(within_um) * double(within_um);
    double best2 = limit2;
    std::optional<Point2> best;
    const CellRange range =
        cellsOf(std::max(std::min(a.X, b.X), b.X - within_um), std::max(std::min(a.Y, b.Y), b.Y - within_um),
                std::min(std::max(a.X, b.X), b.X + within_um), std::min(std::max(a.Y, b.Y), b.Y + within_um));
    forEdges(range, [&](const Edge& e) {
        const std::optional<Point2> c = crossing(a, b, e.a, e.b);
        if (c && distance2(*c, b) < best2)
            best2 = distance2(*c, b), best = c;
    });
    return best;
}

}  // namespace mixengine
