#pragma once
// The points of a layer's overhang that no lightning branch holds up yet, as CuraEngine 4.13's
// LightningDistanceField keeps them: a square lattice of points (x and y multiples of the cell,
// radius / 6) inside the overhang, taken nearest-to-the-outline first — in bands one radius
// wide, in a fixed scrambled order within a band — and dropped once a new branch ends within the
// radius of them. Lengths in microns; the order depends on nothing but the input.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/infill/lightning/OutlineGrid.h"

namespace mixengine {

struct UnsupportedPoint {
    Point2 p{0, 0};
    coord_um to_outline_um = 0;
};

/// The lattice points inside `overhang` with their distance to `outline`, in the order above.
std::vector<UnsupportedPoint> overhangPoints(const Paths& overhang, const OutlineGrid& outline,
                                             coord_um radius_um);

class UnsupportedPoints {
  public:
    /// `points`: as overhangPoints gives them, for the same radius.
    UnsupportedPoints(std::vector<UnsupportedPoint> points, coord_um radius_um);

    /// The next point to hold up; false when all are held.
    bool next(Point2& p);

    /// Drops the points less than the radius from `leaf`.
    void holdAround(Point2 leaf);

  private:
    static std::int64_t key(long long x, long long y) { return (x << 32) ^ (y & 0xffffffffLL); }

    std::vector<UnsupportedPoint> points_;
    std::vector<bool> held_;
    std::unordered_map<std::int64_t, std::size_t> by_cell_;  ///< lattice cell → index in points_
    std::size_t first_ = 0;                                  ///< no point before it is unheld
    coord_um radius_um_;
    coord_um cell_um_;
};

}  // namespace mixengine
