#pragma once
// The tree of every triangle the cross fractal (CuraEngine 4.13's SierpinskiFill) may cross, over a
// square: the root's two children are the square's halves along its diagonal, each triangle's two
// children are its halves split at the middle of its long side AB, down to `max_depth`. C is a
// triangle's right-angled corner; the curve enters at A's side and leaves at B's side, crossing two
// of its edges in one of three orders (CrossDirection).
//
// Every node carries, in millimetres (as floats, as CuraEngine keeps them):
//   realized_mm       — the curve's length through it: half the long side AB for AC→BC, else half
//                       a short side;
//   requested_mm      — for a leaf density × area / line width (density from the caller, asked for
//                       the triangle's bounding box), for a parent the sum of its children's;
//   child_realized_mm — the sum of its children's realized_mm;
//   error_left/_right — what the sequence (toolpaths/infill/cross/SierpinskiSequence.h) moved to and
//                       from its neighbours (0 here).
#include <functional>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

/// The two edges of a triangle the curve crosses, in its order.
enum class CrossDirection { AcToAb, AcToBc, AbToBc };

struct SierpinskiNode {
    Point2 c, a, b;  ///< C the right-angled corner; A nearer the curve's start, B nearer its end
    CrossDirection direction = CrossDirection::AcToAb;
    bool c_is_left = false;  ///< C lies left of the curve (the triangle ABC is counter-clockwise)
    int depth = 0;           ///< the root is 0
    int first_child = -1;    ///< index of the first of its two children (the second follows); −1: a leaf
    float area_mm2 = 0;
    float realized_mm = 0;
    float requested_mm = 0;
    float child_realized_mm = 0;
    float error_left = 0;
    float error_right = 0;

    bool leaf() const { return first_child < 0; }
    float totalError() const { return error_left + error_right; }
    float erroredValue() const { return requested_mm + totalError(); }
    /// What is left of the errored value after subdividing.
    float subdivisionError() const { return erroredValue() - child_realized_mm; }
    /// What is left of the errored value as it is.
    float valueError() const { return erroredValue() - realized_mm; }
};

/// A fraction of the area to fill (0..1) for a box in microns.
using DensityAt = std::function<float(const Box2&)>;

/// A node's edge as the curve crosses it: `left` and `right` of the curve.
struct CrossEdge {
    Point2 left, right;
};

/// The edge the curve enters `node` by, and the one it leaves by.
CrossEdge entryEdge(const SierpinskiNode& node);
CrossEdge exitEdge(const SierpinskiNode& node);

class SierpinskiTree {
  public:
    /// The tree over the square `square` (its corners min and max) down to `max_depth` (≥ 0; 0 is
    /// the root alone), the leaves' requested lengths from `density` and `line_width_um` (> 0).
    SierpinskiTree(const Box2& square, int max_depth, coord_um line_width_um, const DensityAt& density);

    int maxDepth() const { return max_depth_; }
    const SierpinskiNode& node(int index) const { return nodes_[static_cast<std::size_t>(index)]; }
    SierpinskiNode& node(int index) { return nodes_[static_cast<std::size_t>(index)]; }
    static constexpr int kRoot = 0;

  private:
    void split(int index);
    void fillRequested(int index, coord_um line_width_um, const DensityAt& density);

    int max_depth_;
    std::vector<SierpinskiNode> nodes_;
};

}  // namespace mixengine
