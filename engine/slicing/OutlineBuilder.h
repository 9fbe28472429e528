#pragma once
// Turns the closed loops of one cut into its outlines: the union of all shells, holes by nesting.
//
// Contract (independent of facet winding except for one case, see below):
//   - loops with |area| ≤ min_area_um2 are dropped (zero-area loops always, e.g. the sliver a
//     plane through a ridge edge leaves);
//   - nesting: loops are sorted by |area|, each loop's parent is the smallest larger loop that
//     contains it (bounding box, then point-in-polygon on a vertex not on the parent's boundary);
//   - a loop without a parent is solid, whatever its orientation (an inverted mesh still slices);
//   - a loop whose parent is solid is a hole — unless at least two thirds of its length follows
//     the facet direction and that direction says "solid" (an outward-facing shell nested in
//     another: overlapping bodies are united, as Cura's "union overlapping volumes" and
//     PrusaSlicer do). A cavity wound inwards, or with mixed winding, stays a hole;
//   - a loop whose parent is a hole is solid (an island in a cavity);
//   - loops are then oriented (solid counter-clockwise, holes clockwise) and united with Clipper's
//     "positive" fill rule, so overlapping solids merge and holes subtract only where no other
//     solid covers them. The result has outer contours counter-clockwise, holes clockwise, and no
//     collinear vertices.
// Cost: O(n²) bounding-box tests for n loops plus a point-in-polygon test for each nested pair.
#include <vector>

#include "geometry/Point.h"
#include "slicing/SegmentStitcher.h"

namespace mixengine {

Paths buildOutlines(const std::vector<StitchedPath>& loops, double min_area_um2);

/// meshfix_union_all off (CuraEngine 4.13's even-odd parts): every loop toggles inside and outside,
/// whatever its winding, so where two shells of one mesh overlap there is a hole. Loops with |area| ≤
/// min_area_um2 are dropped. Outer contours counter-clockwise, holes clockwise.
Paths evenOddOutlines(const std::vector<StitchedPath>& loops, double min_area_um2);

}  // namespace mixengine
