#pragma once
// Loops that lie side by side, apart in x. Clipper sweeps a scan line from bottom to top and, at
// every vertex height, walks every edge the line crosses; parts that lie beside one another on a
// layer (an armadillo's arms and body) all share that walk. Run apart, each part walks only its own
// edges, and the result is the same area: loops farther apart than an operation can reach do not
// interact in it.
#include <cstddef>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

/// The loops of `a` followed by those of `b` (index k < a.size() is a[k], else b[k − a.size()]) in
/// groups whose x ranges, each widened by `reach_um` on both sides, overlap one another (directly
/// or through other loops of the group). Groups come left to right, indices ascending within each.
/// Empty when all loops form one group (or there are none): then there is nothing to split.
std::vector<std::vector<std::size_t>> sideBySideGroups(const Paths& a, const Paths& b, coord_um reach_um);

}  // namespace mixengine
