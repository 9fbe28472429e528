#pragma once
// The closed curves of the cross patterns through a sequence of triangles
// (toolpaths/infill/cross/SierpinskiSequence.h), as CuraEngine 4.13's SierpinskiFill draws them:
//   cross    — one vertex per triangle: the middle of the edge the curve leaves it by (its side AB
//              when crossed from AC to AB, else its side BC);
//   cross_3d — one vertex per triangle on the edge it is entered by (and one on the last triangle's
//              exit edge), at the part z mod 2p folded back into 0..p (p = the triangle's short
//              side, so the lines lean at most 45° layer over layer) of the edge's length from its
//              end left of the curve, kept min_side_um from either end; where the curve turns by
//              a right angle (within min_side_um of rounding), with pocket_um > 10 the corner is
//              cut by min(pocket_um·√2/2, a third of either side) along both sides, so that the
//              pockets between layers stay pocket_um wide.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/infill/cross/SierpinskiTree.h"

namespace mixengine {

/// cross: the curve's vertices (empty when the sequence is the root alone).
Path crossCurve(const SierpinskiTree& tree, const std::vector<int>& sequence);

struct Cross3dParams {
    coord_um z_um = 0;
    coord_um min_side_um = 0;  ///< the least distance from an edge's end (half the line width)
    coord_um pocket_um = 0;    ///< cross_infill_pocket_size (≤ 10: no pockets)
};

/// cross_3d: the curve's vertices at height z (empty when the sequence is the root alone).
Path cross3dCurve(const SierpinskiTree& tree, const std::vector<int>& sequence, const Cross3dParams& params);

}  // namespace mixengine
