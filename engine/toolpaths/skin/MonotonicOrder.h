#pragma once
// Monotonic order of a fill's lines (Cura's skin_monotonic / roofing_monotonic), as CuraEngine
// 4.13 orders them: lines that lie side by side are printed in one direction across the area, so
// that every line is laid against the one printed before it.
//
// The direction is the normal of the lines, (−cos a, sin a) for lines at angle a (the lines run
// along (sin a, cos a), toolpaths/infill/LineInfill.h). Each line is projected on it; a line's position is
// the smaller projection of its two ends. Two lines are adjacent when their projections come within
// `max_adjacent_um` of each other (CuraEngine: 1.1 line widths) and their extents across the
// direction overlap. A line adjacent to exactly one later line leads on to it; every other later
// neighbour starts a run of its own. Runs are printed in the order of their first line's position
// (ties by the larger projection); a run follows its links until it reaches a line that starts a run.
// Lines are open two-point paths; which end a line is printed from is left to the planner.
#include "geometry/Point.h"

namespace mixengine {

/// `lines` in monotonic order for lines at `angle_degrees`.
Paths monotonicOrder(Paths lines, double angle_degrees, coord_um max_adjacent_um);

}  // namespace mixengine
