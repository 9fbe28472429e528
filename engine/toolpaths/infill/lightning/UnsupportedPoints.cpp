#include "toolpaths/infill/lightning/UnsupportedPoints.h"

#include <algorithm>
#include <cmath>

#include "geometry/PointQueries.h"
#include "toolpaths/infill/LineInfill.h"

namespace mixengine {
namespace {

constexpr coord_um kCellsPerRadius = 6;

coord_um cellOf(coord_um radius_um) {
    return std::max<coord_um>(radius_um / kCellsPerRadius, 1);
}

long long floorDiv(coord_um a, coord_um b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/// A fixed scramble of a lattice point (splitmix64's finaliser).
std::uint64_t scramble(Point2 p) {
    std::uint64_t z =
        static_cast<std::uint64_t>(p.X) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(p.Y);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

}  // namespace

std::vector<UnsupportedPoint> overhangPoints(const Paths& overhang, const OutlineGrid& outline,
                                             coord_um radius_um) {
    std::vector<UnsupportedPoint> points;
    if (overhang.empty() || outline.empty())
        return points;
    const coord_um cell = cellOf(radius_um);
    // The lattice's columns cut by the overhang: vertical pieces at x = k·cell.
    for (const Path& piece : lineSegments(overhang, cell, 0.0, 0)) {
        const coord_um x = piece.front().X;
        const coord_um y0 = std::min(piece.front().Y, piece.back().Y),
                       y1 = std::max(piece.front().Y, piece.back().Y);
        for (coord_um y = floorDiv(y0 + cell - 1, cell) * cell; y < y1; y += cell) {
            const Point2 p{x, y};
            const Point2 q = *outline.nearest(p);
            points.push_back({p, static_cast<coord_um>(std::sqrt(distance2(p, q)))});
        }
    }
    std::sort(points.begin(), points.end(),
              [radius_um](const UnsupportedPoint& a, const UnsupportedPoint& b) {
                  const coord_um band_a = a.to_outline_um / std::max<coord_um>(radius_um, 1);
                  const coord_um band_b = b.to_outline_um / std::max<coord_um>(radius_um, 1);
                  if (band_a != band_b)
                      return band_a < band_b;
                  const std::uint64_t ha = scramble(a.p), hb = scramble(b.p);
                  if (ha != hb)
                      return ha < hb;
                  return a.p.X != b.p.X ? a.p.X < b.p.X : a.p.Y < b.p.Y;
              });
    return points;
}

UnsupportedPoints::UnsupportedPoints(std::vector<UnsupportedPoint> points, coord_um radius_um)
    : points_(std::move(points)),
      held_(points_.size(), false),
      radius_um_(radius_um),
      cell_um_(cellOf(radius_um)) {
    by_cell_.reserve(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i)
        by_cell_.emplace(key(floorDiv(points_[i].p.X, cell_um_), floorDiv(points_[i].p.Y, cell_um_)), i);
}

bool UnsupportedPoints::next(Point2& p) {
    while (first_ < points_.size() && held_[first_])
        ++first_;
    if (first_ >= points_.size())
        return false;
    p = points_[first_].p;
    return true;
}

void UnsupportedPoints::holdAround(Point2 leaf) {
    const double radius2 = double(radius_um_) * double(radius_um_);
    const long long x0 = floorDiv(leaf.X - radius_um_, cell_um_),
                    x1 = floorDiv(leaf.X + radius_um_, cell_um_);
    const long long y0 = floorDiv(leaf.Y - radius_um_, cell_um_),
                    y1 = floorDiv(leaf.Y + radius_um_, cell_um_);
    for (long long x = x0; x <= x1; ++x) {
        for (long long y = y0; y <= y1; ++y) {
            const auto found = by_cell_.find(key(x, y));
            if (found != by_cell_.end() && distance2(points_[found->second].p, leaf) < radius2)
                held_[found->second] = true;
        }
    }
}

}  // namespace mixengine
