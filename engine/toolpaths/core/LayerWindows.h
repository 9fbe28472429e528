#pragma once
// Intersections and unions of the areas of consecutive layers, for every layer at once.
//
// result[i] combines layers[i] … layers[i + window − 1]; it is empty where the window reaches past
// the last layer, and equals layers[i] for window 1 (window ≤ 0: all empty). A window of 2^k layers
// is combined by doubling (pairs, then pairs of pairs: k polygon operations per layer, 2 for the
// usual 4 top/bottom layers); any other with the block scheme for sliding windows: per block of
// `window` layers the running combinations from each end, then one operation per window — under
// three operations per layer whatever the window size. Layers in parallel.
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

std::vector<Paths> windowIntersections(const std::vector<Paths>& layers, int window, int threads);
std::vector<Paths> windowUnions(const std::vector<Paths>& layers, int window, int threads);

}  // namespace mixengine
