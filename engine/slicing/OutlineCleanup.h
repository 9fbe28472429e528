#pragma once
// What CuraEngine does to outlines between slicing and toolpaths:
//   - loops shorter than minimum_polygon_circumference are dropped;
//   - every loop is simplified as CuraEngine 4.13's slicer does, with a fixed 10 µm resolution and 5 µm
//     deviation (slicing/SlicingParams.h); meshfix_maximum_resolution / _deviation act on each wall
//     (toolpaths/walls/Walls.h), as in CuraEngine, not on the outline (a small hole or pin keeps its
//     shape, so a hole grown by hole_xy_offset leaves the band CuraEngine leaves).
// simplifyLoop follows CuraEngine 4.13's simplification: walking the loop, a vertex goes when the
// segment to it from the last kept vertex is under 5 µm, when it is collinear with its neighbours
// (within 1 µm), or when that segment is shorter than the resolution and the area cut off by going
// straight from the last kept vertex to the next one, as a triangle on that shortcut, is no higher
// than the deviation. When the segment after such a vertex is long, the vertex is kept but moved
// to where the lines before and after it meet (if that point stays within the resolution and the
// deviation), and the vertex before it goes. A loop of three vertices stays as it is; loops left
// with fewer than three go. Resolution and deviation both 0 in OutlineCleanupParams: no
// simplification at all (the raw slices, as `mixengine layers` shows them).
// removeHoles fills every hole (meshfix_union_all_remove_holes).
#include <vector>

#include "geometry/Point.h"
#include "slicing/Slicer.h"

namespace mixengine {

struct OutlineCleanupParams {
    coord_um minimum_circumference_um = 1000;
    coord_um maximum_resolution_um = 250;
    coord_um maximum_deviation_um = 25;
};

/// One closed loop, simplified as described above (fewer than three vertices: none left).
Path simplifyLoop(const Path& loop, coord_um maximum_resolution_um, coord_um maximum_deviation_um);

/// Whether the closed loop is shorter than `length_um`, its sides' lengths rounded down to whole
/// microns before they are summed (CuraEngine 4.13's test for minimum_polygon_circumference).
bool loopShorterThan(const Path& loop, coord_um length_um);

/// Every outline of every layer (in parallel over layers).
void cleanOutlines(std::vector<SlicedLayer>& layers, const OutlineCleanupParams& params, int threads);

double loopLengthUm(const Path& loop);

/// meshfix_union_all_remove_holes: every layer's holes filled (the outer contours united), as
/// CuraEngine 4.13 unites all loops turned the same way round.
void removeHoles(std::vector<SlicedLayer>& layers, int threads);

}  // namespace mixengine
