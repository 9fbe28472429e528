#pragma once
// What CuraEngine 4.13's slicer does to a layer's loops (prints run it on every stitched loop before
// the loops are combined, slicing/PlaneCutter.h with SliceOptions):
//   - loops shorter than minimum_polygon_circumference are dropped (loopShorterThan);
//   - every loop is simplified with a fixed 10 µm resolution and 5 µm deviation
//     (slicing/SlicingParams.h); meshfix_maximum_resolution / _deviation act on each wall
//     (toolpaths/walls/Walls.h), as in CuraEngine, not on the outline.
// simplifyLoop follows CuraEngine 4.13's simplification rule, in its 64-bit integer arithmetic
// (truncating divisions): walking the loop, a vertex goes when the segment to it from the last kept
// vertex is under 5 µm, when it is collinear with its neighbours (the area cut off, as the squared
// height of a triangle on the shortcut, at most 1, and its distance from the shortcut under 2 µm),
// or when that segment is shorter than the resolution and that height is no more than the
// deviation. When the segment after such a vertex is long, the vertex is kept but moved to where the
// lines before and after it meet as CuraEngine computes that point (if it stays within the resolution
// and the deviation), and the vertex before it goes. A loop of three vertices stays as it is; loops
// left with fewer than three go. Resolution and deviation both 0: no simplification at all (the raw
// slices, as `mixengine layers` shows them).
// removeHoles fills every hole (meshfix_union_all_remove_holes).
#include <vector>

#include "geometry/Point.h"
#include "slicing/Slicer.h"

namespace mixengine {

/// One closed loop, simplified as described above (fewer than three vertices: none left).
Path simplifyLoop(const Path& loop, coord_um maximum_resolution_um, coord_um maximum_deviation_um);

/// Every loop of `loops` simplified (simplifyLoop); loops left with fewer than three vertices go.
/// Both limits 0 or less: `loops` as given.
Paths simplifyLoops(Paths loops, coord_um maximum_resolution_um, coord_um maximum_deviation_um);

/// Whether the closed loop is shorter than `length_um`, its sides' lengths rounded down to whole
/// microns before they are summed (CuraEngine 4.13's test for minimum_polygon_circumference).
bool loopShorterThan(const Path& loop, coord_um length_um);

/// meshfix_union_all_remove_holes: every layer's holes filled (the outer contours united), as
/// CuraEngine 4.13 unites all loops turned the same way round.
void removeHoles(std::vector<SlicedLayer>& layers, int threads);

}  // namespace mixengine
