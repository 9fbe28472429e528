#pragma once
// One cross fractal for all layers of a mesh (or of the support), computed once before the layers'
// toolpaths, as CuraEngine 4.13's SierpinskiFillProvider:
//   square — centred on the middle of the model's bounding box (x, y), side line_distance·2^k for
//            the least k that reaches the box's longer side, times √2/2 (one level less) when
//            that still reaches it; the depth is 2k (2k − 1 with the √2/2);
//   density — line_width / line_distance everywhere, or the density image's (DensityAt);
//   curve   — cross or cross_3d (toolpaths/infill/cross/CrossCurve.h) through the triangles that
//             toolpaths/infill/cross/SierpinskiSequence.h chooses; cross_3d keeps half the
//             layer's line width from the edges' ends.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/infill/cross/SierpinskiTree.h"

namespace mixengine {

struct CrossSquare {
    Box2 square;    ///< its corners (left, top) and (right, bottom)
    int depth = 0;  ///< the tree's depth
};

/// The fractal's square and depth for a model whose bounding box (x, y) is `model_box`.
CrossSquare crossSquare(const Box2& model_box, coord_um line_distance_um);

class CrossFill {
  public:
    /// `line_distance_um` > 0 and `line_width_um` > 0 (the pattern's settings); without `density`,
    /// uniform line_width / line_distance.
    CrossFill(const Box2& model_box, coord_um line_distance_um, coord_um line_width_um,
              const DensityAt& density = nullptr);

    /// The closed curve (first vertex not repeated) at height `z_um`: cross_3d when `three_d`,
    /// with pockets of `pocket_um` (≤ 10: none); `line_width_um` the layer's line width.
    Path curve(bool three_d, coord_um z_um, coord_um line_width_um, coord_um pocket_um) const;

  private:
    SierpinskiTree tree_;
    std::vector<int> sequence_;
};

}  // namespace mixengine
