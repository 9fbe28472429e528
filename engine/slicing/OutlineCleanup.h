#pragma once
// What CuraEngine does to outlines between slicing and toolpaths, with the same setting keys:
//   - loops shorter than minimum_polygon_circumference are dropped;
//   - vertices are removed where the outline is finer than the printer can follow:
//     a vertex goes when the segment to it from the last kept vertex is shorter than
//     meshfix_maximum_resolution and every vertex dropped since then lies within
//     meshfix_maximum_deviation of the new, straighter segment. Collinear vertices (within 5 µm)
//     go regardless of length. A loop keeps at least three vertices. Resolution and deviation
//     both 0: no simplification at all (the raw slices, as `mixengine layers` shows them).
// The result never moves the outline by more than the deviation; the layer count is unchanged.
// removeHoles fills every hole (meshfix_union_all_remove_holes).
#include <vector>

#include "geometry/Point.h"
#include "slicing/Slicer.h"

namespace mixengine {

struct OutlineCleanupParams {
    coord_um minimum_circumference_um = 1000;
    coord_um maximum_resolution_um = 500;
    coord_um maximum_deviation_um = 25;
};

/// One closed loop, simplified as described above.
Path simplifyLoop(const Path& loop, coord_um maximum_resolution_um, coord_um maximum_deviation_um);

/// Every outline of every layer (in parallel over layers).
void cleanOutlines(std::vector<SlicedLayer>& layers, const OutlineCleanupParams& params, int threads);

double loopLengthUm(const Path& loop);

/// meshfix_union_all_remove_holes: every layer's holes filled (the outer contours united), as
/// CuraEngine 4.13 unites all loops turned the same way round.
void removeHoles(std::vector<SlicedLayer>& layers, int threads);

}  // namespace mixengine
