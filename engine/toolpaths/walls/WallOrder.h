#pragma once
// Which outline a wall loop belongs to, for optimize_wall_printing_order: CuraEngine 4.13 then
// prints the walls of each hole together (its inner walls from the innermost out, then the hole's
// outer wall) and then those of the part's outline, instead of one wall level after the other.
//
// levels[0] are the outer-wall loops (outlines and holes), levels[k] the loops of wall k+1. Every
// loop of levels[k] (k ≥ 1) belongs to the loop of levels[k−1] it runs closest along: the smallest
// mean distance of up to 16 of its vertices (spread along it) to that loop's edges, among the loops
// whose bounds, grown by the distance between the levels' centre lines, hold its bounds. A loop
// with no such candidate belongs to the nearest of all. Each outer-wall loop starts a family.
#include <cstddef>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

/// families[k][i] = the index in levels[0] of the outer-wall loop that loop i of levels[k] belongs
/// to (families[0][i] = i). `level_step_um[k]` is the distance between the centre lines of levels
/// k−1 and k (entry 0 unused).
std::vector<std::vector<std::size_t>> wallFamilies(const std::vector<Paths>& levels,
                                                   const std::vector<coord_um>& level_step_um);

}  // namespace mixengine
