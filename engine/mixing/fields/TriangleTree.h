#pragma once
// A bounding-box tree over triangles for nearest-triangle queries (feathered paint's distances to one
// painted region, mixing/fields/FeatheredPaint.h): boxes split at the median of the longest axis down to a
// few triangles a leaf, searched nearer child first and skipping every box no nearer than the best so far.
#include <array>
#include <cstdint>
#include <vector>

namespace mixengine {

/// Squared distance from `p` to the box [lo, hi] (0 inside): no triangle inside the box is nearer.
double squaredDistanceToBox(const double p[3], const double lo[3], const double hi[3]);

class TriangleTree {
  public:
    /// One triangle: its corners a, b, c (x, y, z each; any unit, the queries' unit).
    using Corners = std::array<double, 9>;

    explicit TriangleTree(std::vector<Corners> triangles);

    /// The nearest triangle to `p` whose squared distance is below `limit_sq`: (squared distance, index
    /// into the constructor's triangles); (limit_sq, −1) when none is so near.
    std::pair<double, int> nearest(const double p[3], double limit_sq) const;
    const Corners& triangle(int index) const { return triangles_[static_cast<std::size_t>(index)]; }
    bool empty() const { return triangles_.empty(); }

  private:
    struct Node {
        double lo[3], hi[3];
        std::uint32_t first = 0;  ///< leaf: first of order_; inner: the right child (the left is next)
        std::uint32_t count = 0;  ///< leaf: its triangles; 0 for an inner node
    };
    std::vector<Corners> triangles_;
    std::vector<std::array<double, 6>> boxes_;  ///< each triangle's lo x, y, z and hi x, y, z
    std::vector<std::uint32_t> order_;
    std::vector<Node> nodes_;

    std::uint32_t build(std::uint32_t begin, std::uint32_t end);
};

}  // namespace mixengine
