#pragma once
// Top and bottom skin: the part of a layer's infill area that is not covered by the layers above
// (top_layers of them) or below (bottom_layers) is printed solid.
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

/// `areas[i]` is layer i's area inside the walls. Returns, per layer, the skin area (a subset of
/// areas[i]). Layers within `bottom_layers` of the bottom and `top_layers` of the top are all skin.
std::vector<Paths> computeSkinAreas(const std::vector<Paths>& areas, int top_layers, int bottom_layers,
                                    int threads);

Paths intersectAll(const Paths& a, const Paths& b);
Paths differenceOf(const Paths& a, const Paths& b);

}  // namespace mixengine
