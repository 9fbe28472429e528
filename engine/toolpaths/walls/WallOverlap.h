#pragma once
// Overlap compensation of walls (travel_compensate_overlapping_walls_0_enabled / _x_enabled), with
// the rule of CuraEngine 4.13's wall overlap computation:
//   - the walls of one set (the outer walls of a layer) are taken in print order, each loop from
//     its first point; a line piece that runs closer than `width_um` to a piece of the set printed
//     before it (not its own neighbours, nor a line running the same way: the next lines of one
//     curve) is printed with less flow;
//   - where a piece runs at distance d from the earlier one, the two overlap by width − d across;
//     the overlap area over the piece (the earlier piece's extent projected onto it) is taken off:
//     flow = 1 − area / (length × width), in [0, 1]; where several earlier pieces overlap the
//     same piece, the largest area counts;
//   - a line is split where an overlap starts or ends (the ends of the earlier piece projected onto
//     it, and where the distance crosses the width), so that each piece gets its own flow;
//   - a piece whose flow falls under `min_flow` (wall_min_flow) is not extruded (flow 0: a move).
// So a thin feature whose outer wall runs back along itself 0.2 mm away with 0.4 mm lines prints
// its second pass at half the flow. The result is ExtrusionPath::flows (the path's own flow times
// the ratio, one per point: flows[k] for the line ending at points[k], flows[0] the closing line).
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct WallOverlapParams {
    coord_um width_um = 400;  ///< closer than this counts as overlap (the line width)
    double min_flow = 0;      ///< wall_min_flow as a ratio: pieces below it are not extruded
};

/// Compensates the closed paths of `feature` in `paths` (in list order) against each other. Paths
/// that already carry per-point flows or cross air (bridge walls) are left as they are, and neither
/// count as earlier pieces.
void compensateWallOverlaps(std::vector<ExtrusionPath>& paths, Feature feature,
                            const WallOverlapParams& params);

}  // namespace mixengine
