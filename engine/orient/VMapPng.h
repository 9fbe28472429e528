#pragma once
// A small heat-map renderer for the V map (like seed 000's figure 6, seen from above): longitude
// along x, latitude along y (0 at the bottom), a colour bar with the V range in mm³, and the
// chosen (latitude, longitude) marked by a white ring. Returns the PNG file's bytes (libpng).
#include <string>

#include "orient/Orienter.h"

namespace mixengine::orient {

std::string renderVMapPng(const VMap& map, const LatLon& chosen);

}  // namespace mixengine::orient
